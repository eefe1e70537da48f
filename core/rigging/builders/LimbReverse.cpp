#include "rigging/builders/LimbReverse.h"

#include "rigging/builders/BuilderKit.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace rs::rigging::limb {

using model::AttributeRef;
using model::RigNodeIndex;
using model::RigNodeKind;

namespace {

// The first guide tagged `tag`, if any (more than one is warned).
std::optional<Vec3> taggedPivot(const BuildContext& ctx, const char* tag)
{
    const auto joints = ctx.taggedJoints(tag);
    if (joints.empty())
        return std::nullopt;
    if (joints.size() > 1)
        ctx.warning(std::to_string(joints.size()) + " guides are tagged '" + tag + "'; using the first");
    return ctx.guidePosition(joints.front());
}

} // namespace

ReversePivots footPivots(const BuildContext& ctx, const Vec3& ankle, const Vec3& ball, const Vec3& toe, const Vec3& normal,
                         model::JointId ankleJoint, model::JointId ballJoint, model::JointId toeJoint)
{
    const double ground = std::min(toe.y, ball.y);
    // Forward along the ground, side = the leg's bend axis flattened.
    Vec3 forward = toe - ankle;
    forward.y = 0.0;
    // Untagged pivots sit by shares of the foot's length (ankle to toe, along the ground; straight when the toe is
    // under the ankle), so they scale with the character: 5 and 4 cm on a 19 cm foot.
    const double footLength = glm::length(forward) > 1e-9 ? glm::length(forward) : glm::length(toe - ankle);
    if (glm::length(forward) < 1e-6)
        forward = Vec3(0.0, 0.0, 1.0);
    forward = glm::normalize(forward);
    Vec3 side = glm::cross(Vec3(0.0, 1.0, 0.0), forward);
    if (glm::dot(side, normal) < 0.0)
        side = -side;

    auto pivot = [&](const char* tag, Vec3 fallback) {
        if (auto tagged = taggedPivot(ctx, tag))
            return *tagged;
        ctx.warning(std::string("no guide is tagged '") + tag + "'; the " + tag +
                    " pivot is placed from the foot (add a guide with tag '" + tag + "' under the ankle)");
        return fallback;
    };
    ReversePivots p;
    p.end = ankle;
    p.ball = ball;
    p.toe = Vec3(toe.x, ground, toe.z);
    p.heel = pivot("heel", Vec3(ankle.x, ground, ankle.z) - forward * (0.26 * footLength));
    p.bankInt = pivot("bank_int", Vec3(ball.x, ground, ball.z) - side * (0.21 * footLength));
    p.bankExt = pivot("bank_ext", Vec3(ball.x, ground, ball.z) + side * (0.21 * footLength));
    p.forward = forward;
    p.up = Vec3(0.0, 1.0, 0.0);
    p.endJoint = ankleJoint;
    p.ballJoint = ballJoint;
    p.toeJoint = toeJoint;
    return p;
}

ReversePivots handPivots(const BuildContext& ctx, const Vec3& wrist, const Vec3& tip, const Vec3& normal,
                         const Vec3& poleDirection, model::JointId wristJoint, model::JointId tipJoint)
{
    ReversePivots p;
    const double length = std::max(glm::length(tip - wrist), 1e-3);
    p.forward = glm::length(tip - wrist) > 1e-9 ? glm::normalize(tip - wrist) : Vec3(1.0, 0.0, 0.0);
    // The back of the hand: across the bend plane, away from its normal (the
    // palm faces the way the arm bends, as a hand planted in front of a crawler).
    Vec3 up = -normal - p.forward * glm::dot(-normal, p.forward);
    if (glm::length(up) < 1e-6) // the hand along the bend normal: any side will do
        up = glm::cross(p.forward, std::abs(p.forward.y) < 0.9 ? Vec3(0.0, 1.0, 0.0) : Vec3(1.0, 0.0, 0.0));
    p.up = glm::normalize(up);
    Vec3 outer = glm::cross(p.forward, p.up); // across the hand
    if (glm::dot(outer, poleDirection) < 0.0)
        outer = -outer;
    p.end = wrist;
    p.ball = tip;
    p.toe = tip + p.forward * length;
    p.heel = taggedPivot(ctx, "heel").value_or(wrist);
    p.bankInt = taggedPivot(ctx, "bank_int").value_or(tip - outer * (0.4 * length));
    p.bankExt = taggedPivot(ctx, "bank_ext").value_or(tip + outer * (0.4 * length));
    p.endJoint = wristJoint;
    p.ballJoint = tipJoint;
    p.toeJoint = tipJoint;
    p.hand = true;
    return p;
}

