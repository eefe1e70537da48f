// spine.torso, neck.head and core.xform.
#include "rigging/builders/Builders.h"

#include "rigging/builders/BuilderKit.h"

#include <glm/geometric.hpp>

namespace rs::rigging {

namespace {

using model::RigNodeIndex;
using model::RigNodeKind;

// The side axis of a vertical chain: the X axis of its root guide (world X
// unless the rigger turned the root), so spines and necks never flip.
Vec3 sideAxis(const BuildContext& ctx, model::JointId root) { return kit::guideAxis(ctx, root, 0, Vec3(1.0, 0.0, 0.0)); }

class SpineBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                            const std::map<std::string, Value>& guides) const override
    {
        // Hips at 1 m (a 1.8 m human), chest about 0.5 m above, a slight S-curve.
        const int count = std::max(3, static_cast<int>(kit::guideNumber(guides, "number", 5)));
        const double height = kit::guideNumber(guides, "length", 0.5);
        std::vector<GuideJointSpec> specs;
        int parent = kit::appendJoint(specs, -1, Vec3(0.0, 1.0, 0.0));
        for (int i = 1; i < count; ++i) {
            const double bow = 0.015 * std::sin(3.14159265358979 * i / (count - 1)); // lumbar curve
            parent = kit::appendJoint(specs, parent, Vec3(0.0, height / (count - 1), i == 1 ? -bow : 0.0));
        }
        return specs;
    }

    bool gather(const BuildContext& ctx) const override
    {
        return kit::chainOfAtLeast(ctx, 3, "the spine", " (hips, one spine joint, chest)").has_value();
    }

    void generate(BuildContext& ctx) const override
    {
        const auto chain = *ctx.structure("chain");
        const auto points = *kit::positions(ctx, chain);
        const auto frames = kit::sideFrames(points, sideAxis(ctx, chain.front()));
        const std::size_t n = chain.size();
        const Mat4 hipsFrame = kit::uprightFrame(points.front());

        const auto cog = kit::addControl(ctx, "cog", "cog", {}, ctx.hookNode(), hipsFrame, chain.front());
        const auto hips = kit::addControl(ctx, "hips", "hips", {}, cog.ctrl, hipsFrame, chain.front());
        const model::AttributeRef blendWeight = ctx.addAttribute(cog.ctrl, "ik_blend", ctx.optionFloat("ik_blend"), 0.0, 1.0);

        // FK: one control per joint, each under the previous one.
        std::vector<RigNodeIndex> fk;
        RigNodeIndex parent = cog.ctrl;
        for (std::size_t i = 0; i < n; ++i) {
            parent = kit::addControl(ctx, "fk." + std::to_string(i), "fk", int(i) + 1, parent, frames[i], chain[i]).ctrl;
            fk.push_back(parent);
        }
        // IK-style torso: hips and chest controls drive a spline through the chain.
        const auto ikHips = kit::addControl(ctx, "ik_hips", "ik_hips", {}, cog.ctrl, hipsFrame, chain.front());
        const auto ikChest = kit::addControl(ctx, "ik_chest", "ik_chest", {}, cog.ctrl, kit::uprightFrame(points.back()), chain.back());
        const model::AttributeRef stretch = ctx.addAttribute(ikChest.ctrl, "stretch", ctx.optionBool("stretch") ? 1.0 : 0.0, 0.0, 1.0);
        std::vector<RigNodeIndex> ik, blend;
        RigNodeIndex ikParent = cog.ctrl, blendParent = cog.ctrl;
        for (std::size_t i = 0; i < n; ++i) {
            const std::string index = std::to_string(i);
            ikParent = kit::addSetup(ctx, RigNodeKind::Joint, "ik." + index, "ik", int(i) + 1, ikParent, frames[i], chain[i]);
            ik.push_back(ikParent);
            blendParent = kit::addSetup(ctx, RigNodeKind::Joint, "blend." + index, "blend", int(i) + 1, blendParent, frames[i], chain[i]);
            blend.push_back(blendParent);
        }
        ctx.addConstraint("cns.ik", ik, {ikHips.ctrl, ikChest.ctrl}, model::SplineConstraint{.stretch = stretch});
        for (std::size_t i = 0; i < n; ++i)
            ctx.addConstraint("cns.blend." + std::to_string(i), {blend[i]}, {fk[i], ik[i]},
                              model::BlendConstraint{.weight = blendWeight});

        // Skin: the pelvis follows the hips control, the spine the blended chain.
        kit::addSkin(ctx, "0", "hips", {}, hips.ctrl, frames.front(), chain.front());
        for (std::size_t i = 1; i < n; ++i)
            kit::addSkin(ctx, std::to_string(i), "", int(i), blend[i], frames[i], chain[i]);

        ctx.setHook(chain.front(), hips.ctrl);
        for (std::size_t i = 1; i < n; ++i)
            ctx.setHook(chain[i], blend[i]);
        ctx.defineSpace("cog", cog.ctrl);
        ctx.defineSpace("hips", hips.ctrl);
        ctx.defineSpace("chest", blend.back());
    }
};

