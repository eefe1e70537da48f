// The constraint solvers. Every solver reproduces the rest pose exactly at the
// default channels: offsets, bone frames and curve parameters are measured on
// the rest pose at compile time and re-applied at evaluation.
#include "eval/Solvers.h"

#include "eval/AimSolver.h"
#include "eval/BendyCurve.h"
#include "eval/DrivenKeys.h"

#include "eval/IkSolver.h"
#include "eval/OffsetCarry.h"
#include "eval/RigProgram.h"
#include "eval/SplineCurve.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/constants.hpp>

namespace rs::eval {

namespace {

using model::ConstraintKind;

// Weighted average of rotations (normalised linear blend, signs aligned to the first).
Quat averageRotation(const Quat* rotations, const double* weights, std::size_t count)
{
    if (count == 2)
        return glm::slerp(rotations[0], rotations[1], weights[1]);
    Quat sum(0, 0, 0, 0);
    for (std::size_t k = 0; k < count; ++k) {
        const Quat q = glm::dot(rotations[k], rotations[0]) < 0.0 ? -rotations[k] : rotations[k];
        sum = sum + q * weights[k];
    }
    return glm::normalize(sum);
}

constexpr std::size_t kMaxTargets = 16;

// A target's world with the constraint's rest offset applied (most offsets are
// the identity: FK controls and IK joints sit where the blend joints do).
Affine placed(const CompiledConstraint& c, const std::vector<Affine>& world, std::size_t k)
{
    return c.identityOffset[k] ? world[c.targets[k]] : world[c.targets[k]] * c.offsets[k];
}

void solveBlendLike(const CompiledConstraint& c, std::vector<Affine>& world, bool position, bool rotation, bool scale)
{
    const std::size_t n = std::min(c.targets.size(), kMaxTargets);
    // One target followed whole: its transform with the offset, exactly as a
    // child of it would be (shear under a non-uniformly scaled parent
    // included), which the decomposition below would lose. `isolate_skin`
    // relies on it (rigging/IsolateSkinStage.cpp).
    if (n == 1 && position && rotation && scale) {
        world[c.driven.front()] = placed(c, world, 0);
        return;
    }
    std::array<Quat, kMaxTargets> rotations;
    Vec3 translation(0.0), scales(0.0);
    for (std::size_t k = 0; k < n; ++k) {
        const Affine target = placed(c, world, k);
        rotations[k] = rotationOf(target);
        translation += target.translation * c.weights[k];
        scales += target.scale() * c.weights[k];
    }
    Affine& driven = world[c.driven.front()];
    const Mat3 r = rotation ? glm::mat3_cast(averageRotation(rotations.data(), c.weights.data(), n)) : driven.rotation();
    driven = compose(r, scale ? scales : driven.scale(), position ? translation : driven.translation);
}

void solveFkIkBlend(const CompiledConstraint& c, const Pose& pose, std::vector<Affine>& world)
{
    const double w = c.weightChannel >= 0 ? std::clamp(pose[c.weightChannel], 0.0, 1.0) : 0.5;
    const Affine a = placed(c, world, 0);
    const Affine b = placed(c, world, 1);
    if (w <= 0.0) { world[c.driven.front()] = a; return; }
    if (w >= 1.0) { world[c.driven.front()] = b; return; }
    // Normalised lerp of the two rotations: the same end points and path as a
    // slerp, without its inverse cosine and sines (the blend runs per limb joint).
    const Vec3 sa = a.scale(), sb = b.scale();
    const Quat qa = glm::quat_cast(Mat3(a.linear[0] / sa.x, a.linear[1] / sa.y, a.linear[2] / sa.z));
    Quat qb = glm::quat_cast(Mat3(b.linear[0] / sb.x, b.linear[1] / sb.y, b.linear[2] / sb.z));
    if (glm::dot(qa, qb) < 0.0)
        qb = -qb;
    const Mat3 r = glm::mat3_cast(glm::normalize(qa * (1.0 - w) + qb * w));
    world[c.driven.front()] = compose(r, glm::mix(sa, sb, w), glm::mix(a.translation, b.translation, w));
}

// A twist joint at `fraction` of its segment a -> b turned to `r`, or, bendy,
// on its curve and swung onto the curve's tangent (BendyCurve.h).
void placeTwistJoint(const CompiledConstraint& c, std::vector<Affine>& world, const Affine& a, const Affine& b, Mat3 r)
{
    Vec3 position = glm::mix(a.translation, b.translation, c.fraction);
    if (c.bendy)
        bendJoint(c, world, a.rotation() * c.twistAxis, r, position);
    Affine& driven = world[c.driven.front()];
    driven = compose(r, driven.scale(), position + a.linear * c.restDelta);
}

// The share of the twist a twist joint takes: its fraction, shaped by the
// bias channel when it has one (model::TwistConstraint::bias).
double twistShare(const CompiledConstraint& c, const Pose& pose)
{
    if (c.biasChannel < 0 || c.fraction <= 0.0)
        return c.fraction;
    return std::pow(c.fraction, std::exp2(std::clamp(pose[c.biasChannel], -1.0, 1.0)));
}

// The roll of targets[0] about its bone relative to targets[2], and the
// swing-only frame it is measured from (model::TwistConstraint, non-rolling).
void solveNonRollingTwist(const CompiledConstraint& c, double share, std::vector<Affine>& world)
{
    const Affine& a = world[c.targets[0]];
    const Affine& b = world[c.targets[1]];
    const Quat qr = rotationOf(world[c.targets[2]]);
    const Quat local = glm::conjugate(qr) * rotationOf(a);
    const Vec3 restBone = c.restFromReference * c.twistAxis, bone = local * c.twistAxis;
    const Quat swung = shortestArc(restBone, bone) * c.restFromReference; // the start without its roll
    Quat roll = glm::conjugate(swung) * local;
    if (roll.w < 0.0)
        roll = -roll;
    const double angle = 2.0 * std::atan2(glm::dot(Vec3(roll.x, roll.y, roll.z), c.twistAxis), roll.w);
    Mat3 r = glm::mat3_cast(qr * swung * glm::angleAxis(angle * share, c.twistAxis)) * c.offsets[0].linear;
    placeTwistJoint(c, world, a, b, r);
}

void solveTwist(const CompiledConstraint& c, const Pose& pose, EvalState& state)
{
    std::vector<Affine>& world = state.world;
    if (c.nonRolling) {
        solveNonRollingTwist(c, twistShare(c, pose), world);
        return;
    }
    const Affine& a = world[c.targets[0]];
    const Affine& b = world[c.targets[1]];
    const Mat3 ra = a.rotation();
    const Quat qa = glm::quat_cast(ra);
    double angle;
    if (c.shareTwistOf >= 0) { // twist joints of one segment share the segment's twist
        angle = state.twistAngles[c.shareTwistOf];
    } else {
        // The change of b relative to a since rest, in a's frame (where the
        // twist axis is: b's rest frame may aim elsewhere, as an ankle aims at
        // the ball), then its twist about the bone.
        Quat delta = (glm::conjugate(qa) * rotationOf(b)) * glm::conjugate(c.restRelative);
        if (delta.w < 0.0)
            delta = -delta; // the shorter way round: the twist stays within +-180 degrees
        const double along = glm::dot(Vec3(delta.x, delta.y, delta.z), c.twistAxis);
        angle = 2.0 * std::atan2(along, delta.w);
        state.twistAngles[c.slot] = angle;
    }
    Mat3 r = ra * glm::mat3_cast(glm::angleAxis(angle * twistShare(c, pose), c.twistAxis)) * c.offsets[0].linear;
    placeTwistJoint(c, world, a, b, r);
}

void solveSpace(const CompiledConstraint& c, const Pose& pose, std::vector<Affine>& world)
{
    const int last = int(c.targets.size()) - 1;
    const int k = c.spaceChannel >= 0 ? std::clamp(int(std::lround(pose[c.spaceChannel])), 0, last) : 0;
    const Affine target = placed(c, world, std::size_t(k));
    Affine& driven = world[c.driven.front()];
    driven = c.orientOnly ? compose(target.rotation(), driven.scale(), driven.translation) : target;
}

void solveDrive(const CompiledConstraint& c, const Pose& pose, std::vector<Affine>& world)
{
    const double v = c.valueChannel >= 0 ? pose[c.valueChannel] : 0.0;
    const double breakAt = c.breakChannel >= 0 ? pose[c.breakChannel] : 0.0;
    double amount;
    if (c.driveResponse == 1) amount = c.factor * std::clamp(v, 0.0, std::max(breakAt, 0.0));
    else if (c.driveResponse == 2) amount = c.factor * std::max(v - breakAt, 0.0);
    else amount = c.factor * std::clamp(v, c.low, c.high);
    Affine& driven = world[c.driven.front()];
    if (c.scaleDrive) {
        driven.linear = driven.linear * amount;
        return;
    }
    if (amount == 0.0)
        return;
    // Right-multiplying by a rotation about local axis k mixes the other two columns.
    const int k = c.axis, a = (k + 1) % 3, b = (k + 2) % 3;
    double sine, cosine;
    sinCosDegrees(amount, sine, cosine);
    const Vec3 columnA = driven.linear[a], columnB = driven.linear[b];
    driven.linear[a] = columnA * cosine + columnB * sine;
    driven.linear[b] = columnB * cosine - columnA * sine;
}

// Right-multiplying by a rotation about local axis k mixes the other two columns.
void turnAbout(Affine& node, int k, double angleRadians)
{
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    const double sine = std::sin(angleRadians), cosine = std::cos(angleRadians);
    const Vec3 columnA = node.linear[a], columnB = node.linear[b];
    node.linear[a] = columnA * cosine + columnB * sine;
    node.linear[b] = columnB * cosine - columnA * sine;
}

// model::RollConstraint, axis mode: the travel from rest along the wheel's
// forward axis, in the reference's frame, turned into a rotation about its axle.
void solveAxisRoll(const CompiledConstraint& c, double amount, std::vector<Affine>& world)
{
    Affine& driven = world[c.driven.front()];
    const Affine toReference = world[c.targets[0]].inverse();
    const Vec3 moved = toReference.apply(driven.translation) - c.restInReference;
    const Vec3 forward = toReference.linear * driven.linear[c.forward];
    const double length = glm::length(forward);
    if (length < 1e-12)
        return;
    const double angle = amount * glm::dot(moved, forward / length) / c.radius;
    if (angle != 0.0)
        turnAbout(driven, c.axle, angle);
}

// Path mode: the step the centre made since the previous evaluation, along
// the rolling direction (the axle crossed with the wheel's rest up in the
// reference: the ground it stands on, be it a floor, a wall or a rail's side;
// signed by the forward axis), added to the roll so far. The step is measured along the
// direction half way between the previous evaluation's and this one's: on a
// turn it is the chord's own direction, so the roll matches the arc's length
// to second order in the step's turn (the current direction alone drifts, at
// every step, by the distance from the pivot times half the step's turn). A wheel
// whose axle turns to stand along that up has no rolling direction: that step rolls nothing.
void solvePathRoll(const CompiledConstraint& c, double amount, EvalState& state)
{
    Affine& driven = state.world[c.driven.front()];
    const Affine toReference = state.world[c.targets[0]].inverse();
    const Vec3 centre = toReference.apply(driven.translation);
    Vec3 rolling = glm::cross(toReference.linear * driven.linear[c.axle], c.upInReference);
    const double length = glm::length(rolling);
    if (length > 1e-9) {
        rolling /= length;
        if (glm::dot(rolling, toReference.linear * driven.linear[c.forward]) < 0.0)
            rolling = -rolling;
    } else {
        rolling = Vec3(0.0);
    }
    RollMemory& memory = state.rolls[std::size_t(c.pathSlot)];
    if (memory.anchored && amount > 0.0 && length > 1e-9) {
        const Vec3 step = centre - memory.centre;
        const Vec3 between = memory.rolling + rolling;
        const double half = glm::length(between);
        if (glm::length(step) <= c.jump)
            memory.angleRadians += amount * glm::dot(step, half > 1e-9 ? between / half : rolling) / c.radius;
    }
    memory.centre = centre;
    memory.rolling = rolling;
    memory.anchored = true;
    if (memory.angleRadians != 0.0)
        turnAbout(driven, c.axle, memory.angleRadians);
}

void solveRoll(const CompiledConstraint& c, const Pose& pose, EvalState& state)
{
    const double amount = c.weightChannel >= 0 ? std::clamp(pose[c.weightChannel], 0.0, 1.0) : 1.0;
    if (c.pathSlot >= 0)
        solvePathRoll(c, amount, state);
    else if (amount != 0.0)
        solveAxisRoll(c, amount, state.world);
}

} // namespace

Quat rotationOf(const Affine& a) { return glm::normalize(glm::quat_cast(a.rotation())); }

Mat3 frameFromAxes(const Vec3& x, const Vec3& normal)
{
    const Vec3 ax = glm::normalize(x);
    Vec3 z = normal - ax * glm::dot(normal, ax);
    z = glm::normalize(z);
    return Mat3(ax, glm::cross(z, ax), z);
}

std::string prepareConstraint(CompiledConstraint& c, const model::Rig& rig, const std::vector<Affine>& rest)
{
    const std::size_t t = c.targets.size();
    c.chainParent = rig.nodes[c.driven.front()].parent;
    if (c.chainParent != model::kNoNode)
    {
        c.restParentScale = rest[c.chainParent].scale().x;
        c.restParentRotation = rest[c.chainParent].rotation();
    }
    switch (c.kind) {
    case ConstraintKind::Parent: case ConstraintKind::Orient: case ConstraintKind::Point: case ConstraintKind::Scale:
        if (c.weights.size() != t)
            return "has " + std::to_string(c.weights.size()) + " weights for " + std::to_string(t) + (t == 1 ? " target" : " targets");
        [[fallthrough]];
    case ConstraintKind::Space:
        if (t == 0) return "needs at least one target";
        if (t > kMaxTargets) return "has more than 16 targets";
        return {};
    case ConstraintKind::Blend:
        return t == 2 ? std::string() : "needs two targets (FK, IK)";
    case ConstraintKind::Aim:
        return prepareAim(c, rest);
    case ConstraintKind::Visibility:
        return t == 0 ? std::string() : "takes no targets";
    case ConstraintKind::Roll:
        if (t != 1) return "needs one target (the reference it travels in)";
        if (c.axle == c.forward || c.axle < 0 || c.axle > 2 || c.forward < 0 || c.forward > 2)
            return "its axle and forward axes must be two different axes of x, y, z";
        if (!(c.radius > 1e-9) || !std::isfinite(c.radius)) return "its radius must be positive";
        if (!(c.jump >= 0.0)) return "its jump distance must not be negative";
        if (c.jump == 0.0) c.jump = glm::two_pi<double>() * c.radius;
        c.restInReference = rest[c.targets[0]].inverse().apply(rest[c.driven.front()].translation);
        c.upInReference = rest[c.targets[0]].inverse().linear * rest[c.driven.front()].linear[3 - c.axle - c.forward];
        if (glm::length(c.upInReference) < 1e-12) return "its rest frame is degenerate";
        c.upInReference = glm::normalize(c.upInReference);
        return {};
    case ConstraintKind::DrivenKey:
        return checkCurveKeys(c.keys);
    case ConstraintKind::Twist: {
        const std::size_t own = c.bendy ? t - std::min<std::size_t>(t, 6) : t; // bendy: six curve targets follow
        if (c.nonRolling && own != 3) return "needs three targets (start, end, reference) to be non-rolling";
        if (!c.nonRolling && own != 2) return "needs two targets (start, end)";
        if (c.bendy)
            if (std::string error = prepareBendy(c, rest); !error.empty())
                return error;
        if (c.nonRolling)
            c.restFromReference = glm::conjugate(rotationOf(rest[c.targets[2]])) * rotationOf(rest[c.targets[0]]);
        const Affine& a = rest[c.targets[0]];
        const Affine& b = rest[c.targets[1]];
        const Affine& d = rest[c.driven.front()];
        c.offsets.resize(1);
        c.restRelative = glm::inverse(rotationOf(a)) * rotationOf(b);
        const Vec3 bone = b.translation - a.translation;
        if (glm::length(bone) < 1e-9) return "its two targets are at the same place";
        c.twistAxis = glm::normalize(glm::transpose(a.rotation()) * bone);
        Vec3 restPlace = glm::mix(a.translation, b.translation, c.fraction);
        if (c.bendy) { // where the curve puts it at rest (the straight segment's point when the bend control is halfway)
            const BendyCurve curve = bendyCurveOf(c, rest);
            Vec3 derivative;
            curve.at(c.byLength ? curve.parameterAtLength(c.fraction) : c.fraction, restPlace, derivative);
        }
        c.restDelta = glm::transpose(a.rotation()) * (d.translation - restPlace) / a.scale().x;
        c.offsets[0].linear = glm::transpose(a.rotation()) * d.rotation();
        return {};
    }
    case ConstraintKind::Drive:
        return c.low <= c.high ? std::string() : "its low limit is above its high limit";
    case ConstraintKind::Ik:
        return prepareIk(c, rest);
    case ConstraintKind::Spline:
        return prepareSpline(c, rest);
    case ConstraintKind::Carry:
        return prepareCarry(c, rest);
    }
    return {};
}

void solveConstraint(const CompiledConstraint& c, const Pose& pose, EvalState& state)
{
    std::vector<Affine>& world = state.world;
    switch (c.kind) {
    case ConstraintKind::Parent: solveBlendLike(c, world, true, true, true); break;
    case ConstraintKind::Orient: solveBlendLike(c, world, false, true, false); break;
    case ConstraintKind::Point: solveBlendLike(c, world, true, false, false); break;
    case ConstraintKind::Scale: solveBlendLike(c, world, false, false, true); break;
    case ConstraintKind::Blend: solveFkIkBlend(c, pose, world); break;
    case ConstraintKind::Aim: solveAim(c, pose, world); break;
    case ConstraintKind::Twist: solveTwist(c, pose, state); break;
    case ConstraintKind::Space: solveSpace(c, pose, world); break;
    case ConstraintKind::Drive: solveDrive(c, pose, world); break;
    case ConstraintKind::Ik: solveIk(c, pose, world); break;
    case ConstraintKind::Spline: solveSpline(c, pose, state); break;
    case ConstraintKind::Roll: solveRoll(c, pose, state); break;
    case ConstraintKind::Carry: solveCarry(c, pose, world); break;
    case ConstraintKind::Visibility: break; // RigProgram::evaluate writes EvalState::visible
    case ConstraintKind::DrivenKey: break;  // RigProgram::evaluate computes the driven channels first
    }
}

} // namespace rs::eval