ReverseLock addReverseLock(BuildContext& ctx, const ReversePivots& p, RigNodeIndex ikCtrl, bool withToeTap)
{
    // Pivot frames: X forward, Y up, Z = X x Y; a positive turn about Z lifts the
    // toes, about X tilts the foot towards Z. Roll lifts the heel (negative about
    // Z), a negative roll rocks back on the heel; bank rolls onto the outer edge.
    const Vec3 lateral = glm::normalize(glm::cross(p.forward, p.up));
    auto frameAt = [&](const Vec3& at) { return kit::aimFrame(at, p.forward, lateral); };
    const AttributeRef roll = ctx.addAttribute(ikCtrl, "roll", 0.0, -90.0, 90.0);
    const AttributeRef rollBreak = ctx.addAttribute(ikCtrl, "roll_break", 30.0, 0.0, 90.0);
    const AttributeRef bank = ctx.addAttribute(ikCtrl, "bank", 0.0, -90.0, 90.0);
    const AttributeRef heelTwist = ctx.addAttribute(ikCtrl, "heel_twist", 0.0, -90.0, 90.0);
    const AttributeRef toeTwist = ctx.addAttribute(ikCtrl, "toe_twist", 0.0, -90.0, 90.0);
    std::optional<AttributeRef> tap;
    if (withToeTap)
        tap = ctx.addAttribute(ikCtrl, "toe_tap", 0.0, -90.0, 90.0);

    auto token = [&](const std::string& key) -> std::string {
        if (!p.hand)
            return key;
        if (key == "heel") return "hand_heel";
        if (key == "toe") return "fingertips";
        if (key == "ball") return "knuckles";
        if (key == "ankle") return "wrist";
        return key;
    };
    auto group = [&](const std::string& key, RigNodeIndex parent, const Vec3& at, model::JointId source) {
        return kit::addSetup(ctx, RigNodeKind::Group, "rfoot." + key, token(key), {}, parent, frameAt(at), source);
    };
    using model::DriveOutput;
    auto drive = [&](const std::string& key, RigNodeIndex node, const AttributeRef& value, DriveOutput output, double factor,
                     model::DriveResponse response) {
        ctx.addConstraint("cns.rfoot." + key, {node}, {},
                          model::DriveConstraint{.value = value, .output = output, .factor = factor, .response = response});
    };
    auto range = [](double low, double high) { return model::DriveClamped{.low = low, .high = high}; };
    ReverseLock out;
    const auto heelNode = group("heel", ikCtrl, p.heel, p.endJoint);
    const auto toeNode = group("toe", heelNode, p.toe, p.toeJoint);
    const auto extNode = group("bank_ext", toeNode, p.bankExt, p.endJoint);
    const auto intNode = group("bank_int", extNode, p.bankInt, p.endJoint);
    const auto ballNode = group("ball", intNode, p.ball, p.ballJoint);
    if (withToeTap)
        out.toeTap = group("toe_tap", intNode, p.ball, p.ballJoint);
    out.effector = kit::addSetup(ctx, RigNodeKind::Group, "rfoot.ankle", token("ankle"), {}, ballNode, frameAt(p.end), p.endJoint);

    drive("heel_roll", heelNode, roll, DriveOutput::RotateZ, -1.0, range(-90.0, 0.0));
    drive("heel_twist", heelNode, heelTwist, DriveOutput::RotateY, 1.0, range(-90.0, 90.0));
    drive("toe_roll", toeNode, roll, DriveOutput::RotateZ, -1.0, model::DrivePastBreak{.breakAngle = rollBreak});
    drive("toe_twist", toeNode, toeTwist, DriveOutput::RotateY, 1.0, range(-90.0, 90.0));
    const double outward = glm::dot(lateral, p.bankExt - p.bankInt) >= 0.0 ? 1.0 : -1.0;
    drive("bank_ext", extNode, bank, DriveOutput::RotateX, outward, range(0.0, 90.0));
    drive("bank_int", intNode, bank, DriveOutput::RotateX, outward, range(-90.0, 0.0));
    drive("ball_roll", ballNode, roll, DriveOutput::RotateZ, -1.0, model::DriveUpToBreak{.breakAngle = rollBreak});
    if (withToeTap)
        drive("toe_tap", out.toeTap, *tap, DriveOutput::RotateZ, 1.0, range(-90.0, 90.0));
    return out;
}

bool hasReverseLock(const BuildContext& ctx, bool leg)
{
    const Value& v = ctx.option("reverse_lock");
    if (leg) // on unless the manifest says otherwise
        return !std::holds_alternative<bool>(v) || std::get<bool>(v);
    return std::holds_alternative<bool>(v) && std::get<bool>(v);
}

} // namespace rs::rigging::limb
