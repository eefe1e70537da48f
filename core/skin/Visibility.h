#pragma once
// Line-of-sight tests against a surface (Embree): is the straight segment
// from a vertex to a point on a bone free of the mesh? Thread-safe queries.
#include "skin/Surface.h"

#include <memory>

namespace rs::skin {

class Visibility {
public:
    // The surface's triangles, and those of `occluders` (the model's other
    // meshes: a head hides the eyes inside it).
    explicit Visibility(const Surface& surface, const std::vector<const model::Mesh*>& occluders = {});
    ~Visibility();
    Visibility(const Visibility&) = delete;
    Visibility& operator=(const Visibility&) = delete;

    // True when the segment from `from` to `to` crosses no triangle, ignoring
    // the first and last `margin` of it (the vertex's own triangles, a bone
    // point lying on the surface).
    bool clear(const Vec3& from, const Vec3& to, double margin = 1e-3) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m;
};

} // namespace rs::skin
