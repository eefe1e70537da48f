#pragma once
// Skin weight files (`<guide>.weights`): the bound meshes' weights, beside the
// guide. Binary, little-endian, versioned and checksummed; written atomically.
//
//   "RSWEIGHT"  8 bytes
//   u32 version (1), u32 mesh count
//   per mesh:   str model (its file, relative to the weights file), str name,
//               u32 vertex count, u64 topology fingerprint
//               (model::topologyFingerprint), u32 joint count, per joint
//               {u32 instance, str branch, str tag (the skin joint's NodeKey),
//               i32 parent (its skin parent's index, -1 for a root)},
//               u32 influence count, u32 offsets[vertex count + 1],
//               per influence {u32 joint, f32 weight}
//   u64 FNV-1a checksum of every byte before it
//   (str: u32 byte length, then UTF-8 bytes)
//
// Reading checks every count against the bytes left, every offset, joint index
// and weight; a damaged file is an error naming the byte where it breaks.
//
// Beside the weights, the bound meshes' chunks (`<guide>.weights.rschunks`,
// io/SkinChunks.h): per record, the mesh as it was bound (all its vertices'
// bind positions and normals, its triangles, the record's weights), so that
// when the model file later changes topology the session re-fits the weights
// from the previous mesh (session::Session::refitChangedMeshes). A separate
// file, not a weights file v2: the weights file stays small and readable by
// every earlier version, and the sidecar is a normal chunk file that `skin
// info` and `skin import` read. No sidecar (older guides) means a changed mesh
// is reported and kept, not re-fitted.
#include "base/Result.h"
#include "base/Status.h"
#include "model/GuideDocument.h"
#include "model/Mesh.h"
#include "skin/SkinChunk.h"

#include <string>
#include <vector>

namespace rs::io {

struct BoundMesh {
    std::string model; // the model file, relative to the weights file's folder
    std::string name;  // the mesh's name in it
    std::size_t vertexCount = 0;
    std::uint64_t fingerprint = 0;
    model::MeshWeights weights;
};

std::string writeWeights(const std::vector<BoundMesh>& meshes);
// The checksum the file ends with: FNV-1a (64 bits) of every byte before it.
std::uint64_t weightsChecksum(const char* data, std::size_t size);
Result<std::vector<BoundMesh>> readWeights(const std::string& bytes, const std::string& path);

Status saveWeightsFile(const std::string& path, const std::vector<BoundMesh>& meshes);
Result<std::vector<BoundMesh>> loadWeightsFile(const std::string& path);

// A guide's weights: `<guide without its extension>.weights` beside it
// (hero.yml -> hero.weights), its records' model paths relative to it.
std::string weightsPathFor(const std::string& guidePath);
// Fills document.bindings from the guide's weights file (model paths made
// absolute); no file is no weights and no message. A damaged file fails with
// where it breaks, and document.bindings stays as it was.
Status loadGuideWeights(const std::string& guidePath, model::GuideDocument& document);
// Writes document.bindings beside the guide, atomically. A document without
// bindings writes nothing (an existing file is never replaced by an empty one).
Status saveGuideWeights(const model::GuideDocument& document, const std::string& guidePath);

// hero.yml -> hero.weights.rschunks
std::string chunksPathFor(const std::string& guidePath);
// The previous meshes' chunks beside the guide; no file is none and no message.
Result<std::vector<skin::SkinChunk>> loadGuideChunks(const std::string& guidePath);
// Writes them atomically; none writes nothing (an existing file stays).
Status saveGuideChunks(const std::vector<skin::SkinChunk>& chunks, const std::string& guidePath);

} // namespace rs::io
