#pragma once
// Export name maps: the names engines see for skeleton joints, when they differ
// from the rig's (Unity's humanoid mapping, a studio's conventions). A map is
// keyed by rig node id ("arm.L::skin.limb.0", identity that survives renames)
// or by node name ("sk_arm1_L"); ids win. YAML file:
//
//   rigsmith_names: 1
//   names:
//     "spine::skin.0": Hips
//     sk_arm1_L: LeftUpperArm
//
// The export validator checks the mapped names like any other.
#include "base/Result.h"
#include "model/Skeleton.h"

#include <map>
#include <string>

namespace rs::io {

struct NameMap {
    std::map<std::string, std::string> names; // node id or node name -> export name
};

// Errors carry file:line:col; an entry that is not text is reported and skipped.
Result<NameMap> readNameMap(const std::string& path);
Result<NameMap> readNameMapText(const std::string& text, const std::string& displayName);
// Unity humanoid names for the bundled biped's instances (world, spine, neck,
// arm/leg L/R, thumb/index/middle/ring/pinky L/R): Hips, Spine, Chest,
// UpperChest, Neck, Head, LeftShoulder, LeftUpperArm... Guides that name
// their instances otherwise use a YAML map.
NameMap unityHumanoidMap();
model::Skeleton applyNameMap(const model::Rig& rig, model::Skeleton skeleton, const NameMap& map);

} // namespace rs::io
