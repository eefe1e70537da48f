// The fallback methods of skin/Transfer.h: the source point cloud (vertices,
// triangle fans, normals, weights, skin/NearestPoints) and, per target
// vertex, closest point on triangles or closest neighbours, with the normal
// filter; then the optional smoothing steps. Target vertices are done in
// slices (progress and cancel between them), each slice in parallel (oneTBB).
#include "skin/Transfer.h"

#include "skin/NearestPoints.h"
#include "skin/TransferInpaint.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>

namespace rs::skin {

namespace {

constexpr int kFanVertices = 2;   // closest point: the triangle fans of this many nearest vertices
constexpr int kFilterCandidates = 16; // the normal filter looks among this many nearest vertices
constexpr int kMaxCandidates = NearestPoints::kMaxK;
constexpr int kMixCapacity = 64;  // distinct joints one target vertex can blend
constexpr float kCoincident = 1e-5f; // metres: a target vertex this near a source vertex is at it

} // namespace

struct TransferSource::Data {
    std::vector<glm::vec3> positions, normals;
    std::vector<std::uint32_t> triangles;             // flat, three corners each
    std::vector<glm::vec3> faceNormals;               // unit (zero for a degenerate triangle)
    struct Corner {
        glm::vec3 a, ab, ac;                          // a triangle's first corner and its two edges from it
    };
    std::vector<Corner> geometry;                     // per triangle
    std::vector<std::uint32_t> fanOffsets, fans;      // vertex -> the triangles around it
    model::MeshWeights weights;                       // per vertex; joints: the union of the chunks'
    int maxInfluences = 0;                            // the most one vertex has
    std::unique_ptr<NearestPoints> nearest;
};

namespace {

using Data = TransferSource::Data;

// Appends one chunk to `d`: its points, triangles and weights, its joints
// mapped onto the union by identity.
void append(Data& d, const SkinChunk& c, bool usePreDeformed, std::map<NodeKey, std::uint32_t>& jointOf)
{
    const auto base = std::uint32_t(d.positions.size());
    const std::vector<glm::vec3>& points = usePreDeformed ? c.restPositions() : c.positions;
    const std::vector<glm::vec3>& normals = usePreDeformed ? c.restNormals() : c.normals;
    d.positions.insert(d.positions.end(), points.begin(), points.end());
    d.normals.insert(d.normals.end(), normals.begin(), normals.end());
    for (std::uint32_t corner : c.triangles)
        d.triangles.push_back(base + corner);
    std::vector<std::uint32_t> joint(c.weights.joints.size());
    for (std::size_t j = 0; j < c.weights.joints.size(); ++j) {
        auto [it, added] = jointOf.try_emplace(c.weights.joints[j], std::uint32_t(d.weights.joints.size()));
        if (added) {
            d.weights.joints.push_back(c.weights.joints[j]);
            d.weights.parents.push_back(-1);
        }
        joint[j] = it->second;
    }
    for (std::size_t j = 0; j < c.weights.joints.size(); ++j) { // parents once every joint has its index
        const std::int32_t parent = j < c.weights.parents.size() ? c.weights.parents[j] : -1;
        if (parent >= 0 && std::size_t(parent) < joint.size() && d.weights.parents[joint[j]] < 0 && joint[std::size_t(parent)] != joint[j])
            d.weights.parents[joint[j]] = std::int32_t(joint[std::size_t(parent)]);
    }
    for (std::size_t v = 0; v < c.vertexCount(); ++v) {
        for (const model::Influence* i = c.weights.begin(v); i != c.weights.end(v); ++i)
            d.weights.influences.push_back({joint[i->joint], i->weight});
        d.maxInfluences = std::max(d.maxInfluences, int(c.weights.end(v) - c.weights.begin(v)));
        d.weights.offsets.push_back(std::uint32_t(d.weights.influences.size()));
    }
}

Result<std::shared_ptr<const Data>> build(const std::vector<const SkinChunk*>& chunks, bool usePreDeformed)
{
    using Out = Result<std::shared_ptr<const Data>>;
    auto d = std::make_shared<Data>();
    d->weights.offsets.push_back(0);
    std::map<NodeKey, std::uint32_t> jointOf;
    for (const SkinChunk* c : chunks) {
        const std::size_t n = c->vertexCount();
        const bool sized = c->positions.size() == n && c->normals.size() == n && c->weights.vertexCount() == n &&
                           (c->inBindPose || (c->bindPositions.size() == n && c->bindNormals.size() == n));
        bool inRange = true;
        for (std::uint32_t corner : c->triangles)
            inRange = inRange && corner < n;
        for (const model::Influence& i : c->weights.influences)
            inRange = inRange && i.joint < c->weights.joints.size();
        if (!sized || !inRange)
            return Out::failure(makeError({}, "chunk '" + c->mesh + "': its arrays do not match its vertex count"));
        append(*d, *c, usePreDeformed, jointOf);
    }
    if (d->positions.empty())
        return Out::failure(makeError({}, "no source vertex to transfer weights from"));
    const std::size_t n = d->positions.size();
    d->fanOffsets.assign(n + 1, 0);
    for (std::uint32_t corner : d->triangles)
        ++d->fanOffsets[corner + 1];
    for (std::size_t v = 0; v < n; ++v)
        d->fanOffsets[v + 1] += d->fanOffsets[v];
    d->fans.resize(d->triangles.size());
    std::vector<std::uint32_t> fill(d->fanOffsets.begin(), d->fanOffsets.end() - 1);
    for (std::size_t k = 0; k < d->triangles.size(); ++k)
        d->fans[fill[d->triangles[k]]++] = std::uint32_t(k / 3);
    d->faceNormals.resize(d->triangles.size() / 3);
    for (std::size_t t = 0; t < d->faceNormals.size(); ++t) {
        const glm::vec3& a = d->positions[d->triangles[3 * t]];
        const glm::vec3 normal = glm::cross(d->positions[d->triangles[3 * t + 1]] - a, d->positions[d->triangles[3 * t + 2]] - a);
        const float length = glm::length(normal);
        d->faceNormals[t] = length > 0.0f ? normal / length : glm::vec3(0.0f);
        d->geometry.push_back({a, d->positions[d->triangles[3 * t + 1]] - a, d->positions[d->triangles[3 * t + 2]] - a});
    }
    d->nearest = std::make_unique<NearestPoints>(d->positions);
    return Out(std::shared_ptr<const Data>(std::move(d)));
}

// Barycentric coordinates (of a, b, c) of the point of triangle abc closest to
// p (Ericson, Real-Time Collision Detection, 5.1.5), from a and the edges
// ab, ac. A degenerate triangle gives its nearest corner.
glm::vec3 closestOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& ab, const glm::vec3& ac)
{
    const glm::vec3 ap = p - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0f && d2 <= 0.0f)
        return {1, 0, 0};
    const glm::vec3 bp = ap - ab;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0f && d4 <= d3)
        return {0, 1, 0};
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f && d1 - d3 > 0.0f) {
        const float t = d1 / (d1 - d3);
        return {1 - t, t, 0};
    }
    const glm::vec3 cp = ap - ac;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0f && d5 <= d6)
        return {0, 0, 1};
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f && d2 - d6 > 0.0f) {
        const float t = d2 / (d2 - d6);
        return {1 - t, 0, t};
    }
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && d4 - d3 >= 0.0f && d5 - d6 >= 0.0f && (d4 - d3) + (d5 - d6) > 0.0f) {
        const float t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {0, 1 - t, t};
    }
    const float sum = va + vb + vc;
    if (!(sum > 0.0f) || !std::isfinite(sum)) {
        const float da = glm::dot(ap, ap), db = glm::dot(bp, bp), dc = glm::dot(cp, cp);
        return da <= db && da <= dc ? glm::vec3(1, 0, 0) : db <= dc ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
    }
    const float v = vb / sum, w = vc / sum;
    return {1 - v - w, v, w};
}

