#pragma once
// Internal to the weight tools (WeightTools.cpp: brush dabs and smoothing over
// the surface; WeightOperations.cpp: prune, normalise, limit, mirror): the
// pieces both use. Influences are tidied (shares below 1e-5 dropped, sum 1,
// largest first), blended keeping locked joints' shares, and written back to
// every file vertex welded into a surface vertex. Not for use outside skin/.
#include "skin/WeightTools.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace rs::skin::detail {

using model::Influence;

// Drops shares below 1e-5, rescales the rest to sum 1, sorts largest first
// (ties by joint).
std::vector<Influence> tidy(std::vector<Influence> in);

inline std::vector<Influence> influencesOf(const model::MeshWeights& w, std::uint32_t vertex)
{
    return {w.begin(vertex), w.end(vertex)};
}

// Surface vertex -> the file vertices welded into it.
struct Welds {
    std::vector<std::uint32_t> offsets, files;
    explicit Welds(const Surface& s)
    {
        offsets.assign(s.positions.size() + 1, 0);
        for (std::uint32_t w : s.welded)
            ++offsets[w + 1];
        for (std::size_t i = 1; i < offsets.size(); ++i)
            offsets[i] += offsets[i - 1];
        files.resize(s.welded.size());
        std::vector<std::uint32_t> at(offsets.begin(), offsets.end() - 1);
        for (std::uint32_t v = 0; v < s.welded.size(); ++v)
            files[at[s.welded[v]]++] = v;
    }
    std::uint32_t first(std::uint32_t s) const { return files[offsets[s]]; }
};

// Writes `influences` to every file vertex welded into surface vertex `s`
// whose weights differ.
void emit(const WeightContext& c, const Welds& welds, std::uint32_t s, const std::vector<Influence>& influences,
          std::vector<VertexInfluences>& out);

inline void sortByVertex(std::vector<VertexInfluences>& out)
{
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.vertex < b.vertex; });
}

// Blends `own` towards `goal` by `amount`, keeping locked joints' shares.
std::vector<Influence> blendUnlocked(const std::vector<Influence>& own, const std::vector<Influence>& goal, double amount,
                                     const WeightContext& c);

} // namespace rs::skin::detail
