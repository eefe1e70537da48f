#pragma once
// How the FBX writer turns sampled rotations into Euler curves (public for
// tests). FBX animates `Lcl Rotation` as three Euler curves in degrees, in the
// node's RotationOrder (we always write the default, eEulerXYZ: X applied
// first, R = Rz * Ry * Rx). Importers interpolate those values, so a jump of
// 350 degrees between keys spins the long way: the curves are made continuous.
#include "base/Math.h"

#include <vector>

namespace rs::io {

// Degrees (x, y, z) with R = Rz(z) * Ry(y) * Rx(x); y in [-90, 90], x and z in
// (-180, 180]. At y = +-90 degrees z is 0.
Vec3 eulerXyzDegrees(const Quat& rotation);

// The rotations as XYZ Euler angles in degrees, each key the equivalent
// triple (whole turns per channel, or the (x+180, 180-y, z+180) twin) nearest
// the previous one, the first nearest `startDegrees` (the node's own Lcl
// Rotation). No channel steps by more than 180 degrees between keys, and
// every key still gives exactly its quaternion's rotation.
std::vector<Vec3> continuousEulerDegrees(const std::vector<Quat>& rotations, const Vec3& startDegrees);

} // namespace rs::io
