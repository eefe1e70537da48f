// neck.head: FK neck controls, a head control with orientation and position
// space switches, and the neck joints on a spline from the neck to the head.
#include "rigging/builders/Builders.h"

#include "rigging/builders/BuilderKit.h"
#include "rigging/builders/ChainOrient.h"
#include "rigging/builders/SkinSpread.h"

#include <algorithm>

namespace rs::rigging {

namespace {

using model::RigNodeIndex;
using model::RigNodeKind;

// The side axis of a vertical chain: the X axis of its root guide (world X
// unless the rigger turned the root), so necks never flip.
Vec3 sideAxis(const BuildContext& ctx, model::JointId root) { return kit::guideAxis(ctx, root, 0, Vec3(1.0, 0.0, 0.0)); }

// aim_axis / up_axis: the turn that takes a neck frame (X along the neck, Y
// across it) to one whose `aim` points along the neck and `up` across it; a
// frame times it keeps its origin and its directions, renamed.
Mat4 axisTurn(const ChainOrient& axes)
{
    Mat3 source(axes.aimAxis, axes.upAxis, glm::cross(axes.aimAxis, axes.upAxis));
    return Mat4(glm::transpose(source));
}

const std::vector<std::string> kHeadSpaces = {"neck", "chest", "cog", "world"};

// head_orient: the head controller's frame at the head joint. `world` is
// axis-aligned (ry turns the head left and right, as on the COG and the
// chest), `joint` the head joint's own frame, `copy` the head guide's
// orientation as the rigger gave it (arm.limb's ik_orient, for the head).
Mat4 headControlFrame(const BuildContext& ctx, const Mat4& jointFrame, model::JointId headGuide)
{
    const std::string orient = ctx.optionString("head_orient");
    Mat4 frame = jointFrame;
    if (orient == "world")
        frame = kit::uprightFrame(kit::positionOf(jointFrame));
    else if (orient == "copy")
        frame = rigidFrame(ctx.guideWorldMatrix(headGuide));
    frame[3] = jointFrame[3];
    return frame;
}

class NeckBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                            const std::map<std::string, Value>& guides) const override
    {
        // Neck base on the chest (1.5 m), head at 1.62 m, head top at 1.8 m.
        const int count = std::max(1, static_cast<int>(kit::guideNumber(guides, "number", 2)));
        std::vector<GuideJointSpec> specs;
        int parent = kit::appendChain(specs, count, Vec3(0.0, 0.02, -0.01), Vec3(0.0, 0.06 / count, 0.01));
        parent = kit::appendJoint(specs, parent, Vec3(0.0, 0.1 - 0.06 * (count - 1) / count, 0.01)); // head 0.12 above the chest
        kit::appendJoint(specs, parent, Vec3(0.0, 0.18, 0.0));
        return specs;
    }

    bool gather(const BuildContext& ctx) const override
    {
        // readChainOrient checks aim_axis and up_axis (the neck declares no other orientation option).
        return kit::chainOfAtLeast(ctx, 3, "the neck", " (a neck joint, the head, the head tip)").has_value() &&
               readChainOrient(ctx).has_value();
    }

    void generate(BuildContext& ctx) const override
    {
        const auto chain = *ctx.structure("chain");
        const auto points = *kit::positions(ctx, chain);
        const Vec3 side = sideAxis(ctx, chain.front());
        const auto frames = kit::sideFrames(points, side);
        const std::size_t head = chain.size() - 2;
        const bool spline = ctx.optionBool("spline");
        // orient_neck: the FK controls turn about the neck's own axes (X
        // along it); off, about the world's, like the chest and the COG.
        const bool orient = ctx.optionBool("orient_neck");
        const Mat4 turn = axisTurn(*readChainOrient(ctx, false));
        if (!spline && ctx.optionInt("bones") > 0)
            ctx.warning("bones needs spline: without it the neck keeps one skin joint per neck guide", "bones");

        RigNodeIndex parent = ctx.hookNode();
        std::vector<RigNodeIndex> fk;
        for (std::size_t i = 0; i < head; ++i) {
            const Mat4 frame = orient ? frames[i] * turn : kit::uprightFrame(points[i]);
            const kit::Control control = kit::addControl(ctx, "fk." + std::to_string(i), "", int(i) + 1, parent, frame, chain[i]);
            kit::animate(ctx, control, kit::kRotate); // FK: rotation only
            parent = control.ctrl;
            fk.push_back(parent);
            if (!spline) {
                kit::addSkin(ctx, std::to_string(i), "", int(i) + 1, parent, frames[i], chain[i]);
                ctx.setHook(chain[i], parent);
            }
        }
        // The head's position follows the space head_point_space picks, its
        // orientation the one head_space picks (configure() wires both).
        const auto pointGroup = ctx.createNode(RigNodeKind::Group, "spaces.head_point",
                                               ctx.nodeName(model::NameRole::Group, "head_point_space"), parent, frames[head], chain[head]);
        const auto spaceGroup = ctx.createNode(RigNodeKind::Group, "spaces.head", ctx.nodeName(model::NameRole::Group, "head_space"),
                                               pointGroup, frames[head], chain[head]);
        const Mat4 headFrame = headControlFrame(ctx, frames[head], chain[head]);
        const kit::Control headControl = kit::addControl(ctx, "head", "head", {}, spaceGroup, headFrame, chain[head]);
        // The head turns on the neck; on a spline neck it also goes where the
        // animator puts it (the neck bends and stretches to follow).
        kit::animate(ctx, headControl, spline ? kit::kTranslate | kit::kRotate : kit::kRotate);
        // What the head controller drives keeps the head joint's frame: with
        // head_orient other than `joint`, a group in that frame under the
        // controller carries the head joint, the spline's end (whose axis
        // rigidity reads), the hooks and the head space, so only the
        // controller's channels change.
        const RigNodeIndex headCtrl = headControl.ctrl;
        RigNodeIndex headDriver = headCtrl;
        if (headFrame != frames[head])
            headDriver = ctx.createNode(RigNodeKind::Group, "mch.follow.head", ctx.markedName("follow", "head"), headCtrl, frames[head],
                                        chain[head]);
        if (spline) {
            // The spline reads its base's axes: with aim_axis / up_axis it
            // follows a group in the neck's own frame under the first control.
            RigNodeIndex base = fk.front();
            if (orient && turn != Mat4(1.0))
                base = ctx.createNode(RigNodeKind::Group, "mch.follow.fk.0", ctx.markedName("follow", "", 1), base, frames[0], chain[0]);
            addSplineNeck(ctx, chain, points, frames, side, headCtrl, {base, headDriver});
        }
        kit::addSkin(ctx, "head", "head", {}, headDriver, frames[head], chain[head]);
        ctx.setHook(chain[head], headDriver);
        ctx.setHook(chain.back(), headDriver);
        ctx.defineSpace("head", headDriver);
    }

