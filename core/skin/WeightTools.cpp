#include "skin/WeightTools.h"

#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>
#include <queue>

namespace rs::skin {

using model::Influence;

namespace {

constexpr float kDrop = 1e-5f; // a share below this is no influence

std::vector<Influence> tidy(std::vector<Influence> in)
{
    std::erase_if(in, [](const Influence& i) { return !(i.weight > kDrop); });
    double sum = 0.0;
    for (const Influence& i : in)
        sum += i.weight;
    if (sum > 0.0)
        for (Influence& i : in)
            i.weight = float(i.weight / sum);
    std::sort(in.begin(), in.end(), [](const Influence& a, const Influence& b) {
        return a.weight != b.weight ? a.weight > b.weight : a.joint < b.joint;
    });
    return in;
}

double shareOf(const std::vector<Influence>& in, std::uint32_t joint)
{
    for (const Influence& i : in)
        if (i.joint == joint)
            return i.weight;
    return 0.0;
}

std::vector<Influence> influencesOf(const model::MeshWeights& w, std::uint32_t vertex)
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

// Writes `influences` to every file vertex welded into surface vertex `s`
// whose weights differ.
void emit(const WeightContext& c, const Welds& welds, std::uint32_t s, const std::vector<Influence>& influences,
          std::vector<VertexInfluences>& out)
{
    for (std::uint32_t k = welds.offsets[s]; k < welds.offsets[s + 1]; ++k) {
        const std::uint32_t v = welds.files[k];
        if (influencesOf(*c.weights, v) != influences)
            out.push_back({v, influences});
    }
}

void sortByVertex(std::vector<VertexInfluences>& out)
{
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.vertex < b.vertex; });
}

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

// Blends `own` towards `goal` by `amount`, keeping locked joints' shares.
std::vector<Influence> blendUnlocked(const std::vector<Influence>& own, const std::vector<Influence>& goal, double amount,
                                     const WeightContext& c)
{
    std::vector<Influence> out;
    double locked = 0.0, unlockedGoal = 0.0;
    for (const Influence& i : own)
        if (c.isLocked(i.joint)) {
            locked += i.weight;
            out.push_back(i);
        }
    for (const Influence& i : goal)
        if (!c.isLocked(i.joint))
            unlockedGoal += i.weight;
    const double available = std::max(0.0, 1.0 - locked);
    std::vector<Influence> mixed;
    auto add = [&](std::uint32_t joint, double w) {
        for (Influence& m : mixed)
            if (m.joint == joint) {
                m.weight += float(w);
                return;
            }
        mixed.push_back({joint, float(w)});
    };
    double unlockedOwn = 0.0;
    for (const Influence& i : own)
        if (!c.isLocked(i.joint))
            unlockedOwn += i.weight;
    for (const Influence& i : own)
        if (!c.isLocked(i.joint))
            add(i.joint, (1.0 - amount) * i.weight);
    if (unlockedGoal > 0.0)
        for (const Influence& i : goal)
            if (!c.isLocked(i.joint))
                add(i.joint, amount * i.weight * (unlockedOwn > 0.0 ? unlockedOwn / unlockedGoal : 1.0 / unlockedGoal));
    double sum = 0.0;
    for (const Influence& m : mixed)
        sum += m.weight;
    if (sum > 0.0)
        for (const Influence& m : mixed)
            out.push_back({m.joint, float(m.weight / sum * available)});
    return tidy(out);
}

struct Cloud {
    const std::vector<Vec3>* points;
    std::size_t kdtree_get_point_count() const { return points->size(); }
    double kdtree_get_pt(std::size_t i, std::size_t d) const { return (*points)[i][int(d)]; }
    template <class B>
    bool kdtree_get_bbox(B&) const { return false; }
};
using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud, 3>;

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

namespace {

template <class F>
std::vector<VertexInfluences> perVertex(const WeightContext& c, const std::vector<std::uint32_t>& vertices, F&& change)
{
    std::vector<VertexInfluences> out;
    auto visit = [&](std::uint32_t v) {
        std::vector<Influence> own = influencesOf(*c.weights, v);
        std::vector<Influence> next = change(own);
        if (next != own)
            out.push_back({v, std::move(next)});
    };
    if (vertices.empty())
        for (std::uint32_t v = 0; v < c.weights->vertexCount(); ++v)
            visit(v);
    else
        for (std::uint32_t v : vertices)
            if (v < c.weights->vertexCount())
                visit(v);
    sortByVertex(out);
    out.erase(std::unique(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.vertex == b.vertex; }), out.end());
    return out;
}

