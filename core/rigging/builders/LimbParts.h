#pragma once
// Parts of the limb builder (LimbBuilder.cpp) an animator judges a limb by,
// each driven by a template option (templates/arm/limb, leg/limb, quad/leg):
// where the IK control is oriented (`ik_orient`), what the pole follows
// (`pv_space`), which of the FK and IK controls are shown for the blend
// (`ik_fk_visibility`) and how the upper segment's twist is shared
// (`non_rolling`, `twist_upper`, `twist_lower`). Everything is in authored
// space (BuildContext), so a mirrored branch gets the mirror image.
#include "rigging/BuildContext.h"

#include <vector>

namespace rs::rigging::limb {

// The IK control's rest frame at `position` (the wrist or ankle) for the
// option `ik_orient`: `world` axis-aligned; `joint` the end joint's frame
// `jointFrame`; `copy` the orientation the rigger gave the end's guide joint.
Mat4 ikControlFrame(const BuildContext& ctx, const Vec3& position, const Mat4& jointFrame, model::JointId endGuide);

// The pole's spaces: "follow" (a hidden group halfway between the limb's root
// group and the IK control, turned like the root, so the knee or elbow keeps
// its side when the body travels or turns away from a planted foot or hand,
// and turning the IK control about itself does not swing it), "ik" (the IK
// control alone), then the rig's named spaces "world", "root" and "cog".
const std::vector<std::string>& poleSpaces();
// Made in generate(): the group "spaces.pole" the pole control hangs under and
// the follow group "spaces.pole_follow" constrained to `limbRoot` and `ikControl`.
model::RigNodeIndex addPoleSpaceGroups(BuildContext& ctx, model::RigNodeIndex world, model::RigNodeIndex limbRoot,
                                       model::RigNodeIndex ikControl, const Mat4& poleFrame, model::JointId source);
// Made in configure(), once other instances' spaces exist: the pole's space
// switch ("space" enum on the pole control, default from `pv_space`).
void addPoleSpaceSwitch(BuildContext& ctx);

// With `ik_fk_visibility` on: `fk` controls shown while `blend` < 1 and `ik`
// controls while `blend` > 0 (model::VisibilityConstraint).
void addBlendVisibility(BuildContext& ctx, const model::AttributeRef& blend, const std::vector<model::RigNodeIndex>& fk,
                        const std::vector<model::RigNodeIndex>& ik);

// Twist skin joints: `twist_upper` along blend[0] -> blend[1] and
// `twist_lower` along blend[1] -> blend[2], at (t + 1) / (count + 1) of the
// segment, each turning by that share of the segment's twist. With
// `non_rolling` the upper segment's skin joint `upperSkin` does not roll and
// the upper twist joints share the upper bone's roll relative to `limbRoot`
// linearly (0 at the shoulder or hip, all of it at the elbow or knee).
// `bendCurves` (LimbBendy.h, per segment; empty: straight) makes them ride
// their segment's bendy curve, spaced by `smooth_type`.
void addTwistJoints(BuildContext& ctx, const std::vector<Vec3>& points, const std::vector<Mat4>& frames,
                    const std::vector<model::JointId>& guides, const std::vector<model::RigNodeIndex>& blend,
                    const std::vector<model::RigNodeIndex>& skin, model::RigNodeIndex limbRoot,
                    const std::vector<std::vector<model::RigNodeIndex>>& bendCurves = {});

// Auto-clavicle (arms): hidden groups under `hook` at the clavicle's frame.
// `follow` (what the clavicle control hangs under) turns towards `aim` (aimed
// at the IK control) by the clavicle's `auto_clavicle` share times the
// limb's ik_blend, so it follows the IK arm's raise and stays put in FK.
struct AutoClavicle {
    model::RigNodeIndex rest = model::kNoNode, aim = model::kNoNode, share = model::kNoNode, follow = model::kNoNode;
};
// Made before the clavicle control: the groups (none when the option
// `auto_clavicle` is absent or the instance has no controllers).
AutoClavicle addAutoClavicleGroups(BuildContext& ctx, model::RigNodeIndex hook, const Vec3& clavicle, const Vec3& shoulder,
                                   const Vec3& hand, model::JointId source);
// Made once the IK control and the blend exist: the `auto_clavicle` channel on
// `clavicle` and the aim and blends.
void connectAutoClavicle(BuildContext& ctx, const AutoClavicle& groups, model::RigNodeIndex clavicle, model::RigNodeIndex ikControl,
                         const model::AttributeRef& ikBlend);

// Pin (option `pin`): a control at the middle joint (elbow, knee) in the
// pole's space; the IK's pin channel (on `settings`, 0 by default) locks the
// middle joint to it. Returns kNoNode when the option is off.
model::RigNodeIndex addPinControl(BuildContext& ctx, model::RigNodeIndex poleSpace, const Vec3& mid, model::JointId source);

} // namespace rs::rigging::limb
