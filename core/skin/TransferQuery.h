#pragma once
// Internal to skin/Transfer (the fallback methods): the source point cloud a
// transfer reads (TransferSource::Data), one target vertex's blend of source
// weights (Mix), the target's weight slots (Slots) and the per-vertex query
// (closest point on triangles, closest neighbours, the normal filter).
// TransferSource.cpp builds the source, TransferQuery.cpp answers queries,
// TransferSmooth.cpp smooths, TransferMethods.cpp runs them over a target.
#include "skin/NearestPoints.h"
#include "skin/Transfer.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace rs::skin {

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

namespace detail {

constexpr int kFanVertices = 2;       // closest point: the triangle fans of this many nearest vertices
constexpr int kFilterCandidates = 16; // the normal filter looks among this many nearest vertices
constexpr int kMaxCandidates = NearestPoints::kMaxK;
constexpr int kMixCapacity = 64;      // distinct joints one target vertex can blend
constexpr float kCoincident = 1e-5f;  // metres: a target vertex this near a source vertex is at it

using Data = TransferSource::Data;

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

// Answers one target vertex at a time; read-only, so any number of threads share one.
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
    // set: the caller searches again with more vertices. `hit` (optional)
    // hears where the point is.
    bool closestPoint(const glm::vec3& p, const std::uint32_t* vertices, const float* distance2, int count, const glm::vec3* normal,
                      Mix& mix, bool* rim = nullptr, Hit* hit = nullptr) const;
    // Skinner's closest neighbours among `vertices` (nearest first).
    void neighbours(const std::uint32_t* vertices, const float* distance2, int count, Mix& mix) const;
    // One target vertex (`normal` unit when the normal filter is on): its
    // route; `nearestDistance` to the nearest source vertex; `hit` (optional)
    // where its closest point is (closest point, no filter).
    Route transfer(const glm::vec3& p, const glm::vec3& normal, Mix& mix, float& nearestDistance, Hit* hit) const;
};

// Builds a transfer source from chunks (TransferSource.cpp).
Result<std::shared_ptr<const Data>> buildSource(const std::vector<const SkinChunk*>& chunks, bool usePreDeformed);

// The smoothing steps (TransferSmooth.cpp): a target vertex (not at a source
// vertex, `nearest` its distance to the nearest) whose weights differ from an
// edge neighbour's by more than the threshold takes the blend of its and its
// neighbours'. Returns how many vertices a step changed.
std::size_t smooth(const model::Mesh& target, const std::vector<float>& nearest, const TransferOptions& o, Slots& slots,
                   std::uint32_t fallbackJoint);

} // namespace detail

} // namespace rs::skin
