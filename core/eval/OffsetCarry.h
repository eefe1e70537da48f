#pragma once
// Internal to rs::eval: a controller's channel transform (how RigProgram
// places a node: parent world * rest local * this) and the carry step
// (model::CarryConstraint: a node moved by other nodes' animated offsets,
// each about its pivot, as an FK chain's links carry the links after them).
#include "eval/Solvers.h"

namespace rs::eval {

// The transform of the channels at `first` (tx ty tz rx ry rz sx sy sz, then
// the rotate order): scale, then rotation in its order, then translation.
inline Affine channelAffine(const Pose& pose, int first)
{
    const double* v = pose.data() + first;
    Mat3 r(1.0);
    if (v[3] != 0.0 || v[4] != 0.0 || v[5] != 0.0) // most controls are not rotated: skip the trigonometry
        r = eulerRotation({v[3], v[4], v[5]}, rotateOrderOf(pose, first));
    return {Mat3(r[0] * v[6], r[1] * v[7], r[2] * v[8]), Vec3(v[0], v[1], v[2])};
}

// Resolves each carried node to its transform channels into `c`; false, with
// an error naming the constraint and the node, for one without them or when
// the carried nodes are not one per target.
bool readCarry(const model::CarryConstraint& settings, const model::RigConstraint& rc, const model::Rig& rig,
               const ChannelLayout& channels, CompiledConstraint& c, Diagnostics& diagnostics);
// Each carried node's rest offset from its pivot; an error message when a
// pivot's rest transform cannot be inverted.
std::string prepareCarry(CompiledConstraint& c, const std::vector<Affine>& rest);
void solveCarry(const CompiledConstraint& c, const Pose& pose, std::vector<Affine>& world);

} // namespace rs::eval
