#pragma once
// Which vertices an import writes (issue 20 item 4, Skinner's "unbind first
// or append", and import onto a selection). The decision tree
// (skin/Transfer.h) gives weights for every vertex of a mesh; the import then
// writes them only where it should and keeps the mesh's existing weights
// elsewhere:
//  - a selection (vertex ids): only the selected vertices are written;
//  - append: only the vertices the import covers are written: those of the
//    chunk when it was loaded 1:1 from a chunk with a subset of the mesh's
//    vertices; every vertex when it was transferred or single-influence;
//  - neither (unbind first, the default): every vertex is written.
// Without existing weights that fit the mesh every vertex is written (as
// Skinner binds first, then loads the subset).
#include "model/Mesh.h"
#include "skin/Transfer.h"

#include <cstdint>
#include <vector>

namespace rs::skin {

struct ImportScope {
    const std::vector<std::uint32_t>* selection = nullptr; // ascending ids; null: the whole mesh
    bool append = false;
};

// Per vertex of the mesh, whether the import writes it. `chunks` and `report`
// are those importChunks used and gave for the mesh.
std::vector<bool> writtenVertices(const std::vector<SkinChunk>& chunks, const MeshImportReport& report, std::size_t vertexCount,
                                  const ImportScope& scope);

// `imported` where `write` is set, `existing` elsewhere; both on the same
// joints (same keys and parents, in order), one entry per vertex; else null.
std::optional<model::MeshWeights> keepUnwritten(const model::MeshWeights& existing, const model::MeshWeights& imported,
                                                const std::vector<bool>& write);

} // namespace rs::skin
