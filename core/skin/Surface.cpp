#include "skin/Surface.h"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <unordered_map>

namespace rs::skin {

namespace {

struct PositionKey {
    std::uint32_t x, y, z;
    bool operator==(const PositionKey&) const = default;
};
struct PositionHash {
    std::size_t operator()(const PositionKey& k) const
    {
        return (std::size_t(k.x) * 73856093u) ^ (std::size_t(k.y) * 19349663u) ^ (std::size_t(k.z) * 83492791u);
    }
};
PositionKey keyOf(const glm::vec3& p)
{
    PositionKey k;
    const float x = p.x + 0.0f, y = p.y + 0.0f, z = p.z + 0.0f; // -0 and +0 weld
    std::memcpy(&k.x, &x, 4);
    std::memcpy(&k.y, &y, 4);
    std::memcpy(&k.z, &z, 4);
    return k;
}

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t v)
{
    while (parent[v] != v) {
        parent[v] = parent[parent[v]];
        v = parent[v];
    }
    return v;
}

} // namespace

Surface makeSurface(const model::Mesh& mesh)
{
    Surface s;
    s.welded.resize(mesh.positions.size());
    std::unordered_map<PositionKey, std::uint32_t, PositionHash> byPosition;
    byPosition.reserve(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        auto [it, added] = byPosition.try_emplace(keyOf(mesh.positions[v]), std::uint32_t(s.positions.size()));
        if (added)
            s.positions.push_back(Vec3(mesh.positions[v]));
        s.welded[v] = it->second;
    }
    const std::size_t n = s.positions.size();
    s.area.assign(n, 0.0);

    double extent = 0.0;
    for (const Vec3& p : s.positions)
        extent = std::max({extent, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    const double minArea = 1e-14 * std::max(extent * extent, 1e-12);

    std::vector<std::pair<std::uint64_t, double>> halfEdges; // (a << 32 | b, weight), merged below
    halfEdges.reserve(mesh.indices.size());
    auto addEdge = [&](std::uint32_t a, std::uint32_t b, double w) {
        if (a > b)
            std::swap(a, b);
        halfEdges.emplace_back((std::uint64_t(a) << 32) | b, w);
    };
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        std::array<std::uint32_t, 3> tri{};
        bool valid = true;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t index = mesh.indices[t + std::size_t(k)];
            if (index >= mesh.positions.size()) {
                valid = false;
                break;
            }
            tri[std::size_t(k)] = s.welded[index];
        }
        if (!valid || tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
            continue;
        const Vec3& p0 = s.positions[tri[0]];
        const Vec3& p1 = s.positions[tri[1]];
        const Vec3& p2 = s.positions[tri[2]];
        const double doubleArea = glm::length(glm::cross(p1 - p0, p2 - p0));
        if (!(doubleArea > 2.0 * minArea))
            continue; // zero-area (or NaN): no direction to diffuse along
        s.triangles.push_back(tri);
        for (int k = 0; k < 3; ++k)
            s.area[tri[std::size_t(k)]] += doubleArea / 6.0;
        // The cotangent of the angle at each corner weighs the opposite edge.
        for (int k = 0; k < 3; ++k) {
            const Vec3& corner = s.positions[tri[std::size_t(k)]];
            const Vec3& a = s.positions[tri[std::size_t((k + 1) % 3)]];
            const Vec3& b = s.positions[tri[std::size_t((k + 2) % 3)]];
            const double cot = glm::dot(a - corner, b - corner) / doubleArea;
            addEdge(tri[std::size_t((k + 1) % 3)], tri[std::size_t((k + 2) % 3)], 0.5 * std::clamp(cot, 0.0, 1e4));
        }
    }
    std::sort(halfEdges.begin(), halfEdges.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (std::size_t i = 0; i < halfEdges.size();) {
        const std::uint64_t key = halfEdges[i].first;
        double weight = 0.0;
        for (; i < halfEdges.size() && halfEdges[i].first == key; ++i)
            weight += halfEdges[i].second;
        s.edges.push_back({std::uint32_t(key >> 32), std::uint32_t(key & 0xffffffffu), weight});
    }

    // Parts: vertices joined by a usable triangle.
    std::vector<std::uint32_t> parent(n);
    std::iota(parent.begin(), parent.end(), 0u);
    for (const auto& tri : s.triangles)
        for (int k = 1; k < 3; ++k) {
            const std::uint32_t a = findRoot(parent, tri[0]), b = findRoot(parent, tri[std::size_t(k)]);
            if (a != b)
                parent[std::max(a, b)] = std::min(a, b);
        }
    s.part.resize(n);
    std::vector<std::uint32_t> partOfRoot(n, std::uint32_t(-1));
    for (std::uint32_t v = 0; v < n; ++v) {
        const std::uint32_t root = findRoot(parent, v);
        if (partOfRoot[root] == std::uint32_t(-1))
            partOfRoot[root] = std::uint32_t(s.partCount++);
        s.part[v] = partOfRoot[root];
    }
    return s;
}

} // namespace rs::skin
