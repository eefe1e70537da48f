// rig.spline (digit.finger and digit.hand are in HandBuilders.cpp).
#include "rigging/builders/Builders.h"

#include "rigging/builders/BuilderKit.h"
#include "rigging/builders/ChainOrient.h"
#include "rigging/builders/SplinePath.h"

#include <algorithm>

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
        const auto chain = kit::chainOfAtLeast(ctx, 3, "a spline chain");
        if (!chain || !readChainOrient(ctx))
            return false;
        if (ctx.optionBool("tweakers") && chain->size() > spline::kMaxCurvePoints) {
            ctx.error("tweakers put a curve point on every guide joint, at most " + std::to_string(spline::kMaxCurvePoints) +
                          "; this chain has " + std::to_string(chain->size()), "tweakers");
            return false;
        }
        return true;
    }

    void generate(BuildContext& ctx) const override
    {
        const auto chain = *ctx.structure("chain");
        const auto points = *kit::positions(ctx, chain);
        // orient, aim_axis, up_axis, up_dir, up_auto; up_dir left unset: the root guide's up axis, as before them.
        const auto frames = orientFrames(ctx, chain, false, true);
        const spline::Controls controls =
            spline::addControls(ctx, chain, points, frames, static_cast<int>(ctx.optionInt("controls")), ctx.hookNode());
        const model::AttributeRef stretch = ctx.addAttribute(controls.nodes.front(), "stretch", ctx.optionBool("stretch") ? 1.0 : 0.0, 0.0, 1.0);
        // The driven chain follows the curve; skin joints ride on it (on an FK control each with `fk`).
        const auto driven = spline::addDrivenChain(ctx, chain, frames, ctx.optionBool("fk"));
        // With tweakers the curve goes through a point on every guide joint
        // (following the controllers around it), each with a control on it.
        const std::vector<RigNodeIndex> through =
            ctx.optionBool("tweakers") ? spline::addCurvePoints(ctx, chain, frames, controls, true) : controls.nodes;
        ctx.addConstraint("cns.spline", driven, through, model::SplineConstraint{.stretch = stretch});
    }
};

} // namespace

std::unique_ptr<TemplateBuilder> makeSplineBuilder() { return std::make_unique<SplineBuilder>(); }

} // namespace rs::rigging