// One target vertex's blend of source weights, by joint.
struct Mix {
    std::array<std::uint32_t, kMixCapacity> joint;
    std::array<float, kMixCapacity> weight;
    int size = 0;
    void add(std::uint32_t j, float w)
    {
        for (int k = 0; k < size; ++k)
            if (joint[k] == j) {
                weight[k] += w;
                return;
            }
        if (size < kMixCapacity) {
            joint[size] = j;
            weight[size++] = w;
        }
    }
    void addVertex(const model::MeshWeights& weights, std::uint32_t v, float share)
    {
        if (share > 0.0f)
            for (const model::Influence* i = weights.begin(v); i != weights.end(v); ++i)
                add(i->joint, i->weight * share);
    }
};

// Target weights: `capacity` slots per vertex (the largest first), normalised.
struct Slots {
    int capacity = 4;
    std::vector<model::Influence> slot; // capacity per vertex; the first count[v] used
    std::vector<std::uint8_t> count;
    // The `capacity` largest of `mix`, normalised; `fallbackJoint` when nothing weighs.
    void store(std::size_t v, Mix& mix, std::uint32_t fallbackJoint)
    {
        // Insertion sort, largest first (ties: the lower joint): a handful of entries.
        std::array<int, kMixCapacity> order;
        for (int k = 0; k < mix.size; ++k) {
            int at = k;
            for (; at > 0; --at) {
                const int o = order[at - 1];
                if (mix.weight[o] > mix.weight[k] || (mix.weight[o] == mix.weight[k] && mix.joint[o] < mix.joint[k]))
                    break;
                order[at] = o;
            }
            order[at] = k;
        }
        const int keep = std::min(capacity, mix.size);
        float sum = 0.0f;
        int kept = 0;
        for (int k = 0; k < keep && mix.weight[order[k]] > 0.0f; ++k, ++kept)
            sum += mix.weight[order[k]];
        const std::size_t at = v * std::size_t(capacity);
        if (!(sum > 0.0f) || !std::isfinite(sum)) {
            slot[at] = {fallbackJoint, 1.0f};
            count[v] = 1;
            return;
        }
        for (int k = 0; k < kept; ++k) {
            slot[at + k] = {mix.joint[order[k]], mix.weight[order[k]] / sum};
        }
        count[v] = std::uint8_t(kept);
    }
};

