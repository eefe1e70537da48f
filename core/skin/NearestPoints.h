#pragma once
// The k nearest of a fixed set of points (the source vertices a weight
// transfer reads), exact, for many queries from several threads at once. A
// uniform grid answers queries near the points (a remeshed or refitted mesh
// over the source) from the 3 x 3 x 3 cells around them, two coarser grids
// those a little off it; a query none can settle (far from every point)
// goes to a KD-tree (nanoflann). Ties in distance: either point.
// Immutable once built; points are copied.
#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace rs::skin {

class NearestPoints {
public:
    static constexpr int kMaxK = 32;

    explicit NearestPoints(std::vector<glm::vec3> points);
    ~NearestPoints();
    NearestPoints(NearestPoints&&) noexcept;
    NearestPoints& operator=(NearestPoints&&) noexcept;

    std::size_t size() const;
    // Up to k (<= kMaxK) nearest points, nearest first:
    // their indices and squared distances. Returns how many (k, or fewer points).
    int nearest(const glm::vec3& query, int k, std::uint32_t* index, float* distance2) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace rs::skin
