#pragma once
// The reverse lock of a limb's IK control (Mikan's `reverse_lock`): a chain of
// pivot groups under the IK control that the limb's end follows, turned by
// attributes on the IK control. Legs have it by default (the reverse foot);
// arms have it when the option is on (a hand planted on the ground: crawling,
// hand-walking). Pivots, from the IK control down: heel, toe, outer bank,
// inner bank, ball; the end (ankle, wrist) hangs under the ball.
//
// Attributes on the IK control (degrees): `roll` (below 0 on the heel; above,
// about the ball up to `roll_break`, then about the toe), `bank` (onto the
// outer edge above 0, the inner below), `heel_twist`, `toe_twist` (about the
// up axis at those pivots), and for legs `toe_tap` (the toes about the ball).
// Everything is in authored space, so a mirrored branch gets the mirror image.
#include "rigging/BuildContext.h"

namespace rs::rigging::limb {

// Where the pivots are, in authored space, and the frame they turn in: X
// `forward` (heel to toe), Y `up` (away from the ground), both unit and
// perpendicular.
struct ReversePivots {
    Vec3 end, heel, ball, toe, bankInt, bankExt;
    Vec3 forward, up;
    model::JointId endJoint = model::kNoId, ballJoint = model::kNoId, toeJoint = model::kNoId;
    bool hand = false; // names the groups for a hand (hand_heel, fingertips, knuckles, wrist); tags stay the foot's
};

// A leg's pivots: heel, bank_int and bank_ext from the guides tagged so (a
// missing tag is warned and placed from the foot), the toe on the ground
// under the toe guide; forward along the ground, up world +Y. `normal` is the
// leg's bend normal (the outer side for fallback banks).
ReversePivots footPivots(const BuildContext& ctx, const Vec3& ankle, const Vec3& ball, const Vec3& toe, const Vec3& normal,
                         model::JointId ankleJoint, model::JointId ballJoint, model::JointId toeJoint);
// An arm's pivots: the heel at the wrist, the ball at the hand tip (the
// knuckles), the toe (fingertips) one hand length beyond it; up is the back of
// the hand (the side opposite the arm's bend normal `normal`), the banks a
// hand width apart across the hand, the outer one on the pole's side (the
// little finger's, as the elbow's). Guides tagged heel, bank_int or bank_ext
// under the arm place those pivots instead.
ReversePivots handPivots(const BuildContext& ctx, const Vec3& wrist, const Vec3& tip, const Vec3& normal,
                         const Vec3& poleDirection, model::JointId wristJoint, model::JointId tipJoint);

struct ReverseLock {
    model::RigNodeIndex effector = model::kNoNode; // what the IK solves the end to ("rfoot.ankle")
    model::RigNodeIndex toeTap = model::kNoNode;   // legs: what the IK ball joint turns with ("rfoot.toe_tap")
};
// The pivot groups ("rfoot.*") and their drives under `ikControl`, and the
// attributes on it; `toeTap` adds the toe tap pivot and attribute (legs).
ReverseLock addReverseLock(BuildContext& ctx, const ReversePivots& p, model::RigNodeIndex ikControl, bool toeTap);

// Whether the limb gets its reverse lock: legs unless `reverse_lock` is off
// (a leg template without the option keeps its foot), arms when it is on.
bool hasReverseLock(const BuildContext& ctx, bool leg);

} // namespace rs::rigging::limb