enum Route : std::uint8_t { kClosestPoint, kNeighbours, kFilterFallback };

// Where a closest point was found: its squared distance and the source's normal
// there (its vertex normals blended as its weights are).
struct Hit {
    float distance2 = 0.0f;
    glm::vec3 normal{0.0f};
};

struct Query {
    const Data& d;
    const TransferOptions& o;

    // Up to `k` nearest source vertices, nearest first; returns how many.
    int nearest(const glm::vec3& p, int k, std::uint32_t* index, float* distance2) const
    {
        return d.nearest->nearest(p, k, index, distance2);
    }
    bool passes(const glm::vec3& a, const glm::vec3& b) const { return glm::dot(a, b) >= float(o.normalTolerance); }

    // The closest point on the fans of `vertices` (of those with passing face
    // normals when `normal` is set), blended into `mix`; false when no
    // triangle or vertex is left. Once the best point is in the open star of
    // the nearest vertex (its weight there above 0), the next fans are not
    // searched: on a smooth surface they only hold farther points. When it is
    // on the first fan's rim and `rim` is set, nothing is blended and *rim is
    // set: the caller searches again with more vertices.
    bool closestPoint(const glm::vec3& p, const std::uint32_t* vertices, const float* distance2, int count, const glm::vec3* normal,
                      Mix& mix, bool* rim = nullptr, Hit* hit = nullptr) const
    {
        float best = std::numeric_limits<float>::infinity();
        std::uint32_t bestTriangle = ~0u, bestVertex = ~0u;
        glm::vec3 bestBary(0.0f);
        std::array<std::uint32_t, 32> tested; // fans overlap: each triangle once
        int testedCount = 0;
        for (int i = 0; i < count; ++i) {
            const std::uint32_t v = vertices[i];
            bool any = false;
            for (std::uint32_t f = d.fanOffsets[v]; f < d.fanOffsets[v + 1]; ++f) {
                const std::uint32_t t = d.fans[f];
                if (normal && !passes(d.faceNormals[t], *normal))
                    continue;
                any = true;
                if (std::find(tested.begin(), tested.begin() + testedCount, t) != tested.begin() + testedCount)
                    continue;
                if (testedCount < int(tested.size()))
                    tested[testedCount++] = t;
                const Data::Corner& g = d.geometry[t];
                const glm::vec3 bary = closestOnTriangle(p, g.a, g.ab, g.ac);
                const glm::vec3 offset = g.a + bary.y * g.ab + bary.z * g.ac - p;
                const float d2 = glm::dot(offset, offset);
                if (d2 < best) {
                    best = d2;
                    bestTriangle = t;
                    bestBary = bary;
                }
            }
            if (!any && distance2[i] < best) { // no (usable) triangle: the vertex itself
                best = distance2[i];
                bestTriangle = ~0u;
                bestVertex = v;
            }
            if (i == 0 && bestTriangle != ~0u) {
                const std::uint32_t* c = &d.triangles[3 * bestTriangle];
                const float centre = c[0] == v ? bestBary.x : c[1] == v ? bestBary.y : bestBary.z;
                if (centre > 0.0f)
                    break;
                if (rim && count == 1) {
                    *rim = true;
                    return true;
                }
            }
        }
        if (bestTriangle != ~0u) {
            const std::uint32_t* c = &d.triangles[3 * bestTriangle];
            for (int k = 0; k < 3; ++k)
                mix.addVertex(d.weights, c[k], bestBary[k]);
            if (hit) { // the source's vertex normals interpolated at the point
                const glm::vec3 n = bestBary.x * d.normals[c[0]] + bestBary.y * d.normals[c[1]] + bestBary.z * d.normals[c[2]];
                const float length = glm::length(n);
                *hit = {best, length > 0.0f ? n / length : d.faceNormals[bestTriangle]};
            }
            return true;
        }
        if (bestVertex == ~0u)
            return false;
        mix.addVertex(d.weights, bestVertex, 1.0f);
        if (hit)
            *hit = {best, d.normals[bestVertex]};
        return true;
    }

