// A uniform grid over the points (counting sort by cell, points copied in cell
// order for cache-friendly scans) settles most queries in the 27 cells around
// them: a query's k-th nearest found so far is final once it is nearer than
// every face of the block of cells searched (faces on the grid's edge bound
// nothing: no point lies beyond them). A query farther from the points than
// a cell goes to the KD-tree (a second ring of 98 cells cost more than the
// tree on a target 1 cm off a 3 mm-spaced source).
#include "skin/NearestPoints.h"

#include <glm/glm.hpp>
#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

namespace rs::skin {

namespace {

struct Cloud {
    const std::vector<glm::vec3>* points = nullptr;
    std::size_t kdtree_get_point_count() const { return points->size(); }
    float kdtree_get_pt(std::size_t i, std::size_t d) const { return (*points)[i][int(d)]; }
    template <class B>
    bool kdtree_get_bbox(B&) const { return false; }
};
using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, Cloud>, Cloud, 3, std::uint32_t>;

constexpr std::size_t kMaxCells = std::size_t(1) << 24;
constexpr int kRings = 1;
constexpr float kPointsPerCell = 1.0f; // points per filled cell the grid aims at

// The k best so far, nearest first.
struct Best {
    int k = 0, size = 0;
    std::uint32_t* index;
    float* distance2;
    float worst() const { return size < k ? std::numeric_limits<float>::infinity() : distance2[k - 1]; }
    void offer(std::uint32_t i, float d2)
    {
        if (size == k && d2 >= distance2[size - 1])
            return;
        int at = size < k ? size++ : size - 1;
        for (; at > 0 && distance2[at - 1] > d2; --at) {
            distance2[at] = distance2[at - 1];
            index[at] = index[at - 1];
        }
        distance2[at] = d2;
        index[at] = i;
    }
};

// nanoflann's result-set interface over Best (seeded with what the grid found).
struct SeededResult {
    Best& best;
    std::size_t size() const { return std::size_t(best.size); }
    bool full() const { return best.size == best.k; }
    bool addPoint(float d2, std::uint32_t i)
    {
        if (d2 < best.worst() && std::find(best.index, best.index + best.size, i) == best.index + best.size)
            best.offer(i, d2); // (the grid may have found it already)
        return true;
    }
    float worstDist() const { return best.worst(); }
};

} // namespace

struct NearestPoints::Impl {
    std::vector<glm::vec3> points;
    Cloud cloud;
    // Built by the first query the grid cannot settle (a target over its source may never need it).
    mutable std::once_flag treeBuilt;
    mutable std::unique_ptr<Tree> tree;
    // The grid: cells[c] .. cells[c + 1] index sorted / sortedIndex.
    glm::vec3 origin{0.0f};
    float cell = 1.0f;
    int n[3] = {1, 1, 1};
    std::vector<std::uint32_t> cells;
    std::vector<glm::vec3> sorted;
    std::vector<std::uint32_t> sortedIndex;

    int cellOf(float x, int axis) const { return std::clamp(int(std::floor((x - origin[axis]) / cell)), 0, n[axis] - 1); }

    // Cells of side `side` (grown until there are at most kMaxCells), the points sorted into them.
    void fill(const glm::vec3& lo, const glm::vec3& extent, float side)
    {
        cell = std::max({side, extent.x / 4096.0f, extent.y / 4096.0f, extent.z / 4096.0f, 1e-6f});
        for (;;) {
            for (int a = 0; a < 3; ++a)
                n[a] = std::max(1, int(std::ceil(extent[a] / cell)) + 1);
            if (std::size_t(n[0]) * std::size_t(n[1]) * std::size_t(n[2]) <= kMaxCells)
                break;
            cell *= 1.25f;
        }
        origin = lo;
        const std::size_t count = std::size_t(n[0]) * std::size_t(n[1]) * std::size_t(n[2]);
        cells.assign(count + 1, 0);
        std::vector<std::uint32_t> cellOfPoint(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            const glm::vec3& p = points[i];
            cellOfPoint[i] = std::uint32_t((std::size_t(cellOf(p.z, 2)) * std::size_t(n[1]) + std::size_t(cellOf(p.y, 1))) * std::size_t(n[0]) +
                                           std::size_t(cellOf(p.x, 0)));
            ++cells[cellOfPoint[i] + 1];
        }
        for (std::size_t c = 0; c < count; ++c)
            cells[c + 1] += cells[c];
        sorted.resize(points.size());
        sortedIndex.resize(points.size());
        std::vector<std::uint32_t> next(cells.begin(), cells.end() - 1);
        for (std::size_t i = 0; i < points.size(); ++i) {
            const std::uint32_t at = next[cellOfPoint[i]]++;
            sorted[at] = points[i];
            sortedIndex[at] = std::uint32_t(i);
        }
    }

