// The smoothing steps of a weight transfer (skin/TransferQuery.h), after
// Skinner's: a vertex whose weights differ from an edge neighbour's by more
// than the threshold for some joint takes the blend of its own and its
// neighbours' weights; each step reads the last one's weights (in parallel).
#include "skin/TransferQuery.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace rs::skin::detail {

namespace {

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

} // namespace

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

} // namespace rs::skin::detail
