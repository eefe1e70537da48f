// spine.torso and neck.head (core.xform is in XformBuilder.cpp).
#include "rigging/builders/Builders.h"

#include "rigging/builders/BuilderKit.h"

#include <algorithm>
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
        const Vec3 side = sideAxis(ctx, chain.front());
        const auto frames = kit::sideFrames(points, side);
        const std::size_t n = chain.size();
        const Mat4 hipsFrame = kit::uprightFrame(points.front());

        const auto cog = kit::addControl(ctx, "cog", "cog", {}, ctx.hookNode(), hipsFrame, chain.front());
        const auto hips = kit::addControl(ctx, "hips", "hips", {}, cog.ctrl, hipsFrame, chain.front());
        kit::animate(ctx, cog, kit::kTranslate | kit::kRotate);
        kit::animate(ctx, hips, kit::kTranslate | kit::kRotate);
        const model::AttributeRef blendWeight = ctx.addAttribute(cog.ctrl, "ik_blend", ctx.optionFloat("ik_blend"), 0.0, 1.0);

        // FK: one control per joint, each under the previous one.
        std::vector<RigNodeIndex> fk;
        RigNodeIndex parent = cog.ctrl;
        for (std::size_t i = 0; i < n; ++i) {
            const kit::Control control = kit::addControl(ctx, "fk." + std::to_string(i), "fk", int(i) + 1, parent, frames[i], chain[i]);
            kit::animate(ctx, control, kit::kRotate); // FK: rotation only
            parent = control.ctrl;
            fk.push_back(parent);
        }
        // IK-style torso: the hips, an optional mid and the chest control drive a
        // spline through the chain; the mid follows the hips and chest halfway.
        const auto ikChest = kit::addControl(ctx, "ik_chest", "ik_chest", {}, cog.ctrl, kit::uprightFrame(points.back()), chain.back());
        kit::animate(ctx, ikChest, kit::kTranslate | kit::kRotate);
        const model::AttributeRef stretch = ctx.addAttribute(ikChest.ctrl, "stretch", ctx.optionBool("stretch") ? 1.0 : 0.0, 0.0, 1.0);
        const model::AttributeRef volume = ctx.addAttribute(ikChest.ctrl, "volume", ctx.optionBool("volume") ? 1.0 : 0.0, 0.0, 1.0);
        std::vector<RigNodeIndex> targets{hips.ctrl};
        if (ctx.optionBool("mid")) {
            const auto [at, segment] = kit::alongChain(points, 0.5);
            const auto mid = kit::addControl(ctx, "ik_mid", "ik_mid", {}, cog.ctrl, kit::uprightFrame(at), chain[segment]);
            kit::animate(ctx, mid, kit::kTranslate | kit::kRotate);
            ctx.addConstraint("cns.mid", {mid.offset}, {hips.ctrl, ikChest.ctrl}, model::ParentConstraint{.weights = {0.5, 0.5}});
            targets.push_back(mid.ctrl);
        }
        targets.push_back(ikChest.ctrl);
        std::vector<RigNodeIndex> ik, blend;
        RigNodeIndex ikParent = cog.ctrl, blendParent = cog.ctrl;
        for (std::size_t i = 0; i < n; ++i) {
            const std::string index = std::to_string(i);
            ikParent = kit::addSetup(ctx, RigNodeKind::Joint, "ik." + index, "ik", int(i) + 1, ikParent, frames[i], chain[i]);
            ik.push_back(ikParent);
            blendParent = kit::addSetup(ctx, RigNodeKind::Joint, "blend." + index, "blend", int(i) + 1, blendParent, frames[i], chain[i]);
            blend.push_back(blendParent);
        }
        ctx.addConstraint("cns.ik", ik, targets, model::SplineConstraint{.stretch = stretch, .volume = volume});
        for (std::size_t i = 0; i < n; ++i)
            ctx.addConstraint("cns.blend." + std::to_string(i), {blend[i]}, {fk[i], ik[i]},
                              model::BlendConstraint{.weight = blendWeight});

        // Skin: the pelvis follows the hips control, the spine the blended
        // chain, or `skin_joints` joints spread along it by a spline through it.
        kit::addSkin(ctx, "0", "hips", {}, hips.ctrl, frames.front(), chain.front());
        const auto skinJoints = static_cast<std::size_t>(std::max(0LL, ctx.optionInt("skin_joints")));
        if (skinJoints == 0) {
            for (std::size_t i = 1; i < n; ++i)
                kit::addSkin(ctx, std::to_string(i), "", int(i), blend[i], frames[i], chain[i]);
        } else {
            std::vector<Vec3> at;
            std::vector<std::size_t> segment;
            for (std::size_t k = 0; k <= skinJoints; ++k) {
                const auto [p, s] = kit::alongChain(points, double(k) / double(skinJoints));
                at.push_back(p);
                segment.push_back(s);
            }
            segment.back() = n - 1; // the top one is the chest's
            const auto defFrames = kit::sideFrames(at, side);
            std::vector<RigNodeIndex> def;
            RigNodeIndex defParent = cog.ctrl;
            for (std::size_t k = 0; k <= skinJoints; ++k) {
                defParent = kit::addSetup(ctx, RigNodeKind::Joint, "def." + std::to_string(k), "def", int(k) + 1, defParent,
                                          defFrames[k], chain[segment[k]]);
                def.push_back(defParent);
                if (k > 0)
                    kit::addSkin(ctx, std::to_string(k), "", int(k), defParent, defFrames[k], chain[segment[k]]);
            }
            ctx.addConstraint("cns.def", def, blend, model::SplineConstraint{.volume = volume});
        }

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
        const bool spline = ctx.optionBool("spline");

        RigNodeIndex parent = ctx.hookNode();
        std::vector<RigNodeIndex> fk;
        for (std::size_t i = 0; i < head; ++i) {
            const kit::Control control = kit::addControl(ctx, "fk." + std::to_string(i), "", int(i) + 1, parent, frames[i], chain[i]);
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
        const kit::Control headControl = kit::addControl(ctx, "head", "head", {}, spaceGroup, frames[head], chain[head]);
        // The head turns on the neck; on a spline neck it also goes where the
        // animator puts it (the neck bends and stretches to follow).
        kit::animate(ctx, headControl, spline ? kit::kTranslate | kit::kRotate : kit::kRotate);
        const auto headCtrl = headControl.ctrl;
        if (spline) {
            // A spline from the neck's base control to the head carries the
            // neck joints: the neck bends and stretches to wherever the head
            // goes (the other neck controls carry the head in neck space).
            std::vector<RigNodeIndex> driven, targets{fk.front(), headCtrl};
            RigNodeIndex drvParent = ctx.hookNode();
            for (std::size_t i = 0; i <= head; ++i) {
                drvParent = kit::addSetup(ctx, RigNodeKind::Joint, "drv." + std::to_string(i), "drv", int(i) + 1, drvParent, frames[i], chain[i]);
                driven.push_back(drvParent);
                if (i < head) {
                    kit::addSkin(ctx, std::to_string(i), "", int(i) + 1, drvParent, frames[i], chain[i]);
                    ctx.setHook(chain[i], drvParent);
                }
            }
            ctx.addConstraint("cns.spline", driven, targets, model::SplineConstraint{});
        }
        kit::addSkin(ctx, "head", "head", {}, headCtrl, frames[head], chain[head]);
        ctx.setHook(chain[head], headCtrl);
        ctx.setHook(chain.back(), headCtrl);
        ctx.defineSpace("head", headCtrl);
    }

    void configure(BuildContext& ctx) const override
    {
        const auto point = ctx.findNode("spaces.head_point");
        const auto group = ctx.findNode("spaces.head");
        const auto headCtrl = ctx.findNode(ctx.optionBool("do_ctrl") ? "ctrls.head" : "roots.head");
        if (!point || !group || !headCtrl)
            return;
        // Space 0 is the neck the head hangs from; the others are named spaces.
        const RigNodeIndex neck = ctx.node(*point).parent;
        kit::addSpaceSwitch(ctx, *point, *headCtrl, "head_point_space", "cns.head_point_space", neck, kHeadSpaces, false,
                            "point_space");
        kit::addSpaceSwitch(ctx, *group, *headCtrl, "head_space", "cns.head_space", neck, kHeadSpaces, true);
    }
};

} // namespace

std::unique_ptr<TemplateBuilder> makeSpineBuilder() { return std::make_unique<SpineBuilder>(); }
std::unique_ptr<TemplateBuilder> makeNeckBuilder() { return std::make_unique<NeckBuilder>(); }

} // namespace rs::rigging
