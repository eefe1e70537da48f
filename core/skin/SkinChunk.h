#pragma once
// A skin chunk (issue 20, after Skinner's SkinChunk): one mesh's skin weights
// as exported, with everything an import needs to put them back on that mesh
// or on a changed one: the vertices it covers and where they were (bind pose
// and the pose at export), their weights, the influences with their
// hierarchy and matrices, and who exported it when. A chunk is a point cloud
// with the triangles among its vertices: transfer reads closest points on
// those triangles, or the vertices alone when it has none.
//
// The file format is io/SkinChunks.h; the import decision tree and the
// fallback methods are skin/Transfer.h. Spaces: world, metres, Y-up.
#include "base/Identity.h"
#include "base/Math.h"
#include "model/Mesh.h"
#include "model/Rig.h"
#include "skin/SkinBones.h"
#include "skin/Skinning.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rs::skin {

// One influence of a chunk: its identity (the skin joint's NodeKey) and its
// export name, so an import matches by identity or, through a name map, by name.
struct ChunkJoint {
    NodeKey key;
    std::string name;        // the rig node's export name ("arm_L_shoulder_jnt")
    Mat4 world{1.0};         // world matrix in the pose at export
    Mat4 local{1.0};         // relative to the parent influence's world (world itself for a root)
    Mat4 bind{1.0};          // world matrix at bind (the inverse bind matrix is its inverse)
};

struct SkinChunk {
    std::string mesh;                 // the mesh's name (the name matched on import)
    std::string model;                // the model file it came from (information only)
    std::string tool;                 // "rigsmith 0.1.0"
    std::string user;                 // who exported it
    std::int64_t exportedAtMicroseconds = 0; // UTC, since 1970: the newest chunk wins a name clash
    std::uint32_t totalVertexCount = 0;      // the mesh's vertex count at export
    std::uint64_t fingerprint = 0;           // model::topologyFingerprint of the mesh at export
    SkinningMethod method = SkinningMethod::Linear;
    bool inBindPose = true;           // exported in bind pose: positions are the bind positions

    // Per exported vertex (all of the mesh, or a subset), ascending ids.
    std::vector<std::uint32_t> vertexIds;  // mesh vertex ids, < totalVertexCount
    std::vector<glm::vec3> positions;      // in the pose at export
    std::vector<glm::vec3> normals;        // unit, in the pose at export
    std::vector<glm::vec3> bindPositions;  // pre-deformed; empty when inBindPose (then `positions`)
    std::vector<glm::vec3> bindNormals;    // pre-deformed; empty when inBindPose
    // Weights per exported vertex; weights.joints/parents are the influences
    // (keys and hierarchy), `joints` their names and matrices, one per influence.
    model::MeshWeights weights;
    std::vector<ChunkJoint> joints;
    // Triangles whose three vertices were exported, as indices into the exported vertices.
    std::vector<std::uint32_t> triangles;
    // A sample of each exported vertex's neighbours (mesh vertex ids, along edges).
    std::vector<std::uint32_t> neighbourOffsets; // exported vertex count + 1 entries
    std::vector<std::uint32_t> neighbours;

    std::size_t vertexCount() const { return vertexIds.size(); }
    const std::vector<glm::vec3>& restPositions() const { return inBindPose ? positions : bindPositions; }
    const std::vector<glm::vec3>& restNormals() const { return inBindPose ? normals : bindNormals; }
};

// What an export reads: a mesh (bind pose, as imported) with its weights on
// `bones` (retargeted: weights.joints are the bones' keys, in order).
struct ChunkSource {
    const model::Mesh* mesh = nullptr;
    const model::MeshWeights* weights = nullptr;
    std::string model;                        // the model file, for the chunk
    std::vector<std::uint32_t> vertices;      // the vertices to export (ascending); empty: all
};

struct ChunkExportOptions {
    const model::Rig* rig = nullptr;          // the rest rig the bones come from (names, bind matrices)
    const model::Rig* posedRig = nullptr;     // the rig in the current pose; null: bind pose
    SkinningMethod method = SkinningMethod::Linear;
    int neighbourSample = 4;                  // neighbours kept per vertex (0: none)
    std::string tool, user;
    std::int64_t exportedAtMicroseconds = 0;
};

// The chunk of one mesh: positions in the current pose by CPU skinning
// (options.posedRig), normals from the mesh or its triangles. Fails when the
// weights do not fit the mesh or the bones, or a vertex id is out of range.
Result<SkinChunk> makeSkinChunk(const ChunkSource& source, const std::vector<SkinBone>& bones, const ChunkExportOptions& options);

// The bind-pose chunk of a whole mesh whose weights are on `joints` (one per
// weights.joints, in order), without a rig (what `skin transfer` writes);
// options.rig and posedRig are not read. Fails when the sizes disagree.
Result<SkinChunk> makeBindPoseChunk(const model::Mesh& mesh, const model::MeshWeights& weights, std::vector<ChunkJoint> joints,
                                    const std::string& model, const ChunkExportOptions& options);

// An export time as people read it: "2024-05-01 13:45:12 UTC".
std::string formatExportTime(std::int64_t microsecondsSince1970);

// Area-weighted vertex normals (model/Mesh.h), as skin code calls them.
using model::vertexNormals;

} // namespace rs::skin
