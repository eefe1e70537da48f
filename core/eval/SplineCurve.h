#pragma once
// Internal to rs::eval: the spline IK solver for spines, necks and tails. The
// control targets define a piecewise cubic Hermite curve (tangents along each
// control's rest chain direction, scaled by the chord); its frame at a
// parameter slerps the controls' rotations and turns them onto the curve
// tangent. Each driven joint keeps its rest parameter and its rest offset from
// the curve frame; without stretch it keeps its rest arc length instead (the
// chain slides along the curve), and the stretch channel blends the two. The
// slide channel moves every joint along the curve by metres of arc (rig.slide).
// The rigidity channels loosen the end tangents towards the chords; with
// stretch by scale the joints also grow along their bones.
#include "eval/Solvers.h"

namespace rs::eval {

std::string prepareSpline(CompiledConstraint& c, const std::vector<Affine>& rest);
void solveSpline(const CompiledConstraint& c, const Pose& pose, EvalState& state);

} // namespace rs::eval
