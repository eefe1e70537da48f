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

std::vector<Mat4> orientEffector(const BuildContext& ctx, std::vector<Mat4> frames, std::size_t k)
{
    const std::string plane = ctx.optionString("effector_plane");
    if (plane != "x" && plane != "y" && plane != "z" && plane != "ground")
        return frames; // auto, or a template without the option
    const Vec3 up(0.0, 1.0, 0.0);
    const Vec3 aim(frames[k - 1][0]);
    Mat4 frame(1.0);
    if (plane == "ground") {
        const Vec3 level = aim - up * glm::dot(aim, up);
        if (glm::length(level) < 1e-6) {
            ctx.warning("effector_plane 'ground': the end joint aims straight up or down, so the ground gives no forward; "
                        "it keeps the limb's plane (auto)",
                        "effector_plane");
            return frames;
        }
        frame = kit::aimFrame(Vec3(0.0), level, glm::cross(level, up));
    } else {
        const Vec3 axis(plane == "x" ? 1.0 : 0.0, plane == "y" ? 1.0 : 0.0, plane == "z" ? 1.0 : 0.0);
        if (glm::length(glm::cross(glm::normalize(aim), axis)) < 1e-3) {
            ctx.warning("effector_plane '" + plane + "': the end joint aims along that axis, so it gives no up; it keeps the "
                        "limb's plane (auto)",
                        "effector_plane");
            return frames;
        }
        frame = kit::aimFrame(Vec3(0.0), aim, glm::cross(aim, axis)); // Z = X x axis, so Y leans towards the axis
    }
    for (std::size_t i = k - 1; i <= k && i < frames.size(); ++i) {
        const Vec4 position = frames[i][3];
        frames[i] = frame;
        frames[i][3] = position;
    }
    return frames;
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

namespace {

// An on/off option that is on unless the manifest says otherwise (a limb
// template of a studio's own without the option keeps the default rig).
bool optionOnUnlessOff(const BuildContext& ctx, const std::string& name)
{
    const Value& v = ctx.option(name);
    return !std::holds_alternative<bool>(v) || std::get<bool>(v);
}

// A space switch on `control` (kit::addSpaceSwitch), or with `space_switch`
// off the space `option` names followed for good, without a switch: nothing
// when that is the group's own parent.
void switchOrFollow(BuildContext& ctx, RigNodeIndex group, RigNodeIndex control, const std::string& option,
                    const std::string& tag, const std::vector<kit::Space>& spaces, bool orientOnly)
{
    if (optionOnUnlessOff(ctx, "space_switch")) {
        kit::addSpaceSwitch(ctx, group, control, option, tag, spaces, orientOnly);
        return;
    }
    const std::string chosen = ctx.optionString(option);
    RigNodeIndex target = spaces.front().node;
    for (const kit::Space& space : spaces) {
        if (space.name != chosen)
            continue;
        target = space.node != model::kNoNode ? space.node : ctx.space(space.name);
        if (target == model::kNoNode) {
            ctx.warning(option + " '" + chosen + "' is not a space of this rig; it follows '" + spaces.front().name + "'", option);
            target = spaces.front().node;
        }
    }
    if (target == ctx.node(group).parent)
        return;
    if (orientOnly)
        ctx.addConstraint(tag, {group}, {target}, model::OrientConstraint{});
    else
        ctx.addConstraint(tag, {group}, {target}, model::ParentConstraint{});
}

// Entry 0 is `first`, the others the rig's named spaces.
std::vector<kit::Space> spacesAfter(RigNodeIndex first, const std::vector<std::string>& names)
{
    std::vector<kit::Space> spaces;
    for (std::size_t i = 0; i < names.size(); ++i)
        spaces.push_back({names[i], i == 0 ? first : model::kNoNode});
    return spaces;
}

} // namespace

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
    switchOrFollow(ctx, *group, *pole, "pv_space", "cns.pv_space", spaces, false);
}

RigNodeIndex addFkSpaceGroup(BuildContext& ctx, RigNodeIndex limbGroup, const Mat4& frame, model::JointId source)
{
    return ctx.createNode(RigNodeKind::Group, "spaces.fk", ctx.nodeName(model::NameRole::Group, "fk_space"), limbGroup, frame,
                          source);
}

const std::vector<std::string>& fkSpaces(bool leg)
{
    // A leg may follow the hips (a biped's thigh swinging free of the pelvis)
    // or the chest (a quadruped's front leg on the chest).
    static const std::vector<std::string> arm = {"parent", "chest", "cog", "world", "root"};
    static const std::vector<std::string> legs = {"parent", "hips", "chest", "cog", "world", "root"};
    return leg ? legs : arm;
}

void addSpaceSwitches(BuildContext& ctx, const std::vector<std::string>& ikSpaces, bool leg)
{
    const bool controls = ctx.optionBool("do_ctrl");
    const auto ikGroup = ctx.findNode("spaces.ik");
    const auto ik = ctx.findNode(controls ? "ctrls.ik" : "roots.ik");
    if (ikGroup && ik)
        switchOrFollow(ctx, *ikGroup, *ik, "ik_space", "cns.ik_space", spacesAfter(ctx.node(*ikGroup).parent, ikSpaces), false);
    addPoleSpaceSwitch(ctx);
    const auto fkGroup = ctx.findNode("spaces.fk");
    const auto fk = ctx.findNode(controls ? "ctrls.fk.0" : "roots.fk.0");
    if (fkGroup && fk)
        switchOrFollow(ctx, *fkGroup, *fk, "fk_space", "cns.fk_space", spacesAfter(ctx.node(*fkGroup).parent, fkSpaces(leg)), true);
}

void addBlendVisibility(BuildContext& ctx, const model::AttributeRef& blend, const std::vector<RigNodeIndex>& fk,
                        const std::vector<RigNodeIndex>& ik)
{
    if (!ctx.optionBool("ik_fk_visibility") || !ctx.optionBool("do_ctrl"))
        return;
    ctx.addConstraint("vis.fk", fk, {}, model::VisibilityConstraint{.value = blend, .when = model::ShowWhen::Below, .threshold = 1.0});
    ctx.addConstraint("vis.ik", ik, {}, model::VisibilityConstraint{.value = blend, .when = model::ShowWhen::Above, .threshold = 0.0});
}

TwistJoints addTwistJoints(BuildContext& ctx, const std::vector<Vec3>& points, const std::vector<Mat4>& frames,
                           const std::vector<model::JointId>& guides, const std::vector<RigNodeIndex>& blend,
                           const std::vector<RigNodeIndex>& skin, RigNodeIndex limbRoot,
                           const std::vector<std::vector<RigNodeIndex>>& bendCurves, const std::optional<model::AttributeRef>& bias)
{
    TwistJoints out;
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
                                                     .byLength = byLength, .bias = bias});
            out.joints[s].push_back(joint);
            out.fractions[s].push_back(fraction);
        }
    }
    return out;
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