const std::vector<std::string> kHeadSpaces = {"neck", "chest", "cog", "world"};

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
        return kit::chainOfAtLeast(ctx, 3, "the neck", " (a neck joint, the head, the head tip)").has_value();
    }

    void generate(BuildContext& ctx) const override
    {
        const auto chain = *ctx.structure("chain");
        const auto points = *kit::positions(ctx, chain);
        const auto frames = kit::sideFrames(points, sideAxis(ctx, chain.front()));
        const std::size_t head = chain.size() - 2;

        RigNodeIndex parent = ctx.hookNode();
        for (std::size_t i = 0; i < head; ++i) {
            parent = kit::addControl(ctx, "fk." + std::to_string(i), "", int(i) + 1, parent, frames[i], chain[i]).ctrl;
            kit::addSkin(ctx, std::to_string(i), "", int(i) + 1, parent, frames[i], chain[i]);
            ctx.setHook(chain[i], parent);
        }
        // The head's orientation follows the space the head_space option picks.
        const auto spaceGroup = ctx.createNode(RigNodeKind::Group, "spaces.head", ctx.nodeName(model::NameRole::Group, "head_space"),
                                               parent, frames[head], chain[head]);
        const auto headCtrl = kit::addControl(ctx, "head", "head", {}, spaceGroup, frames[head], chain[head]).ctrl;
        kit::addSkin(ctx, "head", "head", {}, headCtrl, frames[head], chain[head]);
        ctx.setHook(chain[head], headCtrl);
        ctx.setHook(chain.back(), headCtrl);
        ctx.defineSpace("head", headCtrl);
    }

    void configure(BuildContext& ctx) const override
    {
        const auto group = ctx.findNode("spaces.head");
        const auto headCtrl = ctx.findNode(ctx.optionBool("do_ctrl") ? "ctrls.head" : "roots.head");
        if (!group || !headCtrl)
            return;
        // Space 0 is the neck the group hangs from; the others are named spaces.
        kit::addSpaceSwitch(ctx, *group, *headCtrl, "head_space", "cns.head_space", ctx.node(*group).parent, kHeadSpaces, true);
    }
};

class XformBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                            const std::map<std::string, Value>&) const override
    {
        return {GuideJointSpec{-1, {}, {}, {}}};
    }

    bool gather(const BuildContext& ctx) const override { return ctx.structure("xform").has_value(); }

    void generate(BuildContext& ctx) const override
    {
        const model::JointId joint = ctx.structure("xform")->front();
        const Mat4 frame = rigidFrame(ctx.guideWorldMatrix(joint));
        const auto control = kit::addControl(ctx, "xform", "", {}, ctx.hookNode(), frame, joint);
        kit::addSkin(ctx, "xform", "", {}, control.ctrl, frame, joint);
        ctx.setHook(joint, control.ctrl);
    }
};

} // namespace

std::unique_ptr<TemplateBuilder> makeSpineBuilder() { return std::make_unique<SpineBuilder>(); }
std::unique_ptr<TemplateBuilder> makeNeckBuilder() { return std::make_unique<NeckBuilder>(); }
std::unique_ptr<TemplateBuilder> makeXformBuilder() { return std::make_unique<XformBuilder>(); }

} // namespace rs::rigging
