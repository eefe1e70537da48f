#pragma once
// Internal to rs::eval: the aim solver (model::AimConstraint). The driven's
// aim axis points at the first target, its up axis towards the second (else
// world +Y), its rest orientation relative to that frame kept; a weight
// channel below 1 blends by angle from the rotation the parent gave it.
#include "eval/Solvers.h"

namespace rs::eval {

// Checks the axes and measures the rest offset; an error message, empty when usable.
std::string prepareAim(CompiledConstraint& c, const std::vector<Affine>& rest);
void solveAim(const CompiledConstraint& c, const Pose& pose, std::vector<Affine>& world);

} // namespace rs::eval
