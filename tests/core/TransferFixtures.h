#pragma once
// Small synthetic meshes and weights for the skin chunk import tests
// (TransferTest, TransferMethodsTest, TransferCharacterTest): flat grids, a
// ramp over three joints (skin.a, skin.b, skin.c along x), one joint on
// every vertex, a whole mesh's chunk in bind pose, and a vertex's heaviest joint.
#include "model/Mesh.h"
#include "skin/SkinChunk.h"

#include <cstdint>
#include <string>

namespace rs::test::transfer {

// A grid of nx by ny vertices, `spacing` apart (1 cm), at height z, facing +z (or -z).
model::Mesh grid(const std::string& name, int nx, int ny, float z, bool up = true, float spacing = 0.01f);
// Three joints along x: the first fades into the second by x = width / 2, the second into the third by x = width.
model::MeshWeights rampWeights(const model::Mesh& mesh, float width);
// The ramp's three joints, every vertex all on `joint`.
model::MeshWeights allOn(const model::Mesh& mesh, std::uint32_t joint);
// The chunk of a whole mesh in bind pose, exported at `time` (microseconds: the merge tests say which is newer).
skin::SkinChunk chunkOf(const model::Mesh& mesh, const model::MeshWeights& weights, std::int64_t time = 1);
// The joint with the largest share of vertex `v`.
std::uint32_t dominant(const model::MeshWeights& w, std::size_t v);

} // namespace rs::test::transfer