// Drops unlocked influences `drop` chooses (never all of them), handing their
// share to the remaining unlocked ones.
template <class Drop>
std::vector<Influence> dropUnlocked(std::vector<Influence> in, const WeightContext& c, Drop&& drop)
{
    double removed = 0.0, kept = 0.0;
    std::vector<Influence> out;
    for (const Influence& i : in) {
        if (!c.isLocked(i.joint) && drop(i)) {
            removed += i.weight;
            continue;
        }
        out.push_back(i);
        if (!c.isLocked(i.joint))
            kept += i.weight;
    }
    if (removed <= 0.0 || kept <= 0.0)
        return tidy(std::move(in)); // nothing dropped, or nothing unlocked would be left to hold the share
    for (Influence& i : out)
        if (!c.isLocked(i.joint))
            i.weight = float(i.weight * (kept + removed) / kept);
    return tidy(std::move(out));
}

} // namespace

std::vector<VertexInfluences> pruneWeights(const WeightContext& c, const std::vector<std::uint32_t>& vertices, double below)
{
    return perVertex(c, vertices, [&](const std::vector<Influence>& own) {
        return dropUnlocked(own, c, [&](const Influence& i) { return i.weight < below; });
    });
}

std::vector<VertexInfluences> normaliseWeights(const WeightContext& c, const std::vector<std::uint32_t>& vertices)
{
    return perVertex(c, vertices, [&](const std::vector<Influence>& own) {
        double locked = 0.0, unlocked = 0.0;
        for (const Influence& i : own)
            (c.isLocked(i.joint) ? locked : unlocked) += i.weight;
        std::vector<Influence> out = own;
        if (unlocked > 0.0 && locked < 1.0)
            for (Influence& i : out)
                if (!c.isLocked(i.joint))
                    i.weight = float(i.weight * (1.0 - locked) / unlocked);
        return tidy(std::move(out));
    });
}

std::vector<VertexInfluences> limitWeights(const WeightContext& c, const std::vector<std::uint32_t>& vertices, int maxInfluences)
{
    const std::size_t limit = std::size_t(std::max(1, maxInfluences));
    return perVertex(c, vertices, [&](const std::vector<Influence>& own) {
        if (own.size() <= limit)
            return tidy(own);
        std::vector<Influence> sorted = tidy(own);
        // The smallest unlocked ones go until the limit holds (locked ones stay).
        std::vector<bool> drop(sorted.size(), false);
        std::size_t count = sorted.size();
        for (std::size_t k = sorted.size(); k-- > 0 && count > limit;)
            if (!c.isLocked(sorted[k].joint)) {
                drop[k] = true;
                --count;
            }
        std::size_t k = 0;
        return dropUnlocked(sorted, c, [&](const Influence&) { return drop[k++]; });
    });
}

MirrorResult mirrorWeights(const WeightContext& c, const std::vector<std::uint32_t>& jointMirror, int axis, bool fromPositive,
                           double tolerance)
{
    MirrorResult result;
    const Surface& s = *c.surface;
    const Welds welds(s);
    axis = std::clamp(axis, 0, 2);
    Cloud cloud{&s.positions};
    Tree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    tree.buildIndex();
    for (std::uint32_t v = 0; v < s.positions.size(); ++v) {
        const double side = s.positions[v][axis];
        if (std::abs(side) <= tolerance || (side > 0.0) == fromPositive)
            continue; // on the plane, or a source vertex
        Vec3 reflected = s.positions[v];
        reflected[axis] = -reflected[axis];
        std::size_t nearest = 0;
        double d2 = 0.0;
        nanoflann::KNNResultSet<double> found(1);
        found.init(&nearest, &d2);
        tree.findNeighbors(found, &reflected[0], nanoflann::SearchParams());
        if (!(d2 <= tolerance * tolerance)) {
            ++result.unmatched;
            continue;
        }
        std::vector<Influence> mirrored;
        for (Influence i : influencesOf(*c.weights, welds.first(std::uint32_t(nearest)))) {
            if (i.joint < jointMirror.size())
                i.joint = jointMirror[i.joint];
            mirrored.push_back(i);
        }
        // Locked joints of the target keep their shares.
        const std::vector<Influence> own = influencesOf(*c.weights, welds.first(v));
        emit(c, welds, v, blendUnlocked(own, tidy(mirrored), 1.0, c), result.vertices);
    }
    sortByVertex(result.vertices);
    return result;
}

} // namespace rs::skin
