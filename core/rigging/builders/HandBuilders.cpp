// digit.finger and digit.hand. A finger hung on a hand's master control takes
// the hand's fist, curl, spread and cup attributes: the master drives every
// finger of the hand without knowing how many there are. A finger's aim rig
// (target_weights) is DigitAim.h's.
#include "rigging/builders/Builders.h"

#include "rigging/builders/BuilderKit.h"
#include "rigging/builders/ChainOrient.h"
#include "rigging/builders/ControlNodes.h"
#include "rigging/builders/DigitAim.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace rs::rigging {

namespace {

using model::DriveClamped;
using model::DriveConstraint;
using model::DriveOutput;
using model::JointId;
using model::RigNodeIndex;

// The hand master's attributes and their ranges (degrees but `fist`, a 0..1 share).
struct HandAttribute {
    const char* name;
    double low, high;
};
constexpr HandAttribute kHandAttributes[] = {{"fist", 0.0, 1.0}, {"curl", -30.0, 120.0}, {"spread", -30.0, 45.0}, {"cup", -10.0, 60.0}};

// The Z axis of a chain's root guide: the bend axis used where the chain is straight.
Vec3 rootNormal(const BuildContext& ctx, JointId root) { return kit::guideAxis(ctx, root, 2, Vec3(0.0, 0.0, 1.0)); }

// The default `orient`: each phalanx aims X at the next guide joint with Z on
// the finger's bend normal (the root guide's Z where it is straight).
bool chainOrient(const BuildContext& ctx)
{
    return !ctx.manifest().findOpt("orient") || ctx.optionString("orient") == "chain";
}

// A rotation about a signed unit local axis as a drive output and the sign of its factor.
std::pair<DriveOutput, double> rotationAbout(const Vec3& axis)
{
    const int i = std::abs(axis.x) > 0.5 ? 0 : std::abs(axis.y) > 0.5 ? 1 : 2;
    return {static_cast<DriveOutput>(i), axis[i] > 0.0 ? 1.0 : -1.0};
}

// How a digit's links are turned and posed: the frames, the axis a curl turns
// about (up_axis: the bend normal), the one a spread turns about and the one
// that points at the next joint (aim_axis).
struct DigitFrames {
    std::vector<Mat4> frames;
    Vec3 aimAxis{1.0, 0.0, 0.0};
    Vec3 curlAxis{0.0, 0.0, 1.0};
    Vec3 spreadAxis{0.0, 1.0, 0.0};
};

DigitFrames digitFrames(const BuildContext& ctx, const std::vector<JointId>& chain, const std::vector<Vec3>& points)
{
    DigitFrames d;
    if (chainOrient(ctx)) {
        d.frames = kit::chainFrames(points, rootNormal(ctx, chain.front()));
        return d;
    }
    const ChainOrient orient = readChainOrient(ctx, false).value_or(ChainOrient{}); // gather reported its problems
    d.frames = orientFrames(ctx, chain);
    d.aimAxis = orient.aimAxis;
    d.curlAxis = orient.upAxis;
    d.spreadAxis = glm::cross(orient.upAxis, orient.aimAxis); // turning about it moves the aim towards -up
    return d;
}

class DigitBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                            const std::map<std::string, Value>& guides) const override
    {
        const int count = std::max(2, static_cast<int>(kit::guideNumber(guides, "number", 5)));
        const double length = kit::guideNumber(guides, "length", 0.1);
        const auto thumb = guides.find("thumb");
        std::vector<GuideJointSpec> specs;
        if (thumb != guides.end() && std::holds_alternative<bool>(thumb->second) && std::get<bool>(thumb->second)) {
            // An opposed thumb: from the heel of the palm on the front (+Z) side,
            // pointing forward, out and down, curving back under the palm so
            // that a curl folds it across the palm towards the little finger.
            const Vec3 aim = glm::normalize(Vec3(0.45, -0.45, 0.75));
            const Vec3 bend = glm::normalize(Vec3(0.0, -0.6, -1.0) - aim * glm::dot(Vec3(0.0, -0.6, -1.0), aim));
            int parent = kit::appendJoint(specs, -1, Vec3(-0.035, -0.045, 0.02));
            for (int i = 1; i < count; ++i)
                parent = kit::appendJoint(specs, parent, glm::normalize(aim + bend * (0.12 * i)) * (length / (count - 1)));
            return specs;
        }
        // Base (metacarpal), three phalanges and the tip along +X, curling down slightly.
        int parent = kit::appendJoint(specs, -1, Vec3(0.02, 0.0, 0.0));
        for (int i = 1; i < count; ++i)
            parent = kit::appendJoint(specs, parent, Vec3(length / (count - 1), -0.004 * i, 0.0));
        return specs;
    }

    bool gather(const BuildContext& ctx) const override
    {
        const auto chain = kit::chainOfAtLeast(ctx, 2, "a digit");
        const bool orient = readChainOrient(ctx, !chainOrient(ctx)).has_value();
        const bool nodes = readControlNodes(ctx).has_value();
        return chain && orient && nodes && readDigitAim(ctx, aimedCount(ctx, chain->size())).has_value();
    }

    void generate(BuildContext& ctx) const override
    {
        const auto chain = *ctx.structure("chain");
        const auto points = *kit::positions(ctx, chain);
        const DigitFrames d = digitFrames(ctx, chain, points);
        const auto& frames = d.frames;
        const ControlNodeOptions nodes = readControlNodes(ctx).value_or(ControlNodeOptions{});
        const bool base = hasBase(ctx, chain.size());
        RigNodeIndex parent = ctx.hookNode();
        std::vector<ControlStack> controls;
        for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
            const bool isBase = base && i == 0;
            const std::string token = isBase ? "base" : "";
            const std::optional<int> number = isBase ? std::nullopt : std::optional<int>(int(i) + (base ? 0 : 1));
            const ControlStack control = addControlStack(ctx, nodes, "fk." + std::to_string(i), token, number, parent, frames[i], chain[i], i > 0);
            kit::animate(ctx, control.control(), kit::kRotate); // knuckles turn
            kit::addSkin(ctx, std::to_string(i), token, number, control.skinParent, frames[i], chain[i]);
            ctx.setHook(chain[i], control.ctrl);
            controls.push_back(control);
            parent = control.ctrl;
        }
        ctx.setHook(chain.back(), parent);
        const std::size_t first = base ? 1 : 0; // the first phalanx: the knuckle, where a finger spreads
        // The aim rig before the drives: they turn the phalanges from where it leaves them.
        addDigitAim(ctx, readDigitAim(ctx, aimedCount(ctx, chain.size())).value_or(DigitAimOptions{}),
                    DigitChain{controls, chain, points, frames, d.aimAxis, d.curlAxis}, first);
        // Curl bends every phalanx about its bend axis (up_axis) from one attribute.
        const auto [curlOutput, curlSign] = rotationAbout(d.curlAxis);
        const model::AttributeRef curl = ctx.addAttribute(controls.front().ctrl, "curl", 0.0, -30.0, 120.0);
        for (std::size_t i = first; i < controls.size(); ++i)
            ctx.addConstraint("cns.curl." + std::to_string(i), {controls[i].driven()}, {},
                              DriveConstraint{.value = curl, .output = curlOutput, .factor = driveFactor(ctx, controls[i], curlOutput, curlSign),
                                              .response = DriveClamped{.low = -30.0, .high = 120.0}});

        // Spread turns the finger at its knuckle about the palm's normal (the
        // phalanx's Y by default); positive spreads it towards the hand's side
        // axis (the thumb side: the hand guide's Z, else the finger's own up).
        const RigNodeIndex hook = ctx.hookNode();
        const Vec3 side = hook != model::kNoNode ? glm::normalize(Vec3(ctx.nodeWorld(hook)[2])) : Mat3(frames.front()) * d.curlAxis;
        const double towardSide = glm::dot(Mat3(frames[first]) * d.curlAxis, side) > 0.0 ? -1.0 : 1.0; // spread turns move the aim towards -up
        const auto [spreadOutput, spreadSign] = rotationAbout(d.spreadAxis);
        const model::AttributeRef spread = ctx.addAttribute(controls.front().ctrl, "spread", 0.0, -30.0, 45.0);
        ctx.addConstraint("cns.spread", {controls[first].driven()}, {},
                          DriveConstraint{.value = spread, .output = spreadOutput,
                                          .factor = driveFactor(ctx, controls[first], spreadOutput, towardSide * spreadSign),
                                          .response = DriveClamped{.low = -30.0, .high = 45.0}});
        if (hook != model::kNoNode)
            followHand(ctx, controls, first, points, side, towardSide, d);
    }

