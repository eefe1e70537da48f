#pragma once
// Non-rational B-spline curves as Maya and the shape library store them: a
// degree, control points (CVs) and whether the curve is closed (periodic).
// Periodic curves use uniform knots over the CVs wrapped by `degree`; open
// curves of degree > 1 use clamped uniform knots. Shared by the shape library
// (sampling a shape) and the controller curves of a built rig (re-sampling a
// shape after its CVs were edited).
#include "base/Math.h"

#include <vector>

namespace rs {

// Samples the curve into a polyline, `samplesPerSpan` points a knot span; a
// periodic result repeats its first point at the end. Degree 1 returns the
// CVs themselves (closed when periodic).
std::vector<Vec3> evaluateNurbs(const std::vector<Vec3>& cvs, int degree, bool periodic, int samplesPerSpan = 8);

} // namespace rs
