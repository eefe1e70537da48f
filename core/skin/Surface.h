#pragma once
// The surface heat diffuses over: a mesh's vertices welded where they share a
// position (UV and normal seams split a vertex in the file, not on the body),
// its usable triangles (zero-area ones dropped), its connected parts (eyes,
// teeth, a jacket over a body), and the cotangent weights and vertex areas of
// the diffusion. Holes, non-manifold edges and duplicated vertices are fine.
#include "model/Mesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace rs::skin {

struct Surface {
    std::vector<std::uint32_t> welded;            // file vertex -> surface vertex
    std::vector<Vec3> positions;                  // per surface vertex
    std::vector<std::array<std::uint32_t, 3>> triangles; // with area, welded
    std::vector<std::uint32_t> part;              // per surface vertex: its connected part
    std::size_t partCount = 0;
    std::vector<double> area;                     // a third of the incident triangles' area (0: on none)
    struct Edge {
        std::uint32_t a, b;
        double weight; // the cotangent weight, clamped at 0 (obtuse angles never push heat back)
    };
    std::vector<Edge> edges; // each undirected edge once, a < b
};

Surface makeSurface(const model::Mesh& mesh);

} // namespace rs::skin