private:
    // The first joint is a base control (not a phalanx) with `base` on and more than one phalanx.
    static bool hasBase(const BuildContext& ctx, std::size_t joints) { return ctx.optionBool("base") && joints > 2; }
    // Phalanges the aim rig turns: every control but the base.
    static std::size_t aimedCount(const BuildContext& ctx, std::size_t joints) { return joints - 1 - (hasBase(ctx, joints) ? 1 : 0); }

    // A finger on a digit.hand's master: its fist, curl, spread and cup drive
    // this finger by shares from where the finger sits across the hand.
    static void followHand(BuildContext& ctx, const std::vector<ControlStack>& controls, std::size_t first,
                           const std::vector<Vec3>& points, const Vec3& side, double towardSide, const DigitFrames& d)
    {
        const RigNodeIndex hand = ctx.hookNode();
        const model::RigNode& node = ctx.node(hand);
        for (const HandAttribute& a : kHandAttributes)
            if (std::none_of(node.attributes.begin(), node.attributes.end(), [&](const model::RigAttribute& r) { return r.name == a.name; }))
                return; // not a hand master
        const bool thumb = ctx.optionBool("thumb");
        double length = 0.0;
        for (std::size_t i = 1; i < points.size(); ++i)
            length += glm::length(points[i] - points[i - 1]);
        // Across the hand: +1 on the thumb side, -1 at the little finger, by the
        // knuckle's offset from the hand's centre line relative to the finger's length.
        const double across = thumb ? 1.0
                                    : std::clamp(2.0 * glm::dot(points[first] - kit::positionOf(ctx.nodeWorld(hand)), side) /
                                                     std::max(length, 1e-6), -1.0, 1.0);
        // Each drive lands on the control's pose group (do_pose) or its offset.
        auto drive = [&](const std::string& tag, const ControlStack& driven, const HandAttribute& a, const Vec3& axis, double factor) {
            const auto [output, sign] = rotationAbout(axis);
            if (factor != 0.0)
                ctx.addConstraint(tag, {driven.driven()}, {},
                                  DriveConstraint{.value = {hand, a.name}, .output = output, .factor = driveFactor(ctx, driven, output, sign * factor),
                                                  .response = DriveClamped{.low = a.low, .high = a.high}});
        };
        const double fist = ctx.optionFloat("fist") * (thumb ? 0.6 : 1.0);
        for (std::size_t i = first; i < controls.size(); ++i) {
            const std::string index = std::to_string(i);
            drive("cns.hand_fist." + index, controls[i], kHandAttributes[0], d.curlAxis, fist);
            drive("cns.hand_curl." + index, controls[i], kHandAttributes[1], d.curlAxis, 1.0);
        }
        drive("cns.hand_spread", controls[first], kHandAttributes[2], d.spreadAxis, across * towardSide);
        // Cup folds the palm: the metacarpals bend towards it, the little
        // finger's side (and the thumb) the most.
        if (first > 0)
            drive("cns.hand_cup", controls.front(), kHandAttributes[3], d.curlAxis,
                  thumb ? 1.0 : std::clamp((1.0 - across) / 2.0, 0.0, 1.0));
    }
};

class HandBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&, const std::map<std::string, Value>&) const override
    {
        // Over the back of the hand, clear of the fingers' controls.
        std::vector<GuideJointSpec> specs;
        kit::appendJoint(specs, -1, Vec3(0.05, 0.035, 0.0));
        return specs;
    }

    bool gather(const BuildContext& ctx) const override { return ctx.structure("hand").has_value(); }

    void generate(BuildContext& ctx) const override
    {
        const JointId joint = ctx.structure("hand")->front();
        const Mat4 frame = rigidFrame(ctx.guideWorldMatrix(joint));
        const auto control = kit::addControl(ctx, "hand", "hand", {}, ctx.hookNode(), frame, joint);
        // An attribute control: it carries the fingers and never moves itself.
        if (control.ctrl != control.offset)
            ctx.channels(control.ctrl).lock(0, model::ChannelSettings::kCount);
        kit::animate(ctx, control, kit::kNothing);
        for (const HandAttribute& a : kHandAttributes)
            ctx.addAttribute(control.ctrl, a.name, 0.0, a.low, a.high);
        ctx.setHook(joint, control.ctrl);
    }
};

} // namespace

std::unique_ptr<TemplateBuilder> makeDigitBuilder() { return std::make_unique<DigitBuilder>(); }
std::unique_ptr<TemplateBuilder> makeHandBuilder() { return std::make_unique<HandBuilder>(); }

} // namespace rs::rigging
