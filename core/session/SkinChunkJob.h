#pragma once
// Skin chunk export and import in the session (issue 20): what they cover
// (a SkinScope) and an import in three steps, so the editor can run the long
// middle one on a worker thread:
//
//   Session::prepareSkinImport  (session thread) merges the chunks and takes
//                               the target meshes (shared, immutable models);
//   SkinImportJob::run          (any thread) runs the decision tree
//                               (skin::importChunks); reads only the job;
//   Session::applySkinImport    (session thread) puts the weights in place as
//                               ONE undo step, refused when the models changed
//                               since prepare.
//
// A preview is prepare + run without apply. Cancelling (options.progress
// returning false) makes run fail; nothing in the session changes.
#include "base/Result.h"
#include "base/Status.h"
#include "session/CreateInfluences.h"
#include "skin/InfluenceMap.h"
#include "skin/SkinChunk.h"
#include "skin/Transfer.h"

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

namespace rs::session {

// What an export reads or an import writes.
struct SkinScope {
    enum class Kind {
        All,              // every mesh of the guide's models (export: every bound one)
        Meshes,           // the character meshes in `meshes`
        SelectedVertices, // Session::selectedVertices() (export: only those vertices; import: only
                          // those vertices of bound meshes, the others keep their weights)
        Joints,           // export only: the vertices the skin joints in `joints` weight, with all
                          // their weights, of every bound mesh (Skinner's joint selection); an
                          // import refuses it
    };
    Kind kind = Kind::All;
    std::vector<std::size_t> meshes; // Session::characterMeshes() indices, with Meshes
    std::vector<NodeKey> joints;     // skin joint keys, with Joints
    static SkinScope all() { return {}; }
    static SkinScope ofMeshes(std::vector<std::size_t> meshes) { return {Kind::Meshes, std::move(meshes), {}}; }
    static SkinScope selectedVertices() { return {Kind::SelectedVertices, {}, {}}; }
    static SkinScope ofJoints(std::vector<NodeKey> joints) { return {Kind::Joints, {}, std::move(joints)}; }
};

// Per target vertex, how a run placed its weights, as far as the decision
// tree's routes and the fallback say it: Transferred is the chosen method's
// copy (closest point or neighbours, the normal filter's fallback too),
// Inpainted the vertices weight inpainting solved for.
enum class VertexRoute : std::uint8_t { OneToOne, SingleInfluence, Transferred, Inpainted };

// Per vertex of a mesh of `count` vertices, its route by `report`: under the
// 1:1 route the vertices in `oneToOne` (the chunk's vertex ids; null: all of
// them), the others Transferred; the inpainted ones Inpainted.
std::vector<VertexRoute> vertexRoutes(const skin::MeshImportReport& report, std::size_t count,
                                      const std::vector<std::uint32_t>* oneToOne = nullptr);

// One import in flight. Owns copies of everything run() reads.
struct SkinImportJob {
    CreatedInfluences created; // missing influences made joints (rule "create"): apply adds them first
    std::vector<skin::SkinChunk> chunks; // merged: one per mesh name, the newest kept; weights on the rig's skin bones
    skin::InfluenceResolution influences; // how each chunk influence landed on a skin bone
    skin::TransferOptions options;
    struct Target {
        std::size_t characterMesh = 0;               // into Session::characterMeshes() at prepare
        std::shared_ptr<const model::Model> model;   // keeps the mesh alive on the worker
        const model::Mesh* mesh = nullptr;
        std::vector<std::uint32_t> vertices;         // ascending; empty: all of the mesh
    };
    std::vector<Target> targets;
    Diagnostics notes; // what the merge replaced
    // Append (skin/ImportScope.h, Skinner's "append" rather than "unbind
    // first"): a mesh loaded 1:1 from a chunk of some of its vertices keeps
    // its own weights on the others; without, every target vertex is
    // written. A mesh without weights that fit it is written whole either way.
    bool append = false;

    // After run(): per target, its weights (on the chunks' influences) and report.
    std::vector<model::MeshWeights> weights;
    std::vector<skin::MeshImportReport> reports;

    // Runs the decision tree on every target; fails on cancel or bad options.
    Status run();
    // Per vertex of target `t`, its route (after run()).
    std::vector<VertexRoute> routes(std::size_t t) const;
};

} // namespace rs::session
