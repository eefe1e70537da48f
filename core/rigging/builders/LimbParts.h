#pragma once
// Parts of the limb builder (LimbBuilder.cpp) an animator judges a limb by,
// each driven by a template option (templates/arm/limb, leg/limb, quad/leg):
// where the IK control is oriented (`ik_orient`), how the end joint is
// oriented (`effector_plane`), what the pole follows (`pv_space`), what the
// FK chain takes its orientation from (`fk_space`), whether the IK, pole and
// FK controls get space switches (`space_switch`), whether a leg has its
// reverse foot (`reverse_lock`), which of the FK and IK controls are shown for the blend
// (`ik_fk_visibility`) and how the upper segment's twist is shared
// (`non_rolling`, `twist_upper`, `twist_lower`). Everything is in authored
// space (BuildContext), so a mirrored branch gets the mirror image.
#include "rigging/BuildContext.h"

#include <optional>
#include <vector>

namespace rs::rigging::limb {

// The IK control's rest frame at `position` (the wrist or ankle) for the
// option `ik_orient`: `world` axis-aligned; `joint` the end joint's frame
// `jointFrame`; `copy` the orientation the rigger gave the end's guide joint.
Mat4 ikControlFrame(const BuildContext& ctx, const Vec3& position, const Mat4& jointFrame, model::JointId endGuide);

// The frames of the limb's end joint (wrist, ankle: frames[k - 1]) and the
// joint after it (hand tip, ball: frames[k]) for the option `effector_plane`
// (Mikan's): `auto` keeps `frames` (the limb's bend plane carried on); `x`,
// `y`, `z` keep each one's aim (X) and turn its Y towards that authored-space
// axis; `ground` levels them: X the aim flattened onto the ground, Y straight
// up. An axis along the aim (or a vertical aim for `ground`) keeps `auto` with
// a warning. ik_orient `joint` then orients the IK control the same way.
std::vector<Mat4> orientEffector(const BuildContext& ctx, std::vector<Mat4> frames, std::size_t k);

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

// FK orientation isolation (`fk_space`): the group "spaces.fk" under
// `limbGroup` at the first FK control's rest `frame`, which that control
// hangs under. Returns it (the FK chain's parent).
model::RigNodeIndex addFkSpaceGroup(BuildContext& ctx, model::RigNodeIndex limbGroup, const Mat4& frame, model::JointId source);
// The spaces `fk_space` offers: "parent" (what the limb hangs from: the
// clavicle or pelvis, else the hook), then the rig's named spaces.
const std::vector<std::string>& fkSpaces(bool leg);
// Made in configure(): the space switches of the limb's IK control (`ik_space`
// over `ikSpaces`, entry 0 the IK space group's parent), pole (`pv_space`) and
// first FK control (`fk_space`, orient only: the FK chain keeps its place on
// the clavicle or pelvis and takes its orientation from the space). Each is a
// "space" enum on the control, offering only the spaces this rig has (the others
// left out; kit::addSpaceSwitch). With `space_switch` off none gets a switch: each
// follows the space its option names, fixed (nothing when that is its parent).
void addSpaceSwitches(BuildContext& ctx, const std::vector<std::string>& ikSpaces, bool leg);

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
// their segment's bendy curve, spaced by `smooth_type`. `bias` (advanced_twist,
// LimbTwist.h) shapes every twist joint's share (model::TwistConstraint::bias).
struct TwistJoints {
    // Per segment (0 upper, 1 lower): the twist joints from the start, and
    // the fraction of the segment each sits at.
    std::vector<model::RigNodeIndex> joints[2];
    std::vector<double> fractions[2];
};
TwistJoints addTwistJoints(BuildContext& ctx, const std::vector<Vec3>& points, const std::vector<Mat4>& frames,
                           const std::vector<model::JointId>& guides, const std::vector<model::RigNodeIndex>& blend,
                           const std::vector<model::RigNodeIndex>& skin, model::RigNodeIndex limbRoot,
                           const std::vector<std::vector<model::RigNodeIndex>>& bendCurves = {},
                           const std::optional<model::AttributeRef>& bias = {});

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
