// The brush and smoothing over the welded surface: a dab reaches along the
// surface (or through a ball) with a falloff; smoothing averages each vertex's
// neighbours. Prune, normalise, limit and mirror: WeightOperations.cpp.
#include "skin/WeightTools.h"
#include "skin/WeightToolsSupport.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace rs::skin {

using model::Influence;
using namespace detail;

namespace {

double shareOf(const std::vector<Influence>& in, std::uint32_t joint)
{
    for (const Influence& i : in)
        if (i.joint == joint)
            return i.weight;
    return 0.0;
}

struct Neighbours {
    std::vector<std::uint32_t> offsets, list;
    std::vector<double> length;
    explicit Neighbours(const Surface& s)
    {
        offsets.assign(s.positions.size() + 1, 0);
        for (const auto& e : s.edges) {
            ++offsets[e.a + 1];
            ++offsets[e.b + 1];
        }
        for (std::size_t i = 1; i < offsets.size(); ++i)
            offsets[i] += offsets[i - 1];
        list.resize(offsets.back());
        length.resize(offsets.back());
        std::vector<std::uint32_t> at(offsets.begin(), offsets.end() - 1);
        for (const auto& e : s.edges) {
            const double d = glm::length(s.positions[e.a] - s.positions[e.b]);
            list[at[e.a]] = e.b;
            length[at[e.a]++] = d;
            list[at[e.b]] = e.a;
            length[at[e.b]++] = d;
        }
    }
};

// Surface vertices of `vertices` (file), each once; all when empty.
std::vector<std::uint32_t> surfaceVertices(const Surface& s, const std::vector<std::uint32_t>& vertices)
{
    std::vector<std::uint32_t> out;
    if (vertices.empty()) {
        out.resize(s.positions.size());
        for (std::uint32_t i = 0; i < out.size(); ++i)
            out[i] = i;
        return out;
    }
    std::vector<bool> seen(s.positions.size(), false);
    for (std::uint32_t v : vertices)
        if (v < s.welded.size() && !seen[s.welded[v]]) {
            seen[s.welded[v]] = true;
            out.push_back(s.welded[v]);
        }
    return out;
}

double falloff(Falloff f, double t) // t: distance / radius in [0, 1]
{
    switch (f) {
    case Falloff::Constant: return 1.0;
    case Falloff::Linear: return 1.0 - t;
    case Falloff::Smooth: break;
    }
    const double u = 1.0 - t;
    return u * u * (3.0 - 2.0 * u);
}

} // namespace

std::vector<Influence> setShare(std::vector<Influence> in, std::uint32_t joint, double target, const WeightContext& c)
{
    if (c.isLocked(joint))
        return tidy(std::move(in));
    double locked = 0.0, others = 0.0;
    for (const Influence& i : in) {
        if (i.joint == joint)
            continue;
        (c.isLocked(i.joint) ? locked : others) += i.weight;
    }
    const double available = std::max(0.0, 1.0 - locked);
    target = std::clamp(target, 0.0, available);
    if (others <= 0.0 && target < available) {
        // Nothing else unlocked to take the rest: the joint's skin parent takes it, else the share stays.
        const std::int32_t parent = joint < c.weights->parents.size() ? c.weights->parents[joint] : -1;
        if (parent < 0 || c.isLocked(std::uint32_t(parent)))
            return tidy(std::move(in));
        std::erase_if(in, [&](const Influence& i) { return i.joint == joint; });
        in.push_back({joint, float(target)});
        in.push_back({std::uint32_t(parent), float(available - target)});
        return tidy(std::move(in));
    }
    const double scale = others > 0.0 ? (available - target) / others : 0.0;
    for (Influence& i : in)
        if (i.joint != joint && !c.isLocked(i.joint))
            i.weight = float(i.weight * scale);
    std::erase_if(in, [&](const Influence& i) { return i.joint == joint; });
    in.push_back({joint, float(target)});
    return tidy(std::move(in));
}