    // Skinner's closest neighbours among `vertices` (nearest first).
    void neighbours(const std::uint32_t* vertices, const float* distance2, int count, Mix& mix) const
    {
        const float nearest = std::sqrt(distance2[0]);
        if (nearest <= kCoincident) {
            mix.addVertex(d.weights, vertices[0], 1.0f);
            return;
        }
        const float radius = nearest * float(o.neighbourDistanceMultiplier);
        for (int i = 0; i < count && i < o.neighbourCount; ++i) {
            const float distance = std::sqrt(distance2[i]);
            if (distance > radius)
                break;
            mix.addVertex(d.weights, vertices[i], 1.0f / distance);
        }
    }

    // One target vertex: its route; `nearestDistance` to the nearest source vertex.
    Route transfer(const glm::vec3& p, const glm::vec3& normal, Mix& mix, float& nearestDistance, Hit* hit) const
    {
        std::array<std::uint32_t, kMaxCandidates> index;
        std::array<float, kMaxCandidates> distance2;
        const bool neighbours = o.method == TransferMethod::ClosestNeighbours;
        // Closest point asks for the nearest vertex first, and for more only
        // when the closest point lies on the rim of its fan.
        const int wanted = neighbours ? o.neighbourCount : o.normalFilter ? kFanVertices : 1;
        int found = nearest(p, wanted, index.data(), distance2.data());
        nearestDistance = found > 0 ? std::sqrt(distance2[0]) : 0.0f;
        if (o.normalFilter) {
            // The normal filter: the candidates facing the target's way. When
            // the nearest all do (most vertices), they are what a wider search
            // would keep first; otherwise look among the kFilterCandidates nearest.
            bool all = true;
            for (int i = 0; i < found && all; ++i)
                all = passes(d.normals[index[i]], normal);
            if (!all)
                found = nearest(p, std::max(kFilterCandidates, wanted), index.data(), distance2.data());
            int kept = 0;
            for (int i = 0; i < found; ++i)
                if (passes(d.normals[index[i]], normal)) {
                    index[kept] = index[i];
                    distance2[kept++] = distance2[i];
                }
            if (kept > 0 && neighbours) {
                this->neighbours(index.data(), distance2.data(), std::min(kept, wanted), mix);
                return kNeighbours;
            }
            if (kept > 0 && closestPoint(p, index.data(), distance2.data(), std::min(kept, kFanVertices), &normal, mix))
                return kClosestPoint;
            // Nothing faces the target's way: closest point, unfiltered.
            found = nearest(p, kFanVertices, index.data(), distance2.data());
            closestPoint(p, index.data(), distance2.data(), found, nullptr, mix);
            return kFilterFallback;
        }
        if (neighbours) {
            this->neighbours(index.data(), distance2.data(), found, mix);
            return kNeighbours;
        }
        bool rim = false;
        closestPoint(p, index.data(), distance2.data(), found, nullptr, mix, &rim, hit);
        if (rim) {
            found = nearest(p, kFanVertices, index.data(), distance2.data());
            closestPoint(p, index.data(), distance2.data(), found, nullptr, mix, nullptr, hit);
        }
        return kClosestPoint;
    }
};

