// The weight operations on a selection or a whole mesh, vertex by vertex
// (prune, normalise, limit influences), and mirroring across a plane by the
// nearest reflected surface vertex (a KD-tree, nanoflann). Brush and smoothing:
// WeightTools.cpp.
#include "skin/WeightTools.h"
#include "skin/WeightToolsSupport.h"

#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>

namespace rs::skin {

using model::Influence;
using namespace detail;

namespace {

struct Cloud {
    const std::vector<Vec3>* points;
    std::size_t kdtree_get_point_count() const { return points->size(); }
    double kdtree_get_pt(std::size_t i, std::size_t d) const { return (*points)[i][int(d)]; }
    template <class B>
    bool kdtree_get_bbox(B&) const { return false; }
};
using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud, 3>;

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
