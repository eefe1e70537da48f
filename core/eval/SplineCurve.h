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
// restCurvePoints is the one piece builders use: where that curve runs at rest.
#include "eval/Solvers.h"

namespace rs::eval {

std::string prepareSpline(CompiledConstraint& c, const std::vector<Affine>& rest);
void solveSpline(const CompiledConstraint& c, const Pose& pose, EvalState& state);

// Points on the curve a spline constraint draws through `targets` (their
// world transforms at rest, in order, 2 to 16, no two at one place), for a
// builder placing joints on it (rig.spline's bones): `count` (at least 2) from
// the first target to the last, evenly by the curve's parameter or, with
// `byLength`, at equal arc lengths (to about 1e-6 of the curve's length).
// Empty when the targets do not make a curve.
std::vector<Vec3> restCurvePoints(const std::vector<Affine>& targets, int count, bool byLength);

} // namespace rs::eval
