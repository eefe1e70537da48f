#pragma once
// Importing skin chunks onto meshes (issue 20): the decision tree of Skinner
// and the fallback methods that carry weights onto a mesh whose topology
// changed. Per target mesh (name, vertex count, topology fingerprint):
//
//   a chunk of the mesh's name?
//     yes: only one influence carries weight  -> every vertex 100% on it
//          same vertex count and fingerprint  -> 1:1 by vertex id (vertices the
//                                                chunk leaves out: fallback on it)
//          else                               -> fallback on that chunk
//     no:  (searchByCountAndOrder) exactly one chunk with the mesh's count and
//          fingerprint                         -> 1:1 from it
//          else                               -> fallback on the uber chunk (all
//                                                chunks as one point cloud)
//
// Chunks from many files are merged first (mergeChunks): a name clash keeps
// the most recently exported chunk. Fallbacks read the chunk's pre-deformed
// (bind) points by default, the target's bind positions (a model as imported).
//
// Fallback methods (TransferMethod), each per target vertex, in parallel:
//  - ClosestPoint: the closest point on the source's triangles around its
//    nearest vertices (the triangle fans of the 3 nearest; the vertex itself
//    where the source has no triangles), the triangle's three vertices'
//    weights blended by the point's barycentric coordinates.
//  - ClosestNeighbours (Skinner's): the nearest source vertex at distance d;
//    up to neighbourCount source vertices within d * neighbourDistanceMultiplier,
//    their weights blended by inverse distance (one at distance 0 takes all).
//  - normalFilter: only source vertices (and triangles) whose normal makes a
//    dot product >= normalTolerance with the target's are used, among the 16
//    nearest; when none passes, that vertex falls back to ClosestPoint unfiltered.
//  - smoothSteps: when the target has more vertices than the source, steps
//    of averaging with edge neighbours, only on vertices not at a source
//    vertex's position and whose weights differ from a neighbour's by more
//    than weightDifferenceThreshold (for some joint).
//  - Inpainting (Abdrashitov et al., "Robust Skin Weights Transfer via Weight
//    Inpainting", SIGGRAPH Asia 2023): closest point on triangles is kept
//    only where the point is within inpaintDistance and its normal within
//    inpaintAngleDegrees of the target vertex's; the other vertices' weights
//    are solved for (skin/TransferInpaint.h), so overlapping or mismatched
//    shapes do not stretch. The normal filter does not apply.
// Every result vertex keeps at most maxInfluences weights, normalised.
#include "base/Result.h"
#include "model/Mesh.h"
#include "skin/SkinChunk.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rs::skin {

enum class TransferMethod { ClosestPoint, ClosestNeighbours, Inpainting };
const char* transferMethodName(TransferMethod method); // "closest", "neighbours", "inpaint"
std::optional<TransferMethod> parseTransferMethod(const std::string& name);

struct TransferOptions {
    TransferMethod method = TransferMethod::ClosestPoint;
    bool searchByCountAndOrder = true;   // a mesh without a name match may load 1:1 from a chunk of its count and order
    bool forceUberChunk = false;         // every mesh by fallback on the uber chunk (debugging)
    bool usePreDeformed = true;          // source points: the chunk's bind pose; false: its pose at export
    double neighbourDistanceMultiplier = 2.0; // > 1
    int neighbourCount = 3;              // 1 to 32
    bool normalFilter = false;
    double normalTolerance = 0.75;       // -1 to 1
    int smoothSteps = 0;                 // 0: none
    double weightDifferenceThreshold = 0.25;
    int maxInfluences = 0;               // 1 to 16; 0: the most any source vertex has
    double inpaintDistance = 0.0;        // Inpainting: metres a copied closest point may be away; 0: 5% of the target's bounding box diagonal
    double inpaintAngleDegrees = 30.0;   // Inpainting: the most its normal may turn from the target vertex's (0 to 180)
    // Hears the fraction of all target vertices done; false cancels (no result).
    // Inpainting: the closest points are the first fifth, the solve the rest
    // (reported between its phases, regions and groups of joints).
    std::function<bool(double)> progress;
};
// Refuses options out of range, naming the option.
Status validateTransferOptions(const TransferOptions& options);

enum class ImportRoute { OneToOne, SingleInfluence, Fallback };
const char* importRouteName(ImportRoute route); // "one-to-one", "single-influence", "fallback"

struct MeshImportReport {
    std::string mesh;
    std::string source;      // the chunk's mesh name, or "uber chunk"
    ImportRoute route = ImportRoute::Fallback;
    std::string why;         // "name, vertex count and order match", ...
    std::size_t vertices = 0;
    std::size_t oneToOne = 0, singleInfluence = 0, closestPoint = 0, closestNeighbours = 0;
    std::size_t normalFilterFallbacks = 0; // counted in closestPoint too
    std::size_t inpainted = 0;             // vertices whose weights were inpainted (not counted in closestPoint)
    std::vector<std::uint32_t> inpaintedVertices; // their ids, ascending (what a preview shows by step)
    std::size_t smoothed = 0;              // vertices a smoothing step changed
    double milliseconds = 0.0;
};

// The chunks of many files (in the order given), one per mesh name: the most
// recently exported wins a clash (the later one when both have the same time),
// a note names what it replaced.
Result<std::vector<SkinChunk>> mergeChunks(std::vector<SkinChunk> chunks);

// A point cloud transfer reads from: one chunk's vertices, or the uber chunk
// (all chunks'), with their triangles, normals, weights and a KD-tree. Built
// once, shared by every mesh that falls back on it. Immutable.
class TransferSource {
public:
    static Result<TransferSource> fromChunk(const SkinChunk& chunk, bool usePreDeformed);
    static Result<TransferSource> uber(const std::vector<SkinChunk>& chunks, bool usePreDeformed);
    std::size_t vertexCount() const;
    const model::MeshWeights& weights() const; // per source vertex; joints: the chunk's (the union, for the uber chunk)
    struct Data; // skin/TransferQuery.h

private:
    friend Result<model::MeshWeights> transferWeights(const TransferSource&, const model::Mesh&, const TransferOptions&,
                                                      MeshImportReport*);
    std::shared_ptr<const Data> m_data;
};

// Weights for every vertex of `target` (bind positions; normals from the mesh
// or its triangles) from `source` by the fallback method. `report` (optional)
// counts vertices per method. Fails on cancel or bad options.
Result<model::MeshWeights> transferWeights(const TransferSource& source, const model::Mesh& target, const TransferOptions& options,
                                           MeshImportReport* report = nullptr);

// The decision tree above for each target; results in the targets' order, their
// joints the source chunk's (merge first: `chunks` should hold one per name).
Result<std::vector<model::MeshWeights>> importChunks(const std::vector<SkinChunk>& chunks, const std::vector<const model::Mesh*>& targets,
                                                     const TransferOptions& options, std::vector<MeshImportReport>* reports = nullptr);

} // namespace rs::skin
