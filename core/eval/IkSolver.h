#pragma once
// Internal to rs::eval: the limb IK solver. Two segments: the analytic
// two-bone solution in the plane of the root, the effector and the pole, with
// soft IK (the reach eases towards full extension instead of snapping) and
// stretch (segments lengthen beyond reach, blended by the stretch channel).
// Three segments (quadruped hind legs): the two-bone solution on a virtual
// bone from joint 1 to the end, joint 2 kept in that bone's rest frame, so
// the end still lands on the effector. The last joint takes the effector's
// rotation (rest offset kept). A pin pulls the middle joint onto a third
// target; volume scales stretched bones across (model::IkConstraint).
#include "eval/Solvers.h"

namespace rs::eval {

std::string prepareIk(CompiledConstraint& c, const std::vector<Affine>& rest);
void solveIk(const CompiledConstraint& c, const Pose& pose, std::vector<Affine>& world);

// Soft IK: the distance the chain actually reaches for a target at `distance`
// when fully extended at `reach`, with the last `softness` of the reach eased.
double softReach(double distance, double reach, double softness);

} // namespace rs::eval
