#include "rigging/builders/DigitAim.h"

#include "base/TextScalars.h"

#include <cctype>
#include <cmath>
#include <glm/geometric.hpp>

namespace rs::rigging {

namespace {

using model::RigNodeIndex;

constexpr const char* kHookTarget = "*::hooks.digits"; // Mikan's default: the hand's digits hook
constexpr const char* kSpacePrefix = "*::space.";

bool isName(const std::string& text)
{
    if (text.empty() || !(std::isalpha(static_cast<unsigned char>(text[0])) || text[0] == '_'))
        return false;
    for (char c : text)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_'))
            return false;
    return true;
}

// target_parent as a space name ("" for the hook); nullopt when it names no node.
std::optional<std::string> targetSpace(const std::string& text)
{
    if (text == kHookTarget || text == "hook")
        return std::string();
    const std::string prefix = kSpacePrefix;
    const std::string name = text.rfind(prefix, 0) == 0 ? text.substr(prefix.size()) : text;
    if (!isName(name))
        return std::nullopt;
    return name;
}

// The model axis of a signed unit local axis.
model::Axis axisOf(const Vec3& axis)
{
    return std::abs(axis.x) > 0.5 ? model::Axis::X : std::abs(axis.y) > 0.5 ? model::Axis::Y : model::Axis::Z;
}

} // namespace

std::optional<DigitAimOptions> readDigitAim(const BuildContext& ctx, std::size_t aimed)
{
    DigitAimOptions o;
    bool ok = true;
    const std::string parentText = ctx.optionString("target_parent");
    if (const auto space = targetSpace(parentText)) {
        o.space = *space;
    } else {
        ctx.error("target_parent '" + parentText + "' names no node: " + kHookTarget + " (or hook) for the node the finger hangs "
                  "from, or a space of the rig (" + kSpacePrefix + "cog, or cog, chest, world...)", "target_parent");
        ok = false;
    }
    const auto items = ctx.optionList("target_weights");
    if (!items)
        return std::nullopt;
    for (const std::string& item : *items) {
        const auto weight = parseNumber(item);
        if (!weight || !std::isfinite(*weight) || *weight < 0.0 || *weight > 1.0) {
            ctx.error("target_weights: '" + item + "' is no weight (a number from 0, the FK pose, to 1, fully aimed)", "target_weights");
            ok = false;
        } else {
            o.weights.push_back(*weight);
        }
    }
    if (ok && o.weights.size() > 1 && o.weights.size() != aimed) {
        ctx.error("target_weights has " + std::to_string(o.weights.size()) + " weights for " + std::to_string(aimed) +
                  " aimed phalanges (one per phalanx after the base, or one for all)", "target_weights");
        ok = false;
    }
    if (!ok)
        return std::nullopt;
    if (o.weights.size() == 1)
        o.weights.assign(aimed, o.weights.front());
    return o;
}

void addDigitAim(BuildContext& ctx, const DigitAimOptions& options, const DigitChain& chain, std::size_t first)
{
    if (options.weights.empty() || chain.controls.size() <= first)
        return;
    RigNodeIndex parent = ctx.hookNode();
    if (!options.space.empty()) {
        const RigNodeIndex space = ctx.space(options.space);
        if (space == model::kNoNode)
            ctx.warning("target_parent '" + ctx.optionString("target_parent") + "' is not a space of this rig; the target follows "
                        "the node the finger hangs from", "target_parent");
        else
            parent = space;
    }
    const std::size_t tip = chain.joints.size() - 1;
    const kit::Control target = kit::addControl(ctx, "target", "target", {}, parent, chain.frames[tip], chain.joints[tip]);
    kit::animate(ctx, target, kit::kTranslate); // a point the finger reaches for
    for (std::size_t i = first; i < chain.controls.size(); ++i) {
        const ControlStack& control = chain.controls[i];
        const std::string key = std::to_string(i);
        // Where the next joint sits, carried by the target (the tip is the target itself).
        const RigNodeIndex goal = i + 1 == tip ? target.ctrl
                                               : kit::addSetup(ctx, model::RigNodeKind::Group, "mch.aim_target." + key, "aim_target",
                                                               int(i), target.ctrl, chain.frames[i + 1], chain.joints[i + 1]);
        // The up: the phalanx's bend axis as what it hangs from carries it.
        const Vec3 bend = glm::normalize(Mat3(chain.frames[i]) * chain.curlAxis);
        Mat4 upFrame = chain.frames[i];
        upFrame[3] = Vec4(chain.points[i] + bend * glm::length(chain.points[i + 1] - chain.points[i]), 1.0);
        const RigNodeIndex up = kit::addSetup(ctx, model::RigNodeKind::Group, "mch.aim_up." + key, "aim_up", int(i),
                                              ctx.node(control.offset).parent, upFrame, chain.joints[i]);
        const model::AttributeRef weight = ctx.addAttribute(control.ctrl, "aim", options.weights[i - first], 0.0, 1.0);
        ctx.addConstraint("cns.aim." + key, {control.offset}, {goal, up},
                          model::AimConstraint{.aim = axisOf(chain.aimAxis), .up = axisOf(chain.curlAxis), .weight = weight});
    }
}

} // namespace rs::rigging
