#pragma once
// Re-fitting (Session, SessionRefit.cpp): a binding whose mesh changed topology
// is re-fitted from the previous mesh's chunk (its bind positions and
// triangles; the binding's own weights) through skin::importChunks with
// Session::refitOptions(): 1:1 only when count and order still match, else the
// fallback, by default weight inpainting (closest point kept where it is
// near and its normal agrees, the rest solved), so a remesh whose shape
// moved does not stretch. Previous chunks come from the host (the chunk
// file saved beside the weights, Session::setSavedChunks) or from the mesh in
// memory when a model is reloaded. A re-fit is one undo step ("Re-fit
// weights"), so the old record comes back with undo; the build log says
// per mesh how many vertices were matched 1:1, transferred or inpainted.
// Run after replaceDocument, reloadModel and build; never by undo/redo.
//
// The re-fit of changed meshes (issue 20 item 5) in three steps, like an
// import (SkinChunkJob.h), so the editor can run the long middle one on a
// worker thread while the window stays responsive:
//
//   Session::prepareRefit  (session thread) copies what the re-fit reads: per
//                          changed mesh its record, its previous chunk and the
//                          new mesh (shared, immutable), the rig, the options,
//                          and the session's revision;
//   RefitJob::run          (any thread) re-fits every mesh (skin::refitBinding);
//   Session::applyRefit    (session thread) puts the records in place as ONE
//                          undo step, refused for a stale job: the document or
//                          its models changed since prepare (the host then
//                          prepares again; a result is never applied over
//                          newer edits).
//
// Session::refitChangedMeshes() does all three on its thread, unless a host
// set a RefitRunner: it then hands the prepared job over and returns.
#include "base/Status.h"
#include "session/SkinChunkJob.h"
#include "model/Mesh.h"
#include "model/Rig.h"
#include "skin/Refit.h"
#include "skin/SkinChunk.h"
#include "skin/Transfer.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace rs::session {

struct RefitJob {
    struct Item {
        model::MeshBinding was;                     // the record, made for the previous mesh
        skin::SkinChunk previous;                   // where its vertices were
        std::shared_ptr<const model::Model> model;  // keeps the mesh alive on the worker
        const model::Mesh* mesh = nullptr;          // the mesh as it is now
    };
    std::vector<Item> items;
    std::shared_ptr<const model::Rig> rig; // names the influences; null without a rig
    skin::TransferOptions options;
    std::uint64_t revision = 0;            // Session::revision() at prepare

    // After run(): per item, its re-fit (nullopt: it failed, said in notes).
    std::vector<std::optional<skin::Refit>> refits;
    Diagnostics notes;

    // Re-fits every item; fails only when cancelled (options.progress returned false).
    Status run();
    // Per vertex of item `i`'s mesh, the step that placed its weights (empty when it was not re-fitted).
    std::vector<VertexRoute> routes(std::size_t i) const;
};

} // namespace rs::session