    void configure(BuildContext& ctx) const override
    {
        const auto point = ctx.findNode("spaces.head_point");
        const auto group = ctx.findNode("spaces.head");
        const auto headCtrl = ctx.findNode(ctx.optionBool("do_ctrl") ? "ctrls.head" : "roots.head");
        if (!point || !group || !headCtrl || !ctx.optionBool("space_switch"))
            return; // without space_switch the head simply rides on the neck
        // Space 0 is the neck the head hangs from; the others are named spaces.
        const RigNodeIndex neck = ctx.node(*point).parent;
        kit::addSpaceSwitch(ctx, *point, *headCtrl, "head_point_space", "cns.head_point_space", neck, kHeadSpaces, false,
                            "point_space");
        kit::addSpaceSwitch(ctx, *group, *headCtrl, "head_space", "cns.head_space", neck, kHeadSpaces, true);
    }

private:
    // The spline from the neck's base control to the head (targets: the head
    // controller or the group in the head joint's frame under it) carries
    // the neck joints: the neck bends and stretches to wherever the head goes
    // (the other neck controls carry the head in neck space). Its stretch,
    // stretch mode and end rigidities are attributes of `headCtrl` (the head
    // controller) and the instance's options; with `bones` the skin joints
    // ride on a chain of their own along it, spread by bones_length.
    static void addSplineNeck(BuildContext& ctx, const std::vector<model::JointId>& chain, const std::vector<Vec3>& points,
                              const std::vector<Mat4>& frames, const Vec3& side, RigNodeIndex headCtrl,
                              const std::vector<RigNodeIndex>& targets)
    {
        const std::size_t head = chain.size() - 2;
        const auto bones = static_cast<std::size_t>(std::max(0LL, ctx.optionInt("bones")));
        model::SplineConstraint settings{.stretch = ctx.addAttribute(headCtrl, "stretch", ctx.optionBool("default_stretch") ? 1.0 : 0.0, 0.0, 1.0)};
        settings.scaleStretch = ctx.optionString("stretch_mode") == "scale";
        if (ctx.optionBool("rigidity")) {
            settings.rigidityStart = ctx.addAttribute(headCtrl, "rigidity_dn", ctx.optionFloat("rigidity_dn"), 0.0, 1.0);
            settings.rigidityEnd = ctx.addAttribute(headCtrl, "rigidity_up", ctx.optionFloat("rigidity_up"), 0.0, 1.0);
        }
        std::vector<RigNodeIndex> driven;
        RigNodeIndex drvParent = ctx.hookNode();
        for (std::size_t i = 0; i <= head; ++i) {
            drvParent = kit::addSetup(ctx, RigNodeKind::Joint, "drv." + std::to_string(i), "drv", int(i) + 1, drvParent, frames[i], chain[i]);
            driven.push_back(drvParent);
            if (i == head)
                break;
            if (bones == 0)
                kit::addSkin(ctx, std::to_string(i), "", int(i) + 1, drvParent, frames[i], chain[i]);
            ctx.setHook(chain[i], drvParent);
        }
        ctx.addConstraint("cns.spline", driven, targets, settings);
        if (bones == 0)
            return;
        const auto length = kit::parseBonesLength(ctx.optionString("bones_length")).value_or(kit::BonesLength::Equal);
        const kit::Spread spread = kit::spreadAlong(std::vector<Vec3>(points.begin(), points.begin() + std::ptrdiff_t(head) + 1), bones, length);
        const auto boneFrames = kit::sideFrames(spread.at, side);
        std::vector<RigNodeIndex> def;
        RigNodeIndex defParent = ctx.hookNode();
        for (std::size_t k = 0; k <= bones; ++k) {
            const model::JointId source = k == bones ? chain[head] : chain[spread.segment[k]];
            defParent = kit::addSetup(ctx, RigNodeKind::Joint, "def." + std::to_string(k), "def", int(k) + 1, defParent, boneFrames[k], source);
            def.push_back(defParent);
            if (k < bones)
                kit::addSkin(ctx, std::to_string(k), "", int(k) + 1, defParent, boneFrames[k], source);
        }
        ctx.addConstraint("cns.bones", def, targets, settings);
    }
};

} // namespace

std::unique_ptr<TemplateBuilder> makeNeckBuilder() { return std::make_unique<NeckBuilder>(); }

} // namespace rs::rigging
