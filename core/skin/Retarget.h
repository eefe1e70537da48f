#pragma once
// Weights kept across rebuilds: weights bound to an earlier build, moved onto
// this build's skin joints by identity (NodeKey), whatever their order now. A
// skin joint that is gone (a template option removed it) hands its share to
// its nearest surviving skin ancestor, and a note names both; with no
// surviving ancestor, the skeleton's root takes it. Shares landing on one
// joint add up; every vertex stays normalised.
#include "base/Result.h"
#include "model/Mesh.h"
#include "skin/SkinBones.h"

#include <string>

namespace rs::skin {

// `label` names the mesh in notes. Fails only when there is no bone.
Result<model::MeshWeights> retargetWeights(const model::MeshWeights& weights, const std::vector<SkinBone>& bones,
                                           const std::string& label);

} // namespace rs::skin