// Each vertex's neighbours along the target's edges.
void edgeNeighbours(const model::Mesh& mesh, std::vector<std::uint32_t>& offsets, std::vector<std::uint32_t>& neighbours)
{
    const std::size_t n = mesh.vertexCount();
    offsets.assign(n + 1, 0);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k)
            if (mesh.indices[t + k] < n)
                offsets[mesh.indices[t + k] + 1] += 2;
    for (std::size_t v = 0; v < n; ++v)
        offsets[v + 1] += offsets[v];
    neighbours.assign(offsets.back(), 0);
    std::vector<std::uint32_t> fill(offsets.begin(), offsets.end() - 1);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t c[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
        for (int k = 0; k < 3; ++k)
            if (c[k] < n) {
                neighbours[fill[c[k]]++] = c[(k + 1) % 3] < n ? c[(k + 1) % 3] : c[k];
                neighbours[fill[c[k]]++] = c[(k + 2) % 3] < n ? c[(k + 2) % 3] : c[k];
            }
    }
}

float weightOf(const Slots& s, std::size_t v, std::uint32_t joint)
{
    for (int k = 0; k < s.count[v]; ++k)
        if (s.slot[v * s.capacity + k].joint == joint)
            return s.slot[v * s.capacity + k].weight;
    return 0.0f;
}

// Whether v's weights differ from a neighbour's by more than `threshold` for some joint.
bool differs(const Slots& s, std::size_t v, std::size_t u, float threshold)
{
    for (int k = 0; k < s.count[v]; ++k)
        if (std::abs(s.slot[v * s.capacity + k].weight - weightOf(s, u, s.slot[v * s.capacity + k].joint)) > threshold)
            return true;
    for (int k = 0; k < s.count[u]; ++k)
        if (std::abs(s.slot[u * s.capacity + k].weight - weightOf(s, v, s.slot[u * s.capacity + k].joint)) > threshold)
            return true;
    return false;
}

std::size_t smooth(const model::Mesh& target, const std::vector<float>& nearest, const TransferOptions& o, Slots& slots,
                   std::uint32_t fallbackJoint)
{
    std::vector<std::uint32_t> offsets, around;
    edgeNeighbours(target, offsets, around);
    const std::size_t n = target.vertexCount();
    std::vector<std::uint8_t> changed(n, 0);
    for (int step = 0; step < o.smoothSteps; ++step) {
        Slots next = slots;
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096), [&](const tbb::blocked_range<std::size_t>& range) {
            Mix mix;
            for (std::size_t v = range.begin(); v != range.end(); ++v) {
                if (nearest[v] <= kCoincident || offsets[v] == offsets[v + 1])
                    continue;
                bool rough = false;
                for (std::uint32_t e = offsets[v]; e < offsets[v + 1] && !rough; ++e)
                    rough = differs(slots, v, around[e], float(o.weightDifferenceThreshold));
                if (!rough)
                    continue;
                mix.size = 0;
                for (int k = 0; k < slots.count[v]; ++k)
                    mix.add(slots.slot[v * slots.capacity + k].joint, slots.slot[v * slots.capacity + k].weight);
                for (std::uint32_t e = offsets[v]; e < offsets[v + 1]; ++e)
                    for (int k = 0; k < slots.count[around[e]]; ++k)
                        mix.add(slots.slot[around[e] * slots.capacity + k].joint, slots.slot[around[e] * slots.capacity + k].weight);
                next.store(v, mix, fallbackJoint);
                changed[v] = 1;
            }
        });
        slots = std::move(next);
    }
    return std::size_t(std::count(changed.begin(), changed.end(), std::uint8_t(1)));
}

} // namespace

