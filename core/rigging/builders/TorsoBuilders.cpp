// spine.torso (neck.head: NeckBuilder.cpp; core.xform: XformBuilder.cpp).
#include "rigging/builders/Builders.h"

#include "rigging/builders/BuilderKit.h"
#include "rigging/builders/SkinSpread.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace rs::rigging {

namespace {

using model::RigNodeIndex;
using model::RigNodeKind;

// The side axis of a vertical chain: the X axis of its root guide (world X
// unless the rigger turned the root), so spines and necks never flip.
Vec3 sideAxis(const BuildContext& ctx, model::JointId root) { return kit::guideAxis(ctx, root, 0, Vec3(1.0, 0.0, 0.0)); }

// A control's frame at `at`: the spine's own frame there when the orient_*
// option `option` is on (its X along the spine), else the world's axes.
Mat4 controlFrame(const BuildContext& ctx, const std::string& option, const Mat4& spineFrame, const Vec3& at)
{
    Mat4 frame = ctx.optionBool(option) ? spineFrame : Mat4(1.0);
    frame[3] = Vec4(at, 1.0);
    return frame;
}

// Where the hips control pivots (the pivots option): at the hips (legacy),
// the first spine joint (spine1) or halfway up the spine (centered), and the
// spine segment that point lies on.
std::pair<Vec3, std::size_t> hipsPivot(const BuildContext& ctx, const std::vector<Vec3>& points)
{
    const std::string pivots = ctx.optionString("pivots");
    if (pivots == "spine1")
        return {points[1], 1};
    if (pivots == "centered")
        return kit::alongChain(points, 0.5);
    return {points.front(), 0};
}

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
        // The hips control turns about its pivot and carries the pelvis (a
        // group at the hips under it when it pivots elsewhere).
        const auto [pivot, pivotSegment] = hipsPivot(ctx, points);
        const auto hips = kit::addControl(ctx, "hips", "hips", {}, cog.ctrl, controlFrame(ctx, "orient_pelvis", frames[pivotSegment], pivot),
                                          chain.front());
        const RigNodeIndex pelvis = glm::length(pivot - points.front()) < 1e-9
                                        ? hips.ctrl
                                        : kit::addSetup(ctx, RigNodeKind::Group, "pivot.hips", "hips_base", {}, hips.ctrl, hipsFrame, chain.front());
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
        const auto ikChest = kit::addControl(ctx, "ik_chest", "ik_chest", {}, cog.ctrl,
                                             controlFrame(ctx, "orient_shoulders", frames.back(), points.back()), chain.back());
        kit::animate(ctx, ikChest, kit::kTranslate | kit::kRotate);
        const model::AttributeRef stretch = ctx.addAttribute(ikChest.ctrl, "stretch", ctx.optionBool("stretch") ? 1.0 : 0.0, 0.0, 1.0);
        const model::AttributeRef volume = ctx.addAttribute(ikChest.ctrl, "volume", ctx.optionBool("volume") ? 1.0 : 0.0, 0.0, 1.0);
        std::vector<RigNodeIndex> targets{pelvis};
        if (ctx.optionBool("mid")) {
            const auto [at, segment] = kit::alongChain(points, 0.5);
            const auto mid = kit::addControl(ctx, "ik_mid", "ik_mid", {}, cog.ctrl, controlFrame(ctx, "orient_spine", frames[segment], at),
                                             chain[segment]);
            kit::animate(ctx, mid, kit::kTranslate | kit::kRotate);
            ctx.addConstraint("cns.mid", {mid.offset}, {pelvis, ikChest.ctrl}, model::ParentConstraint{.weights = {0.5, 0.5}});
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
        // stretch_mode scale: the stretched spine's joints also grow along it.
        const bool scaleStretch = ctx.optionString("stretch_mode") == "scale";
        ctx.addConstraint("cns.ik", ik, targets, model::SplineConstraint{.stretch = stretch, .volume = volume, .scaleStretch = scaleStretch});
        for (std::size_t i = 0; i < n; ++i)
            ctx.addConstraint("cns.blend." + std::to_string(i), {blend[i]}, {fk[i], ik[i]},
                              model::BlendConstraint{.weight = blendWeight});

        // Skin: the pelvis follows the hips control, the spine the blended
        // chain, or `skin_joints` joints spread along it by a spline through it.
        kit::addSkin(ctx, "0", "hips", {}, pelvis, frames.front(), chain.front());
        const auto skinJoints = static_cast<std::size_t>(std::max(0LL, ctx.optionInt("skin_joints")));
        if (skinJoints == 0) {
            for (std::size_t i = 1; i < n; ++i)
                kit::addSkin(ctx, std::to_string(i), "", int(i), blend[i], frames[i], chain[i]);
        } else {
            const auto length = kit::parseBonesLength(ctx.optionString("bones_length")).value_or(kit::BonesLength::Equal);
            auto [at, segment] = kit::spreadAlong(points, skinJoints, length);
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
            ctx.addConstraint("cns.def", def, blend, model::SplineConstraint{.volume = volume, .scaleStretch = scaleStretch});
        }

        ctx.setHook(chain.front(), pelvis);
        for (std::size_t i = 1; i < n; ++i)
            ctx.setHook(chain[i], blend[i]);
        ctx.defineSpace("cog", cog.ctrl);
        ctx.defineSpace("hips", hips.ctrl);
        ctx.defineSpace("chest", blend.back());
    }
};

} // namespace

std::unique_ptr<TemplateBuilder> makeSpineBuilder() { return std::make_unique<SpineBuilder>(); }

} // namespace rs::rigging
