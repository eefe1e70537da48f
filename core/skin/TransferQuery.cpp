// One target vertex of a weight transfer (skin/TransferQuery.h): the closest
// point on the triangle fans of its nearest source vertices, or Skinner's
// closest neighbours, either after the vertex normal filter.
#include "skin/TransferQuery.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rs::skin::detail {

namespace {

// Barycentric coordinates (of a, b, c) of the point of triangle abc closest to
// p (Ericson, Real-Time Collision Detection, 5.1.5), from a and the edges
// ab, ac. A degenerate triangle gives its nearest corner.
glm::vec3 closestOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& ab, const glm::vec3& ac)
{
    const glm::vec3 ap = p - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0f && d2 <= 0.0f)
        return {1, 0, 0};
    const glm::vec3 bp = ap - ab;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0f && d4 <= d3)
        return {0, 1, 0};
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f && d1 - d3 > 0.0f) {
        const float t = d1 / (d1 - d3);
        return {1 - t, t, 0};
    }
    const glm::vec3 cp = ap - ac;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0f && d5 <= d6)
        return {0, 0, 1};
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f && d2 - d6 > 0.0f) {
        const float t = d2 / (d2 - d6);
        return {1 - t, 0, t};
    }
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && d4 - d3 >= 0.0f && d5 - d6 >= 0.0f && (d4 - d3) + (d5 - d6) > 0.0f) {
        const float t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {0, 1 - t, t};
    }
    const float sum = va + vb + vc;
    if (!(sum > 0.0f) || !std::isfinite(sum)) {
        const float da = glm::dot(ap, ap), db = glm::dot(bp, bp), dc = glm::dot(cp, cp);
        return da <= db && da <= dc ? glm::vec3(1, 0, 0) : db <= dc ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
    }
    const float v = vb / sum, w = vc / sum;
    return {1 - v - w, v, w};
}

} // namespace

bool Query::closestPoint(const glm::vec3& p, const std::uint32_t* vertices, const float* distance2, int count, const glm::vec3* normal,
                         Mix& mix, bool* rim, Hit* hit) const
{
    float best = std::numeric_limits<float>::infinity();
    std::uint32_t bestTriangle = ~0u, bestVertex = ~0u;
    glm::vec3 bestBary(0.0f);
    for (int i = 0; i < count; ++i) {
        const std::uint32_t v = vertices[i];
        bool any = false;
        for (std::uint32_t f = d.fanOffsets[v]; f < d.fanOffsets[v + 1]; ++f) {
            const std::uint32_t t = d.fans[f];
            if (normal && !passes(d.faceNormals[t], *normal))
                continue;
            any = true;
            // Fans overlap: a triangle with an earlier vertex's corner was tested with that fan.
            const std::uint32_t* c = &d.triangles[3 * t];
            bool tested = false;
            for (int j = 0; j < i && !tested; ++j)
                tested = c[0] == vertices[j] || c[1] == vertices[j] || c[2] == vertices[j];
            if (tested)
                continue;
            const Data::Corner& g = d.geometry[t];
            const glm::vec3 bary = closestOnTriangle(p, g.a, g.ab, g.ac);
            const glm::vec3 offset = g.a + bary.y * g.ab + bary.z * g.ac - p;
            const float d2 = glm::dot(offset, offset);
            if (d2 < best) {
                best = d2;
                bestTriangle = t;
                bestBary = bary;
            }
        }
        if (!any && distance2[i] < best) { // no (usable) triangle: the vertex itself
            best = distance2[i];
            bestTriangle = ~0u;
            bestVertex = v;
        }
        if (i == 0 && bestTriangle != ~0u) {
            const std::uint32_t* c = &d.triangles[3 * bestTriangle];
            const float centre = c[0] == v ? bestBary.x : c[1] == v ? bestBary.y : bestBary.z;
            if (centre > 0.0f)
                break;
            if (rim && count == 1) {
                *rim = true;
                return true;
            }
        }
    }
    if (bestTriangle != ~0u) {
        const std::uint32_t* c = &d.triangles[3 * bestTriangle];
        for (int k = 0; k < 3; ++k)
            mix.addVertex(d.weights, c[k], bestBary[k]);
        if (hit) { // the source's vertex normals interpolated at the point
            const glm::vec3 n = bestBary.x * d.normals[c[0]] + bestBary.y * d.normals[c[1]] + bestBary.z * d.normals[c[2]];
            const float length = glm::length(n);
            *hit = {best, length > 0.0f ? n / length : d.faceNormals[bestTriangle]};
        }
        return true;
    }
    if (bestVertex == ~0u)
        return false;
    mix.addVertex(d.weights, bestVertex, 1.0f);
    if (hit)
        *hit = {best, d.normals[bestVertex]};
    return true;
}