std::vector<VertexInfluences> brushDab(const WeightContext& c, const Brush& brush)
{
    const Surface& s = *c.surface;
    const Welds welds(s);
    // Every surface vertex the brush reaches, with its distance from the centre.
    std::vector<std::pair<std::uint32_t, double>> reached;
    if (brush.surface && brush.vertex < s.welded.size()) {
        const Neighbours n(s);
        std::vector<double> dist(s.positions.size(), std::numeric_limits<double>::infinity());
        using Item = std::pair<double, std::uint32_t>;
        std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
        const std::uint32_t start = s.welded[brush.vertex];
        dist[start] = glm::length(s.positions[start] - brush.centre);
        open.push({dist[start], start});
        while (!open.empty()) {
            const auto [d, v] = open.top();
            open.pop();
            if (d > dist[v] || d > brush.radius)
                continue;
            reached.emplace_back(v, d);
            for (std::uint32_t k = n.offsets[v]; k < n.offsets[v + 1]; ++k) {
                const double next = d + n.length[k];
                if (next < dist[n.list[k]] && next <= brush.radius) {
                    dist[n.list[k]] = next;
                    open.push({next, n.list[k]});
                }
            }
        }
    } else {
        for (std::uint32_t v = 0; v < s.positions.size(); ++v)
            if (const double d = glm::length(s.positions[v] - brush.centre); d <= brush.radius)
                reached.emplace_back(v, d);
    }
    std::vector<VertexInfluences> out;
    if (brush.mode == BrushMode::Smooth) {
        const Neighbours n(s);
        for (const auto& [v, d] : reached) {
            const double amount = std::clamp(brush.strength * falloff(brush.falloff, d / brush.radius), 0.0, 1.0);
            std::vector<Influence> average;
            for (std::uint32_t k = n.offsets[v]; k < n.offsets[v + 1]; ++k)
                for (const Influence& i : influencesOf(*c.weights, welds.first(n.list[k]))) {
                    auto it = std::find_if(average.begin(), average.end(), [&](const Influence& a) { return a.joint == i.joint; });
                    if (it != average.end())
                        it->weight += i.weight;
                    else
                        average.push_back(i);
                }
            if (average.empty())
                continue;
            emit(c, welds, v, blendUnlocked(influencesOf(*c.weights, welds.first(v)), tidy(average), amount, c), out);
        }
        sortByVertex(out);
        return out;
    }
    for (const auto& [v, d] : reached) {
        const double amount = std::clamp(brush.strength * falloff(brush.falloff, d / brush.radius), 0.0, 1.0);
        const std::vector<Influence> own = influencesOf(*c.weights, welds.first(v));
        const double share = shareOf(own, brush.joint);
        double target = share;
        switch (brush.mode) {
        case BrushMode::Add: target = share + amount * (1.0 - share); break;
        case BrushMode::Subtract: target = share * (1.0 - amount); break;
        case BrushMode::Replace: target = share + (brush.strength - share) * falloff(brush.falloff, d / brush.radius); break;
        case BrushMode::Smooth: break;
        }
        emit(c, welds, v, setShare(own, brush.joint, target, c), out);
    }
    sortByVertex(out);
    return out;
}

std::vector<VertexInfluences> smoothWeights(const WeightContext& c, const std::vector<std::uint32_t>& vertices, double strength,
                                            int iterations)
{
    const Surface& s = *c.surface;
    const Welds welds(s);
    const Neighbours n(s);
    // Per surface vertex, the current weights (iterations work on the smoothed ones).
    std::vector<std::vector<Influence>> current(s.positions.size());
    for (std::uint32_t v = 0; v < s.positions.size(); ++v)
        current[v] = influencesOf(*c.weights, welds.first(v));
    const std::vector<std::uint32_t> targets = surfaceVertices(s, vertices);
    for (int it = 0; it < std::max(1, iterations); ++it) {
        std::vector<std::vector<Influence>> next = current;
        for (std::uint32_t v : targets) {
            std::vector<Influence> average;
            for (std::uint32_t k = n.offsets[v]; k < n.offsets[v + 1]; ++k)
                for (const Influence& i : current[n.list[k]]) {
                    auto found = std::find_if(average.begin(), average.end(), [&](const Influence& a) { return a.joint == i.joint; });
                    if (found != average.end())
                        found->weight += i.weight;
                    else
                        average.push_back(i);
                }
            if (!average.empty())
                next[v] = blendUnlocked(current[v], tidy(average), std::clamp(strength, 0.0, 1.0), c);
        }
        current = std::move(next);
    }
    std::vector<VertexInfluences> out;
    for (std::uint32_t v : targets)
        emit(c, welds, v, current[v], out);
    sortByVertex(out);
    return out;
}

} // namespace rs::skin
