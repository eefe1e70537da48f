#pragma once
// The tools a rigger edits skin weights with: brush dabs (add, subtract,
// replace, smooth; a radius over the surface or through the volume, with a
// falloff), whole-mesh or selection operations (smooth, prune, normalise,
// limit influences) and mirroring across a plane. Each returns the vertices it
// changes and their new influences, normalised, leaving locked joints' weights
// as they are; the session turns that into one undoable weight edit.
//
// Tools work on the welded surface: the vertices a UV or normal seam splits in
// the file are one point of the body and always get the same weights.
#include "model/Mesh.h"
#include "skin/Surface.h"

#include <cstdint>
#include <vector>

namespace rs::skin {

struct VertexInfluences {
    std::uint32_t vertex = 0;                 // file vertex
    std::vector<model::Influence> influences; // into the weights' joints; sum 1, largest first
};

// What a tool reads. `locked` has one entry per weights joint (or is empty: none locked).
struct WeightContext {
    const model::Mesh* mesh = nullptr;
    const Surface* surface = nullptr; // makeSurface(*mesh)
    const model::MeshWeights* weights = nullptr;
    std::vector<bool> locked;
    bool isLocked(std::uint32_t joint) const { return joint < locked.size() && locked[joint]; }
};

enum class BrushMode { Add, Subtract, Replace, Smooth };
enum class Falloff { Smooth, Linear, Constant };

struct Brush {
    BrushMode mode = BrushMode::Add;
    std::uint32_t joint = 0;      // the painted joint (into the weights' joints); unused by Smooth
    double radius = 0.05;         // metres
    double strength = 0.5;        // 0 to 1: how far one dab goes towards its goal at the centre
    Falloff falloff = Falloff::Smooth;
    bool surface = true;          // reach along the surface from `vertex` (no bleeding across a gap); else a ball
    Vec3 centre{0.0};             // the hit point
    std::uint32_t vertex = 0;     // the file vertex nearest the hit (surface brushes start there)
};

std::vector<VertexInfluences> brushDab(const WeightContext& context, const Brush& brush);

// Operations on `vertices` (file vertices; empty: every vertex).
std::vector<VertexInfluences> smoothWeights(const WeightContext& context, const std::vector<std::uint32_t>& vertices, double strength,
                                            int iterations);
std::vector<VertexInfluences> pruneWeights(const WeightContext& context, const std::vector<std::uint32_t>& vertices, double below);
std::vector<VertexInfluences> normaliseWeights(const WeightContext& context, const std::vector<std::uint32_t>& vertices);
std::vector<VertexInfluences> limitWeights(const WeightContext& context, const std::vector<std::uint32_t>& vertices, int maxInfluences);

// Mirrors one side onto the other across the plane `axis` = 0 (x = 0), 1 or
// 2: every vertex on the target side takes the weights of the vertex nearest
// its reflection, each joint swapped for its mirror (`jointMirror[j]`, j itself
// on the centre line). `fromPositive`: the +axis side is the source. Vertices
// within `tolerance` of the plane are left alone; a target vertex with no
// source vertex within `tolerance` of its reflection is counted in `unmatched`.
struct MirrorResult {
    std::vector<VertexInfluences> vertices;
    std::size_t unmatched = 0;
};
MirrorResult mirrorWeights(const WeightContext& context, const std::vector<std::uint32_t>& jointMirror, int axis, bool fromPositive,
                           double tolerance = 1e-3);

// Sets `joint`'s share of `influences` to `target` (clamped to what locked
// joints leave), rescaling the other unlocked joints so the sum stays 1. With
// no other unlocked weight to take a reduction, it goes to the joint's skin
// parent (when unlocked); otherwise the share cannot drop. Largest first.
std::vector<model::Influence> setShare(std::vector<model::Influence> influences, std::uint32_t joint, double target,
                                       const WeightContext& context);

} // namespace rs::skin
