// The source point cloud of a weight transfer (skin/Transfer.h): the chunks'
// vertices, normals and weights (joints merged by identity), their triangles
// with the fans around each vertex and per-triangle geometry, and the
// nearest-point search over the vertices.
#include "skin/TransferQuery.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <map>

namespace rs::skin {

namespace detail {

namespace {

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

} // namespace

Result<std::shared_ptr<const Data>> buildSource(const std::vector<const SkinChunk*>& chunks, bool usePreDeformed)
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
    // The fans and triangle geometry beside the nearest-point grids (both cores).
    const auto fans = [&d] {
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
    };
    const auto geometry = [&d] {
        d->faceNormals.resize(d->triangles.size() / 3);
        d->geometry.resize(d->faceNormals.size());
        for (std::size_t t = 0; t < d->faceNormals.size(); ++t) {
            const glm::vec3& a = d->positions[d->triangles[3 * t]];
            const glm::vec3 ab = d->positions[d->triangles[3 * t + 1]] - a, ac = d->positions[d->triangles[3 * t + 2]] - a;
            const glm::vec3 normal = glm::cross(ab, ac);
            const float length = glm::length(normal);
            d->faceNormals[t] = length > 0.0f ? normal / length : glm::vec3(0.0f);
            d->geometry[t] = {a, ab, ac};
        }
    };
    tbb::parallel_invoke([&] { d->nearest = std::make_unique<NearestPoints>(d->positions); }, [&] {
        fans();
        geometry();
    });
    return Out(std::shared_ptr<const Data>(std::move(d)));
}

} // namespace detail

Result<TransferSource> TransferSource::fromChunk(const SkinChunk& chunk, bool usePreDeformed)
{
    auto data = detail::buildSource({&chunk}, usePreDeformed);
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
    auto data = detail::buildSource(all, usePreDeformed);
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

} // namespace rs::skin
