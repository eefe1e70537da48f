#include "eval/AimSolver.h"

#include <algorithm>
#include <glm/gtc/constants.hpp>
#include <cmath>

namespace rs::eval {

namespace {

// The aimed frame of the driven (rest offset applied), keeping its scale and place.
Affine aimed(const CompiledConstraint& c, const Affine& driven, const std::vector<Affine>& world)
{
    const Vec3 origin = driven.translation;
    const Vec3 aim = world[c.targets[0]].translation - origin;
    const Vec3 up = c.targets.size() > 1 ? world[c.targets[1]].translation - origin : Vec3(0, 1, 0);
    // Frame with the aim axis on `aim` and the up axis towards `up`, then the rest offset.
    const Vec3 x = glm::normalize(aim);
    Vec3 y = up - x * glm::dot(up, x);
    y = glm::length(y) < 1e-12 ? glm::normalize(glm::cross(x, Vec3(0, 0, 1))) : glm::normalize(y);
    Mat3 frame;
    frame[c.aimAxis] = x;
    frame[c.upAxis] = y;
    const int third = 3 - c.aimAxis - c.upAxis;
    const bool cyclic = (c.upAxis == (c.aimAxis + 1) % 3);
    frame[third] = cyclic ? glm::cross(x, y) : glm::cross(y, x);
    return compose(frame * c.offsets[0].linear, driven.scale(), origin);
}

} // namespace

std::string prepareAim(CompiledConstraint& c, const std::vector<Affine>& rest)
{
    if (c.targets.empty()) return "needs an aim target";
    if (c.aimAxis == c.upAxis || c.aimAxis < 0 || c.aimAxis > 2 || c.upAxis < 0 || c.upAxis > 2)
        return "aim and up axes must be two different axes of x, y, z";
    c.offsets.resize(1);
    CompiledConstraint probe = c; // the aim frame at rest, to keep the driven's rest orientation
    probe.offsets[0] = Affine{};
    probe.weightChannel = -1;
    std::vector<Affine> world = rest;
    solveAim(probe, {}, world);
    c.offsets[0].linear = glm::transpose(world[c.driven.front()].rotation()) * rest[c.driven.front()].rotation();
    return {};
}

void solveAim(const CompiledConstraint& c, const Pose& pose, std::vector<Affine>& world)
{
    Affine& driven = world[c.driven.front()];
    if (glm::length(world[c.targets[0]].translation - driven.translation) < 1e-12)
        return;
    const double weight = c.weightChannel >= 0 ? std::clamp(pose[c.weightChannel], 0.0, 1.0) : 1.0;
    if (weight <= 0.0)
        return;
    const Affine full = aimed(c, driven, world);
    if (weight >= 1.0) {
        driven = full;
        return;
    }
    // The turn from the parent's rotation to the aimed one, split into the
    // swing that takes the driven's aim direction onto the target and a twist
    // about the target's direction, `weight` of each: the aim direction
    // travels `weight` of its angle towards the target. Both frames have the
    // same handedness (a reflected branch frame included), so the turn is a
    // proper rotation.
    const Mat3 from = driven.rotation();
    const Vec3 localAim = glm::transpose(c.offsets[0].linear)[c.aimAxis]; // the driven's axis that aims
    const Vec3 before = glm::normalize(from * localAim);
    const Vec3 after = glm::normalize(world[c.targets[0]].translation - driven.translation);
    const Quat swing = shortestArc(before, after);
    Quat twist = glm::quat_cast(full.rotation() * glm::transpose(from)) * glm::conjugate(swing); // about `after`
    if (twist.w < 0.0)
        twist = -twist;
    const double twistAngle = 2.0 * std::atan2(glm::dot(Vec3(twist.x, twist.y, twist.z), after), twist.w);
    const Quat partSwing = glm::slerp(Quat(1, 0, 0, 0), swing, weight);
    const Quat part = glm::angleAxis(weight * twistAngle, partSwing * before) * partSwing;
    driven = compose(glm::mat3_cast(part) * from, driven.scale(), driven.translation);
}

// The shortest arc (Solvers.h); the aim's swing and the twist solver share it.
Quat shortestArc(const Vec3& from, const Vec3& to)
{
    const double d = glm::dot(from, to);
    if (d < -1.0 + 1e-12) {
        Vec3 axis = glm::cross(Vec3(1, 0, 0), from);
        if (glm::length(axis) < 1e-6) axis = glm::cross(Vec3(0, 1, 0), from);
        return glm::angleAxis(glm::pi<double>(), glm::normalize(axis));
    }
    const Vec3 axis = glm::cross(from, to);
    return glm::normalize(Quat(1.0 + d, axis.x, axis.y, axis.z));
}

} // namespace rs::eval
