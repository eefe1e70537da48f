#pragma once
// Unity's humanoid bones on a rig built from the bundled templates, found by
// what survives a rename: the template that built an instance (spine.torso,
// neck.head, arm.limb, leg.limb, digit.finger), the side of its copy (the
// branch "L"/"R", or for an unbranched copy the sign of its guide root's x:
// +x is the character's left) and the node's tag ("skin.limb.0"). Each bone
// resolves to a typed NodeKey through the guide's instances, so renaming the
// biped's `spine` to `torso` maps it the same. When a template has several
// instances, the first in document order takes the bone. A side's thumb is
// its digit.finger with `thumb: on`, or else its first digit.finger (hands are
// authored thumb first); its other fingers are Index, Middle, Ring and Little
// in document order.
#include "io/NameMap.h"
#include "model/GuideDocument.h"
#include "model/Rig.h"

#include <optional>
#include <string>
#include <vector>

namespace rs::io {

struct HumanoidBone {
    std::string bone;              // Unity's name: "Hips", "LeftUpperArm"...
    std::optional<NodeKey> node;   // the rig node it names; none when the guide has no such instance
    std::string wanted;            // what it looks for, for people: "arm.L::skin.limb.0" or "left arm.limb instance"
};

// Every humanoid bone Rigsmith maps (Hips, Spine, Chest, UpperChest, Neck,
// Head, shoulders, arms, legs, toes, three phalanges of each finger), resolved
// on `guide` and the copies `rig` built of its instances.
std::vector<HumanoidBone> unityHumanoidBones(const model::GuideDocument& guide, const model::Rig& rig);
// The resolved bones as a name map (NameMap::byKey).
NameMap unityHumanoidMap(const model::GuideDocument& guide, const model::Rig& rig);

} // namespace rs::io
