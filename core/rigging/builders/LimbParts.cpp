#include "rigging/builders/LimbParts.h"

#include "rigging/builders/BuilderKit.h"
#include "rigging/builders/Builders.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace rs::rigging::limb {

using model::RigNodeIndex;
using model::RigNodeKind;

Mat4 ikControlFrame(const BuildContext& ctx, const Vec3& position, const Mat4& jointFrame, model::JointId endGuide)
{
    const std::string orient = ctx.optionString("ik_orient");
    Mat4 frame = kit::uprightFrame(position);
    if (orient == "joint")
        frame = jointFrame;
    else if (orient == "copy")
        frame = rigidFrame(ctx.guideWorldMatrix(endGuide));
    frame[3] = Vec4(position, 1.0);
    return frame;
}

const std::vector<std::string>& poleSpaces()
{
    static const std::vector<std::string> spaces = {"follow", "ik", "world", "root", "cog"};
    return spaces;
}

RigNodeIndex addPoleSpaceGroups(BuildContext& ctx, RigNodeIndex world, RigNodeIndex limbRoot, RigNodeIndex ikControl,
                                const Mat4& poleFrame, model::JointId source)
{
    // Halfway between the limb's root and the IK control, turned like the root:
    // the bend plane travels with the body and the planted end without taking
    // the IK control's own rotation (turning a hand about the forearm does not
    // swing the elbow) and without an aim that could flip.
    Mat4 followFrame = ctx.nodeWorld(limbRoot);
    followFrame[3] = Vec4(glm::mix(kit::positionOf(followFrame), kit::positionOf(ctx.nodeWorld(ikControl)), 0.5), 1.0);
    const auto follow = kit::addSetup(ctx, RigNodeKind::Group, "spaces.pole_follow", "pole_follow", {}, world, followFrame, source);
    ctx.addConstraint("cns.pole_follow.point", {follow}, {limbRoot, ikControl},
                      model::PointConstraint{.weights = {0.5, 0.5}, .keepOffset = false});
    ctx.addConstraint("cns.pole_follow.orient", {follow}, {limbRoot}, model::OrientConstraint{});
    return ctx.createNode(RigNodeKind::Group, "spaces.pole", ctx.nodeName(model::NameRole::Group, "pole_space"), world, poleFrame,
                          source);
}

void addPoleSpaceSwitch(BuildContext& ctx)
{
    const bool controls = ctx.optionBool("do_ctrl");
    const auto group = ctx.findNode("spaces.pole");
    const auto follow = ctx.findNode("spaces.pole_follow");
    const auto pole = ctx.findNode(controls ? "ctrls.pole" : "roots.pole");
    const auto ik = ctx.findNode(controls ? "ctrls.ik" : "roots.ik");
    if (!group || !follow || !pole || !ik)
        return;
    std::vector<kit::Space> spaces;
    for (const std::string& name : poleSpaces())
        spaces.push_back({name, name == "follow" ? *follow : name == "ik" ? *ik : model::kNoNode});
    kit::addSpaceSwitch(ctx, *group, *pole, "pv_space", "cns.pv_space", spaces, false);
}

void addBlendVisibility(BuildContext& ctx, const model::AttributeRef& blend, const std::vector<RigNodeIndex>& fk,
                        const std::vector<RigNodeIndex>& ik)
{
    if (!ctx.optionBool("ik_fk_visibility") || !ctx.optionBool("do_ctrl"))
        return;
    ctx.addConstraint("vis.fk", fk, {}, model::VisibilityConstraint{.value = blend, .when = model::ShowWhen::Below, .threshold = 1.0});
    ctx.addConstraint("vis.ik", ik, {}, model::VisibilityConstraint{.value = blend, .when = model::ShowWhen::Above, .threshold = 0.0});
}