Result<TransferSource> TransferSource::fromChunk(const SkinChunk& chunk, bool usePreDeformed)
{
    auto data = build({&chunk}, usePreDeformed);
    if (!data)
        return Result<TransferSource>::failure(data.takeDiagnostics());
    TransferSource out;
    out.m_data = data.take();
    return out;
}

Result<TransferSource> TransferSource::uber(const std::vector<SkinChunk>& chunks, bool usePreDeformed)
{
    std::vector<const SkinChunk*> all;
    for (const SkinChunk& c : chunks)
        all.push_back(&c);
    auto data = build(all, usePreDeformed);
    if (!data)
        return Result<TransferSource>::failure(data.takeDiagnostics());
    TransferSource out;
    out.m_data = data.take();
    return out;
}

std::size_t TransferSource::vertexCount() const { return m_data ? m_data->positions.size() : 0; }

const model::MeshWeights& TransferSource::weights() const
{
    static const model::MeshWeights none;
    return m_data ? m_data->weights : none;
}

namespace {

// The inpainting match distance: the option, or 5% of the target's bounding box diagonal (the paper's).
double inpaintDistance(const TransferOptions& options, const model::Mesh& target)
{
    if (options.inpaintDistance > 0.0)
        return options.inpaintDistance;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const glm::vec3& p : target.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return target.positions.empty() ? 0.0 : 0.05 * double(glm::length(hi - lo));
}

} // namespace

