#pragma once
// Export name maps: the names engines see for skeleton joints, when they differ
// from the rig's (Unity's humanoid mapping, a studio's conventions). Built-in
// maps (io/HumanoidMap.h) are keyed by typed NodeKey, which survives renames.
// A map file is text: keyed by rig node path ("arm.L::skin.limb.0", the
// instance's current name) or by node name ("sk_arm1_L"); keys win over paths,
// paths over names. YAML file:
//
//   rigsmith_names: 1
//   names:
//     "spine::skin.0": Hips
//     sk_arm1_L: LeftUpperArm
//
// The export validator checks the mapped names like any other.
#include "base/Identity.h"
#include "base/Result.h"
#include "model/Skeleton.h"

#include <map>
#include <string>

namespace rs::io {

struct NameMap {
    std::map<NodeKey, std::string> byKey;     // typed node identity -> export name (built-in maps)
    std::map<std::string, std::string> names; // node path or node name -> export name (map files)

    bool empty() const { return byKey.empty() && names.empty(); }
};

// Errors carry file:line:col; an entry that is not text is reported and skipped.
Result<NameMap> readNameMap(const std::string& path);
Result<NameMap> readNameMapText(const std::string& text, const std::string& displayName);
model::Skeleton applyNameMap(const model::Rig& rig, model::Skeleton skeleton, const NameMap& map);

} // namespace rs::io