void Query::neighbours(const std::uint32_t* vertices, const float* distance2, int count, Mix& mix) const
{
    const float nearest = std::sqrt(distance2[0]);
    if (nearest <= kCoincident) {
        mix.addVertex(d.weights, vertices[0], 1.0f);
        return;
    }
    const float radius = nearest * float(o.neighbourDistanceMultiplier);
    for (int i = 0; i < count && i < o.neighbourCount; ++i) {
        const float distance = std::sqrt(distance2[i]);
        if (distance > radius)
            break;
        mix.addVertex(d.weights, vertices[i], 1.0f / distance);
    }
}

Route Query::transfer(const glm::vec3& p, const glm::vec3& normal, Mix& mix, float& nearestDistance, Hit* hit) const
{
    std::array<std::uint32_t, kMaxCandidates> index;
    std::array<float, kMaxCandidates> distance2;
    const bool neighbours = o.method == TransferMethod::ClosestNeighbours;
    // Closest point asks for the nearest vertex first, and for more only
    // when the closest point lies on the rim of its fan.
    const int wanted = neighbours ? o.neighbourCount : o.normalFilter ? kFanVertices : 1;
    int found = nearest(p, wanted, index.data(), distance2.data());
    nearestDistance = found > 0 ? std::sqrt(distance2[0]) : 0.0f;
    if (o.normalFilter) {
        // The normal filter: the candidates facing the target's way. When
        // the nearest all do (most vertices), they are what a wider search
        // would keep first; otherwise look among the kFilterCandidates nearest.
        bool all = true;
        for (int i = 0; i < found && all; ++i)
            all = passes(d.normals[index[i]], normal);
        if (!all)
            found = nearest(p, std::max(kFilterCandidates, wanted), index.data(), distance2.data());
        int kept = 0;
        for (int i = 0; i < found; ++i)
            if (passes(d.normals[index[i]], normal)) {
                index[kept] = index[i];
                distance2[kept++] = distance2[i];
            }
        if (kept > 0 && neighbours) {
            this->neighbours(index.data(), distance2.data(), std::min(kept, wanted), mix);
            return kNeighbours;
        }
        if (kept > 0 && closestPoint(p, index.data(), distance2.data(), std::min(kept, kFanVertices), &normal, mix))
            return kClosestPoint;
        // Nothing faces the target's way: closest point, unfiltered.
        found = nearest(p, kFanVertices, index.data(), distance2.data());
        closestPoint(p, index.data(), distance2.data(), found, nullptr, mix);
        return kFilterFallback;
    }
    if (neighbours) {
        this->neighbours(index.data(), distance2.data(), found, mix);
        return kNeighbours;
    }
    bool rim = false;
    closestPoint(p, index.data(), distance2.data(), found, nullptr, mix, &rim, hit);
    if (rim) {
        found = nearest(p, kFanVertices, index.data(), distance2.data());
        closestPoint(p, index.data(), distance2.data(), found, nullptr, mix, nullptr, hit);
    }
    return kClosestPoint;
}

} // namespace rs::skin::detail
