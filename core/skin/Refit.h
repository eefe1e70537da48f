#pragma once
// Re-fitting a weight record whose mesh changed topology (issue 20 item 5):
// the mesh as it was bound (a chunk: bind positions, normals, triangles,
// saved beside the guide's weights as <guide>.weights.rschunks) carries the
// record's own weights onto the new mesh by the import decision tree
// (skin/Transfer.h). The record is the truth for the weights; the chunk only
// says where its vertices were. Shared by the session (open, reload, build)
// and the CLI's build, so both re-fit the same way.
#include "base/Diagnostic.h"
#include "base/Result.h"
#include "model/Mesh.h"
#include "model/Rig.h"
#include "skin/SkinChunk.h"
#include "skin/Transfer.h"

#include <vector>

namespace rs::skin {

// The chunk of a mesh as `binding` fits it (every vertex, bind pose, the
// record's weights; influences named by `rig` when it has them, else by tag).
SkinChunk bindingChunk(const model::MeshBinding& binding, const model::Mesh& mesh, const model::Rig* rig);

// `chunk` with `binding`'s weights (its influences named by `rig` when it has them).
void putBindingWeights(SkinChunk& chunk, const model::MeshBinding& binding, const model::Rig* rig);

// Whether `chunk` is the whole mesh `binding` was made for (mesh name, model
// file name, vertex count, fingerprint).
bool chunkDescribes(const SkinChunk& chunk, const model::MeshBinding& binding);

// The newest of `chunks` that describes the mesh `binding` was made for (mesh
// name, model file name, vertex count, fingerprint; all vertices); null if none.
const SkinChunk* previousChunk(const std::vector<SkinChunk>& chunks, const model::MeshBinding& binding);

// Inpainting: what a re-fit does unless told otherwise.
TransferOptions defaultRefitOptions();

struct Refit {
    model::MeshBinding binding; // the new record, fitting `mesh`
    MeshImportReport report;
    Diagnostic note;            // "mesh 'x' changed since it was bound (...): re-fitted ...: N matched 1:1, ..."
};

// The record `was` re-fitted onto `mesh` from `previous`; fails (with why)
// when the transfer does, or is cancelled through options.progress.
Result<Refit> refitBinding(const model::MeshBinding& was, const SkinChunk& previous, const model::Mesh& mesh, const model::Rig* rig,
                           const TransferOptions& options);

} // namespace rs::skin