    void buildGrid()
    {
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
        for (const glm::vec3& p : points) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        const glm::vec3 extent = glm::max(hi - lo, glm::vec3(1e-6f));
        // First about two cells per point by volume. Points on a surface fill
        // few of them, crowded: the side then shrinks (as the square root, a
        // surface's count per cell going as its area) to about kPointsPerCell
        // per filled cell (1 measured fastest of 0.5, 1, 2 and 4 on the bench).
        fill(lo, extent, std::cbrt(extent.x * extent.y * extent.z / float(2 * points.size())));
        std::size_t filled = 0;
        for (std::size_t c = 0; c + 1 < cells.size(); ++c)
            filled += cells[c + 1] > cells[c];
        const float perCell = float(points.size()) / float(std::max<std::size_t>(filled, 1));
        if (perCell > 1.5f * kPointsPerCell)
            fill(lo, extent, cell * std::max(0.25f, std::sqrt(kPointsPerCell / perCell)));
    }

    // The points of the cells from c - r to c + r on each axis: each row of
    // cells along x is one run of `sorted`.
    void scan(const glm::vec3& q, const int* c, int r, Best& best) const
    {
        const int x0 = std::max(c[0] - r, 0), x1 = std::min(c[0] + r, n[0] - 1);
        for (int z = std::max(c[2] - r, 0); z <= std::min(c[2] + r, n[2] - 1); ++z)
            for (int y = std::max(c[1] - r, 0); y <= std::min(c[1] + r, n[1] - 1); ++y) {
                const std::size_t row = (std::size_t(z) * std::size_t(n[1]) + std::size_t(y)) * std::size_t(n[0]);
                const std::uint32_t end = cells[row + std::size_t(x1) + 1];
                for (std::uint32_t i = cells[row + std::size_t(x0)]; i < end; ++i) {
                    const glm::vec3 d = sorted[i] - q;
                    const float d2 = d.x * d.x + d.y * d.y + d.z * d.z;
                    if (d2 < best.worst())
                        best.offer(sortedIndex[i], d2);
                }
            }
    }

    // The distance within which the block of ring r around cell c holds every point.
    float settled(const glm::vec3& q, const int* c, int r) const
    {
        float bound = std::numeric_limits<float>::infinity();
        for (int a = 0; a < 3; ++a) {
            if (c[a] - r > 0)
                bound = std::min(bound, q[a] - (origin[a] + float(c[a] - r) * cell));
            if (c[a] + r < n[a] - 1)
                bound = std::min(bound, origin[a] + float(c[a] + r + 1) * cell - q[a]);
        }
        return std::max(bound, 0.0f);
    }
};

NearestPoints::NearestPoints(std::vector<glm::vec3> points) : m_impl(std::make_unique<Impl>())
{
    m_impl->points = std::move(points);
    m_impl->cloud.points = &m_impl->points;
    if (!m_impl->points.empty())
        m_impl->buildGrid();
}

NearestPoints::~NearestPoints() = default;
NearestPoints::NearestPoints(NearestPoints&&) noexcept = default;
NearestPoints& NearestPoints::operator=(NearestPoints&&) noexcept = default;

std::size_t NearestPoints::size() const { return m_impl->points.size(); }

int NearestPoints::nearest(const glm::vec3& q, int k, std::uint32_t* index, float* distance2) const
{
    const Impl& g = *m_impl;
    k = int(std::min<std::size_t>(std::size_t(std::clamp(k, 0, kMaxK)), g.points.size()));
    if (k == 0)
        return 0;
    const int c[3] = {g.cellOf(q.x, 0), g.cellOf(q.y, 1), g.cellOf(q.z, 2)};
    Best best{k, 0, index, distance2};
    for (int r = 1; r <= kRings; ++r) {
        if (r > 1)
            best.size = 0; // the block of ring r holds ring r - 1's points again
        g.scan(q, c, r, best);
        const float bound = g.settled(q, c, r);
        if (best.size == k && best.worst() <= bound * bound)
            return k;
    }
    std::call_once(g.treeBuilt, [&g] {
        g.tree = std::make_unique<Tree>(3, g.cloud, nanoflann::KDTreeSingleIndexAdaptorParams(12));
        g.tree->buildIndex();
    });
    // The tree starts from the grid's candidates: their distance bounds its search.
    SeededResult found{best};
    g.tree->findNeighbors(found, &q.x, nanoflann::SearchParams());
    return best.size;
}

} // namespace rs::skin
