#pragma once
// The moving parts of an export (internal to io/ExportScene.cpp): the current
// pose on the scene's nodes and the range-of-motion clip(s), sampled from the
// evaluator at the keys io/RangeOfMotion.h plans. Tracks say which channels
// change (ExportTrack::animated / held); tracks that change nothing are left
// out of the clip. Where a node turns more than 120 degrees between two keys
// the rig is sampled again in between (on even frames), so that slerp, nlerp
// and Euler-curve players (three.js, Blender, Assimp, FBX importers) all play
// the same motion between keys.
#include "eval/RigProgram.h"
#include "io/ExportCamera.h"
#include "io/ExportScene.h"

#include <vector>

namespace rs::io {

// The rig nodes the scene's joints, controllers and cameras are (kNoNode: a joint the preset added).
struct SceneNodes {
    std::vector<model::RigNodeIndex> joints, controllers;
    CameraNodes cameras;
};

// Puts the rig's default values (or options.pose) on the nodes and adds the
// range of motion (options.rangeOfMotion);
// false when cancelled through options.progress.
bool addMotion(const model::Rig& rig, const ExportOptions& options, const eval::RigProgram& program, const SceneNodes& nodes,
               ExportScene& scene);

} // namespace rs::io