void addTwistJoints(BuildContext& ctx, const std::vector<Vec3>& points, const std::vector<Mat4>& frames,
                    const std::vector<model::JointId>& guides, const std::vector<RigNodeIndex>& blend,
                    const std::vector<RigNodeIndex>& skin, RigNodeIndex limbRoot,
                    const std::vector<std::vector<RigNodeIndex>>& bendCurves)
{
    const bool byLength = bendCurves.empty() || ctx.optionString("smooth_type") != "parametric";
    const bool nonRolling = ctx.optionBool("non_rolling");
    if (nonRolling && skin[0] != model::kNoNode) // the upper segment's own skin joint keeps the parent's roll
        ctx.addConstraint("cns.up.start", {skin[0]}, {blend[0], blend[1], limbRoot},
                          model::TwistConstraint{.fraction = 0.0, .nonRolling = true});
    const char* segment[] = {"up", "dn"};
    const char* option[] = {"twist_upper", "twist_lower"};
    for (std::size_t s = 0; s < 2; ++s) {
        const long long count = ctx.optionInt(option[s]);
        const bool upper = s == 0 && nonRolling;
        for (long long t = 0; t < count; ++t) {
            const double fraction = double(t + 1) / double(count + 1);
            Mat4 frame = frames[s];
            frame[3] = Vec4(glm::mix(points[s], points[s + 1], fraction), 1.0);
            const std::string key = std::string(segment[s]) + "." + std::to_string(t);
            const auto joint = kit::addSkin(ctx, key, segment[s], int(t) + 1, skin[s], frame, guides[s]);
            std::vector<RigNodeIndex> targets = {blend[s], blend[s + 1]};
            if (upper)
                targets.push_back(limbRoot);
            const bool bendy = s < bendCurves.size();
            if (bendy)
                targets.insert(targets.end(), bendCurves[s].begin(), bendCurves[s].end());
            ctx.addConstraint("cns." + key, {joint}, targets,
                              model::TwistConstraint{.fraction = fraction, .nonRolling = upper, .bendy = bendy, .lower = bendy && s == 1,
                                                     .byLength = byLength});
        }
    }
}

AutoClavicle addAutoClavicleGroups(BuildContext& ctx, RigNodeIndex hook, const Vec3& clavicle, const Vec3& shoulder,
                                   const Vec3& hand, model::JointId source)
{
    AutoClavicle g;
    if (!ctx.optionBool("do_ctrl") || !ctx.optionBool("clavicle"))
        return g;
    // X from the clavicle to the hand, Z forward (across the raise), so the aim
    // keeps its up in every raise and only a hand straight behind is ambiguous.
    Vec3 along = hand - clavicle;
    if (glm::length(along) < 1e-9)
        along = shoulder - clavicle;
    Vec3 forward = glm::cross(along, Vec3(0.0, 1.0, 0.0));
    if (glm::length(forward) < 1e-9)
        forward = Vec3(0.0, 0.0, 1.0);
    forward = glm::normalize(forward);
    if (forward.z < 0.0)
        forward = -forward;
    const Mat4 frame = kit::aimFrame(clavicle, along, forward);
    auto group = [&](const std::string& key) {
        return kit::addSetup(ctx, RigNodeKind::Group, "auto_clavicle." + key, "auto_clavicle_" + key, {}, hook, frame, source);
    };
    g.rest = group("rest");
    g.aim = group("aim");
    g.share = group("share");
    g.follow = group("follow");
    return g;
}

void connectAutoClavicle(BuildContext& ctx, const AutoClavicle& g, RigNodeIndex clavicle, RigNodeIndex ikControl,
                         const model::AttributeRef& ikBlend)
{
    if (g.follow == model::kNoNode)
        return;
    const model::AttributeRef share =
        ctx.addAttribute(clavicle, "auto_clavicle", std::clamp(ctx.optionFloat("auto_clavicle"), 0.0, 1.0), 0.0, 1.0);
    // The up target: behind the clavicle, so raising the arm up, down or
    // forward never lines the aim up with it.
    Mat4 upFrame = ctx.nodeWorld(g.rest);
    upFrame[3] = Vec4(kit::positionOf(upFrame) - Vec3(upFrame[2]) * 0.5, 1.0);
    const auto up = kit::addSetup(ctx, RigNodeKind::Group, "auto_clavicle.up", "auto_clavicle_up", {}, g.rest, upFrame,
                                  ctx.node(g.rest).guide);
    ctx.addConstraint("cns.auto_clavicle.aim", {g.aim}, {ikControl, up},
                      model::AimConstraint{.aim = model::Axis::X, .up = model::Axis::Z});
    ctx.addConstraint("cns.auto_clavicle.share", {g.share}, {g.rest, g.aim}, model::BlendConstraint{.weight = share});
    ctx.addConstraint("cns.auto_clavicle.follow", {g.follow}, {g.rest, g.share}, model::BlendConstraint{.weight = ikBlend});
}

RigNodeIndex addPinControl(BuildContext& ctx, RigNodeIndex poleSpace, const Vec3& mid, model::JointId source)
{
    if (!ctx.optionBool("pin"))
        return model::kNoNode;
    const auto pin = kit::addControl(ctx, "pin", "pin", {}, poleSpace, kit::uprightFrame(mid), source).ctrl;
    if (ctx.node(pin).kind == RigNodeKind::Controller)
        ctx.channels(pin).lock(3, 6); // a position: rotation and scale mean nothing
    kit::animate(ctx, pin, kit::kTranslate);
    return pin;
}

} // namespace rs::rigging::limb
