#pragma once
// `skin transfer ... -o OUT.glb / OUT.gltf`: the target's meshes skinned with
// the transferred weights on the source's skeleton, written by io/GltfExport.
// The skeleton is every influence of the source's chunks (by key, in the
// chunks' order, parents from each chunk's hierarchy), each at its bind matrix
// (the bind pose is also the pose written); several roots get a common
// `root` joint at the origin, since a glTF skin has one skeleton root. Each
// vertex keeps its 4 largest weights, normalised (engines read 4); a vertex
// left without weight goes wholly on the skeleton's root, with a warning.
// Materials are not carried: the meshes are written plain.
#include "base/Diagnostic.h"
#include "model/Mesh.h"
#include "skin/SkinChunk.h"

#include <string>
#include <vector>

namespace rs::cli {

// `weights[i]` are `meshes[i]`'s (joints: keys of the chunks' influences).
// Nothing is written on an error (an influence no chunk has, or the writer's).
Diagnostics writeTransferredGltf(const std::string& path, const std::vector<const model::Mesh*>& meshes,
                                 const std::vector<model::MeshWeights>& weights, const std::vector<skin::SkinChunk>& chunks,
                                 const std::string& generator);

} // namespace rs::cli
