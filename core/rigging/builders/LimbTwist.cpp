#include "rigging/builders/LimbTwist.h"

#include "rigging/builders/BuilderKit.h"
#include "templates/NodeNames.h"

namespace rs::rigging::limb {

using model::AttributeRef;
using model::RigNodeIndex;

namespace {

bool declares(const BuildContext& ctx, const char* name) { return ctx.manifest().findOpt(name) != nullptr; }

const char* const kSegments[] = {"up", "dn"};

// A roll of `value` times `share` about `joint`'s bone (its X axis).
void roll(BuildContext& ctx, const std::string& tag, RigNodeIndex joint, const AttributeRef& value, double share)
{
    if (share != 0.0)
        ctx.addConstraint(tag, {joint}, {},
                          model::DriveConstraint{.value = value, .output = model::DriveOutput::RotateX, .factor = share});
}

} // namespace

AdvancedTwist addAdvancedTwistAttributes(BuildContext& ctx, RigNodeIndex settings)
{
    AdvancedTwist out;
    if (!declares(ctx, "advanced_twist") || !ctx.optionBool("advanced_twist"))
        return out;
    out.start = ctx.addAttribute(settings, "twist_start", 0.0, -180.0, 180.0);
    out.mid = ctx.addAttribute(settings, "twist_mid", 0.0, -180.0, 180.0);
    out.end = ctx.addAttribute(settings, "twist_end", 0.0, -180.0, 180.0);
    out.bias = ctx.addAttribute(settings, "twist_bias", 0.0, -1.0, 1.0);
    return out;
}

void addAdvancedTwistRolls(BuildContext& ctx, const AdvancedTwist& twist, const TwistJoints& joints,
                           const std::vector<RigNodeIndex>& skin)
{
    if (!twist.isOn())
        return;
    if (skin.size() > 1 && skin[0] != model::kNoNode) {
        roll(ctx, "cns.advanced_twist.limb.0", skin[0], *twist.start, 1.0);
        roll(ctx, "cns.advanced_twist.limb.1", skin[1], *twist.mid, 1.0);
    }
    const AttributeRef* bounds[2][2] = {{&*twist.start, &*twist.mid}, {&*twist.mid, &*twist.end}};
    for (std::size_t s = 0; s < 2; ++s)
        for (std::size_t t = 0; t < joints.joints[s].size(); ++t) {
            const double f = joints.fractions[s][t];
            const std::string tag = "cns.advanced_twist." + std::string(kSegments[s]) + "." + std::to_string(t);
            roll(ctx, tag + ".start", joints.joints[s][t], *bounds[s][0], 1.0 - f);
            roll(ctx, tag + ".end", joints.joints[s][t], *bounds[s][1], f);
        }
}

std::vector<std::string> twistChainNames(const BuildContext& ctx)
{
    if (!declares(ctx, "add_chains"))
        return {};
    const auto names = ctx.optionList("add_chains");
    if (!names)
        return {};
    bool ok = true;
    for (const std::string& problem : templates::addChainsProblems(*names)) {
        ctx.error("add_chains " + problem, "add_chains");
        ok = false;
    }
    return ok ? *names : std::vector<std::string>{};
}

void addTwistChains(BuildContext& ctx, const TwistJoints& joints, const std::vector<model::JointId>& guides)
{
    const std::vector<std::string> names = twistChainNames(ctx);
    if (names.empty())
        return;
    if (joints.joints[0].empty() && joints.joints[1].empty()) {
        ctx.warning("add_chains: the limb has no twist joints (twist_upper and twist_lower are 0, or no skin joints), so "
                    "no chain is built",
                    "add_chains");
        return;
    }
    for (const std::string& name : names)
        for (std::size_t s = 0; s < 2; ++s)
            for (std::size_t t = 0; t < joints.joints[s].size(); ++t) {
                const RigNodeIndex twist = joints.joints[s][t];
                const std::string key = std::string(kSegments[s]) + "." + name + "." + std::to_string(t);
                const std::string token = name + "_" + kSegments[s];
                const Mat4 frame = ctx.nodeWorld(twist);
                const kit::Control tweak = kit::addControl(ctx, key, token, int(t) + 1, twist, frame, guides[s]);
                kit::animate(ctx, tweak, kit::kTranslate | kit::kRotate | kit::kScale); // flesh: move, turn, bulge
                kit::addSkin(ctx, key, token, int(t) + 1, tweak.ctrl, frame, guides[s]);
            }
}

} // namespace rs::rigging::limb