Result<model::MeshWeights> transferWeights(const TransferSource& source, const model::Mesh& target, const TransferOptions& options,
                                           MeshImportReport* report)
{
    using Out = Result<model::MeshWeights>;
    const Status valid = validateTransferOptions(options);
    if (valid.failed())
        return Out::failure(valid.diagnostics());
    if (!source.m_data)
        return Out::failure(makeError({}, "mesh '" + target.name + "': no source to transfer weights from"));
    const auto start = std::chrono::steady_clock::now();
    const Data& d = *source.m_data;
    const std::size_t n = target.vertexCount();
    Slots slots;
    slots.capacity = std::clamp(options.maxInfluences > 0 ? options.maxInfluences : d.maxInfluences, 1, 16);
    slots.slot.resize(n * std::size_t(slots.capacity));
    slots.count.assign(n, 0);
    std::uint32_t fallbackJoint = 0; // a vertex nothing weighs goes to the first root
    for (std::size_t j = 0; j < d.weights.parents.size(); ++j)
        if (d.weights.parents[j] < 0) {
            fallbackJoint = std::uint32_t(j);
            break;
        }
    // Inpainting copies by closest point (no filter: its own test is below).
    const bool inpainting = options.method == TransferMethod::Inpainting;
    TransferOptions queryOptions = options;
    if (inpainting)
        queryOptions.normalFilter = false;
    const bool needNormals = options.normalFilter || inpainting;
    const std::vector<glm::vec3> normals = needNormals && target.normals.size() != n ? vertexNormals(target) : std::vector<glm::vec3>();
    const std::vector<glm::vec3>& targetNormals = target.normals.size() == n ? target.normals : normals;
    std::vector<float> nearest(n, 0.0f);
    std::vector<std::uint8_t> route(n, kClosestPoint), matched(inpainting ? n : 0, 0);
    const Query query{d, queryOptions};
    const float matchDistance2 = inpainting ? float(std::pow(inpaintDistance(options, target), 2.0)) : 0.0f;
    const float matchCosine = float(std::cos(options.inpaintAngleDegrees * 3.14159265358979 / 180.0));
    // Inpainting: the closest points are about a fifth of the work (BM_TransferInpainting), the solve the rest.
    const double queryShare = inpainting ? 0.2 : 1.0;
    const std::size_t slice = std::max<std::size_t>(16384, n / 50);
    for (std::size_t first = 0; first < n; first += slice) {
        const std::size_t last = std::min(n, first + slice);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last, 1024), [&](const tbb::blocked_range<std::size_t>& range) {
            Mix mix;
            for (std::size_t v = range.begin(); v != range.end(); ++v) {
                mix.size = 0;
                const glm::vec3 normal = needNormals ? glm::normalize(targetNormals[v]) : glm::vec3(0.0f);
                Hit hit;
                route[v] = query.transfer(target.positions[v], normal, mix, nearest[v], &hit);
                slots.store(v, mix, fallbackJoint);
                if (inpainting) // near, and facing the target's way
                    matched[v] = hit.distance2 <= matchDistance2 && glm::dot(hit.normal, normal) >= matchCosine;
            }
        });
        if (options.progress && !options.progress(queryShare * double(last) / double(n)))
            return Out::failure(makeError({}, "mesh '" + target.name + "': the transfer was cancelled"));
    }
    Diagnostics notes;
    std::size_t inpainted = 0;
    std::vector<std::uint32_t> inpaintedIds;
    if (inpainting) {
        bool cancelled = false;
        std::function<bool(double)> progress;
        if (options.progress)
            progress = [&](double f) { return !(cancelled = !options.progress(queryShare + (1.0 - queryShare) * f)); };
        auto solved = inpaintWeights(target, matched, slots.capacity, slots.slot, slots.count, progress, report ? &inpaintedIds : nullptr);
        if (cancelled)
            return Out::failure(solved.takeDiagnostics());
        if (solved)
            inpainted = *solved;
        else {
            inpaintedIds.clear();
            for (Diagnostic diagnostic : solved.diagnostics()) {
                diagnostic.severity = Severity::Warning;
                diagnostic.message += "; its vertices keep the closest point's weights";
                notes.push_back(std::move(diagnostic));
            }
        }
    }
    std::size_t smoothed = 0;
    if (options.smoothSteps > 0 && n > d.positions.size())
        smoothed = smooth(target, nearest, options, slots, fallbackJoint);

    // The slots become the influences, compacted in place (each vertex's move left).
    model::MeshWeights out;
    out.joints = d.weights.joints;
    out.parents = d.weights.parents;
    out.offsets.resize(n + 1);
    out.offsets[0] = 0;
    std::size_t used = 0;
    for (std::size_t v = 0; v < n; ++v) {
        for (int k = 0; k < slots.count[v]; ++k)
            slots.slot[used++] = slots.slot[v * std::size_t(slots.capacity) + std::size_t(k)];
        out.offsets[v + 1] = std::uint32_t(used);
    }
    slots.slot.resize(used);
    out.influences = std::move(slots.slot);
    if (report) {
        report->vertices = n;
        report->closestPoint += std::size_t(std::count(route.begin(), route.end(), kClosestPoint)) +
                                std::size_t(std::count(route.begin(), route.end(), kFilterFallback));
        report->closestNeighbours += std::size_t(std::count(route.begin(), route.end(), kNeighbours));
        report->normalFilterFallbacks += std::size_t(std::count(route.begin(), route.end(), kFilterFallback));
        report->smoothed += smoothed;
        report->inpainted += inpainted;
        report->inpaintedVertices.insert(report->inpaintedVertices.end(), inpaintedIds.begin(), inpaintedIds.end());
        report->closestPoint -= std::min(report->closestPoint, inpainted);
        report->milliseconds += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    }
    return Out(std::move(out), std::move(notes));
}

} // namespace rs::skin
