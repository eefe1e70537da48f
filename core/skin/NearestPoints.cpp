// A uniform grid over the points (counting sort by cell, points copied in cell
// order for cache-friendly scans) settles most queries in the 27 cells around
// them: a query's k-th nearest found so far is final once it is nearer than
// every face of the block of cells searched (faces on the grid's edge bound
// nothing: no point lies beyond them). A query farther from the points than
// a cell tries the same in grids of cells two and four times wider; only what
// those cannot settle goes to the KD-tree (nanoflann). Building that tree
// took longer (one thread, the others waiting) than the coarser grids cost
// the queries of a target 12 mm off a 3 mm-spaced source (BM_TransferClosestPoint/1).
#include "skin/NearestPoints.h"

#include <glm/glm.hpp>
#include <nanoflann.hpp>
#include <tbb/parallel_for.h>

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
constexpr int kGrids = 3;      // grids from fine to coarse before the KD-tree
constexpr float kCoarser = 2.0f; // each grid's cells this many times wider than the last's
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


// One uniform grid over the points: cells[c] .. cells[c + 1] index sorted / sortedIndex.
struct Grid {
    glm::vec3 origin{0.0f};
    float cell = 1.0f;
    int n[3] = {1, 1, 1};
    std::vector<std::uint32_t> cells;
    std::vector<glm::vec3> sorted;
    std::vector<std::uint32_t> sortedIndex;

    int cellOf(float x, int axis) const { return std::clamp(int(std::floor((x - origin[axis]) / cell)), 0, n[axis] - 1); }

    // Cells of side `side` (grown until there are at most kMaxCells), the points sorted into them.
    void fill(const std::vector<glm::vec3>& points, const glm::vec3& lo, const glm::vec3& extent, float side)
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

    // The points of the cells from c - 1 to c + 1 on each axis: each row of
    // cells along x is one run of `sorted`.
    void scan(const glm::vec3& q, const int* c, Best& best) const
    {
        const int x0 = std::max(c[0] - 1, 0), x1 = std::min(c[0] + 1, n[0] - 1);
        for (int z = std::max(c[2] - 1, 0); z <= std::min(c[2] + 1, n[2] - 1); ++z)
            for (int y = std::max(c[1] - 1, 0); y <= std::min(c[1] + 1, n[1] - 1); ++y) {
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

    // The distance within which the block of cells around c holds every point.
    float settled(const glm::vec3& q, const int* c) const
    {
        float bound = std::numeric_limits<float>::infinity();
        for (int a = 0; a < 3; ++a) {
            if (c[a] - 1 > 0)
                bound = std::min(bound, q[a] - (origin[a] + float(c[a] - 1) * cell));
            if (c[a] + 1 < n[a] - 1)
                bound = std::min(bound, origin[a] + float(c[a] + 2) * cell - q[a]);
        }
        return std::max(bound, 0.0f);
    }

    // Whether the block of cells around q settles its k nearest (found into `best`, emptied first).
    bool search(const glm::vec3& q, int k, Best& best) const
    {
        const int c[3] = {cellOf(q.x, 0), cellOf(q.y, 1), cellOf(q.z, 2)};
        best.size = 0;
        scan(q, c, best);
        const float bound = settled(q, c);
        return best.size == k && best.worst() <= bound * bound;
    }
};

} // namespace

struct NearestPoints::Impl {
    std::vector<glm::vec3> points;
    Cloud cloud;
    // Built by the first query no grid can settle (a target near its source may never need it).
    mutable std::once_flag treeBuilt;
    mutable std::unique_ptr<Tree> tree;
    // Grids of cells kCoarser times wider each: the first sized for queries on the surface.
    std::vector<Grid> grids;

    void buildGrids()
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
        Grid& fine = grids.emplace_back();
        fine.fill(points, lo, extent, std::cbrt(extent.x * extent.y * extent.z / float(2 * points.size())));
        std::size_t filled = 0;
        for (std::size_t c = 0; c + 1 < fine.cells.size(); ++c)
            filled += fine.cells[c + 1] > fine.cells[c];
        const float perCell = float(points.size()) / float(std::max<std::size_t>(filled, 1));
        if (perCell > 1.5f * kPointsPerCell)
            fine.fill(points, lo, extent, fine.cell * std::max(0.25f, std::sqrt(kPointsPerCell / perCell)));
        // Coarser grids for queries off the surface, while a block of cells
        // still holds a small part of the points.
        int levels = 1;
        for (float side = fine.cell; levels < kGrids; ++levels) {
            const int across = int(std::ceil(std::max({extent.x, extent.y, extent.z}) / side)) + 1;
            if (across <= 3)
                break; // one block of the last grid is the whole grid: it settles every query
            side *= kCoarser;
        }
        grids.resize(std::size_t(levels));
        tbb::parallel_for(1, levels, [&](int level) {
            grids[std::size_t(level)].fill(points, lo, extent, grids[0].cell * std::pow(kCoarser, float(level)));
        });
    }
};

NearestPoints::NearestPoints(std::vector<glm::vec3> points) : m_impl(std::make_unique<Impl>())
{
    m_impl->points = std::move(points);
    m_impl->cloud.points = &m_impl->points;
    if (!m_impl->points.empty())
        m_impl->buildGrids();
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
    Best best{k, 0, index, distance2};
    for (const Grid& grid : g.grids)
        if (grid.search(q, k, best))
            return k;
    std::call_once(g.treeBuilt, [&g] {
        g.tree = std::make_unique<Tree>(3, g.cloud, nanoflann::KDTreeSingleIndexAdaptorParams(12));
        g.tree->buildIndex();
    });
    // The tree starts from the coarsest grid's candidates: their distance bounds its search.
    SeededResult found{best};
    g.tree->findNeighbors(found, &q.x, nanoflann::SearchParams());
    return best.size;
}

} // namespace rs::skin
