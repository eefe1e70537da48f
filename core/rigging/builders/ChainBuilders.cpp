// rig.spline (digit.finger and digit.hand are in HandBuilders.cpp).
#include "rigging/builders/Builders.h"

#include "rigging/builders/BuilderKit.h"
#include "rigging/builders/ChainOrient.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace rs::rigging {

namespace {

using model::JointId;
using model::RigNodeIndex;
using model::RigNodeKind;

class SplineBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                            const std::map<std::string, Value>& guides) const override
    {
        // A tail: back (-Z) and slightly down from where it hangs.
        const int count = std::max(3, static_cast<int>(kit::guideNumber(guides, "number", 8)));
        const double length = kit::guideNumber(guides, "length", 0.8);
        std::vector<GuideJointSpec> specs;
        kit::appendChain(specs, count, Vec3(0.0, 0.0, -0.05), Vec3(0.0, -0.15 * length / (count - 1), -length / (count - 1)));
        return specs;
    }

    bool gather(const BuildContext& ctx) const override
    {
        return kit::chainOfAtLeast(ctx, 3, "a spline chain").has_value() && readChainOrient(ctx).has_value();
    }

    void generate(BuildContext& ctx) const override
    {
        const auto chain = *ctx.structure("chain");
        const auto points = *kit::positions(ctx, chain);
        const auto frames = orientFrames(ctx, chain); // orient, aim_axis, up_axis, up_dir, up_auto

        // Arc length along the guides, to spread the controllers evenly.
        std::vector<double> along{0.0};
        for (std::size_t i = 1; i < points.size(); ++i)
            along.push_back(along.back() + glm::length(points[i] - points[i - 1]));
        const int controls = static_cast<int>(ctx.optionInt("controls"));
        std::vector<RigNodeIndex> targets;
        RigNodeIndex parent = ctx.hookNode();
        for (int c = 0; c < controls; ++c) {
            const double at = along.back() * c / (controls - 1);
            std::size_t s = 0;
            while (s + 2 < points.size() && along[s + 1] < at)
                ++s;
            const double span = along[s + 1] - along[s];
            const double t = span > 1e-12 ? std::clamp((at - along[s]) / span, 0.0, 1.0) : 0.0;
            Mat4 frame = frames[s];
            frame[3] = Vec4(glm::mix(points[s], points[s + 1], t), 1.0);
            const kit::Control control = kit::addControl(ctx, "spline." + std::to_string(c), "", c + 1, parent, frame, chain[s]);
            kit::animate(ctx, control, kit::kTranslate | kit::kRotate); // a curve's controls: placed and turned
            parent = control.ctrl;
            targets.push_back(parent);
        }
        const model::AttributeRef stretch = ctx.addAttribute(targets.front(), "stretch", ctx.optionBool("stretch") ? 1.0 : 0.0, 0.0, 1.0);

        // The driven chain follows the curve; skin joints ride on it.
        std::vector<RigNodeIndex> driven;
        RigNodeIndex drvParent = ctx.hookNode();
        for (std::size_t i = 0; i < chain.size(); ++i) {
            drvParent = kit::addSetup(ctx, RigNodeKind::Joint, "drv." + std::to_string(i), "drv", int(i) + 1, drvParent, frames[i], chain[i]);
            driven.push_back(drvParent);
            kit::addSkin(ctx, std::to_string(i), "", int(i) + 1, drvParent, frames[i], chain[i]);
            ctx.setHook(chain[i], drvParent);
        }
        ctx.addConstraint("cns.spline", driven, targets, model::SplineConstraint{.stretch = stretch});
    }
};

} // namespace

std::unique_ptr<TemplateBuilder> makeSplineBuilder() { return std::make_unique<SplineBuilder>(); }

} // namespace rs::rigging
