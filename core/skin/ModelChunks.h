#pragma once
// Skin chunks from a skinned model file (issue 20 item 6, `skin transfer`
// from a .glb/.fbx/...): each mesh io::importModel read with the file's
// weights (model::FileWeights) becomes a bind-pose chunk, so the decision
// tree and fallbacks of skin/Transfer.h read a skinned character the way
// they read exported chunks. Spaces: world, metres, Y-up (as imported).
//
// Every chunk lists every joint of the file's skeleton (Model::joints, parents
// first) as an influence, the way a chunk exported from a rig lists every
// skin joint: joints that weight nothing still carry the hierarchy. A joint's
// bind matrix is the mesh's own (from its bone's offset matrix) where the
// mesh has that bone, else FileJoint::world.
#include "base/Identity.h"
#include "base/Result.h"
#include "model/Mesh.h"
#include "skin/SkinChunk.h"

#include <string>
#include <vector>

namespace rs::skin {

// A file joint's influence key: its name is its identity (instance kNoId,
// branch "file", tag the name). It is never a rig node's key, so an import
// onto a rig matches it by export name (skin/InfluenceMap.h rule 2), and
// chunks of one file (or of files that share joint names) share influences.
NodeKey fileJointKey(const std::string& name);

// One chunk per skinned mesh, in the model's mesh order; options.rig and
// posedRig are not read. Fails naming the file when no mesh has weights or
// two skinned meshes share a name (a chunk set holds one chunk per name).
Result<std::vector<SkinChunk>> chunksFromModel(const model::Model& model, const ChunkExportOptions& options);

} // namespace rs::skin
