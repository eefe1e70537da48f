// digit.finger and digit.hand. A finger hung on a hand's master control takes
// the hand's fist, curl, spread and cup attributes: the master drives every
// finger of the hand without knowing how many there are.
#include "rigging/builders/Builders.h"

#include "rigging/builders/BuilderKit.h"

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

    bool gather(const BuildContext& ctx) const override { return kit::chainOfAtLeast(ctx, 2, "a digit").has_value(); }

    void generate(BuildContext& ctx) const override
    {
        const auto chain = *ctx.structure("chain");
        const auto points = *kit::positions(ctx, chain);
        const auto frames = kit::chainFrames(points, rootNormal(ctx, chain.front()));
        const bool base = ctx.optionBool("base") && chain.size() > 2;
        RigNodeIndex parent = ctx.hookNode();
        std::vector<kit::Control> controls;
        for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
            const bool isBase = base && i == 0;
            const std::string token = isBase ? "base" : "";
            const std::optional<int> number = isBase ? std::nullopt : std::optional<int>(int(i) + (base ? 0 : 1));
            const auto control = kit::addControl(ctx, "fk." + std::to_string(i), token, number, parent, frames[i], chain[i]);
            kit::animate(ctx, control, kit::kRotate); // knuckles turn
            kit::addSkin(ctx, std::to_string(i), token, number, control.ctrl, frames[i], chain[i]);
            ctx.setHook(chain[i], control.ctrl);
            controls.push_back(control);
            parent = control.ctrl;
        }
        ctx.setHook(chain.back(), parent);
        const std::size_t first = base ? 1 : 0; // the first phalanx: the knuckle, where a finger spreads
        // Curl bends every phalanx about its bend axis (Z) from one attribute.
        const model::AttributeRef curl = ctx.addAttribute(controls.front().ctrl, "curl", 0.0, -30.0, 120.0);
        for (std::size_t i = first; i < controls.size(); ++i)
            ctx.addConstraint("cns.curl." + std::to_string(i), {controls[i].offset}, {},
                              DriveConstraint{.value = curl, .output = DriveOutput::RotateZ, .factor = 1.0,
                                              .response = DriveClamped{.low = -30.0, .high = 120.0}});

        // Spread turns the finger at its knuckle about the palm's normal (the
        // phalanx's Y); positive spreads it towards the hand's side axis (the
        // thumb side: the hand guide's Z, else the finger's own Z).
        const RigNodeIndex hook = ctx.hookNode();
        const Vec3 side = hook != model::kNoNode ? glm::normalize(Vec3(ctx.nodeWorld(hook)[2])) : Vec3(frames.front()[2]);
        const double towardSide = glm::dot(Vec3(frames[first][2]), side) > 0.0 ? -1.0 : 1.0; // Y turns move X towards -Z
        const model::AttributeRef spread = ctx.addAttribute(controls.front().ctrl, "spread", 0.0, -30.0, 45.0);
        ctx.addConstraint("cns.spread", {controls[first].offset}, {},
                          DriveConstraint{.value = spread, .output = DriveOutput::RotateY, .factor = towardSide,
                                          .response = DriveClamped{.low = -30.0, .high = 45.0}});
        if (hook != model::kNoNode)
            followHand(ctx, controls, first, points, side, towardSide);
    }

private:
    // A finger on a digit.hand's master: its fist, curl, spread and cup drive
    // this finger by shares from where the finger sits across the hand.
    static void followHand(BuildContext& ctx, const std::vector<kit::Control>& controls, std::size_t first,
                           const std::vector<Vec3>& points, const Vec3& side, double towardSide)
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
        auto drive = [&](const std::string& tag, RigNodeIndex driven, const HandAttribute& a, DriveOutput output, double factor) {
            if (factor != 0.0)
                ctx.addConstraint(tag, {driven}, {},
                                  DriveConstraint{.value = {hand, a.name}, .output = output, .factor = factor,
                                                  .response = DriveClamped{.low = a.low, .high = a.high}});
        };
        const double fist = ctx.optionFloat("fist") * (thumb ? 0.6 : 1.0);
        for (std::size_t i = first; i < controls.size(); ++i) {
            const std::string index = std::to_string(i);
            drive("cns.hand_fist." + index, controls[i].offset, kHandAttributes[0], DriveOutput::RotateZ, fist);
            drive("cns.hand_curl." + index, controls[i].offset, kHandAttributes[1], DriveOutput::RotateZ, 1.0);
        }
        drive("cns.hand_spread", controls[first].offset, kHandAttributes[2], DriveOutput::RotateY, across * towardSide);
        // Cup folds the palm: the metacarpals bend towards it, the little
        // finger's side (and the thumb) the most.
        if (first > 0)
            drive("cns.hand_cup", controls.front().offset, kHandAttributes[3], DriveOutput::RotateZ,
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
