// rig.spline (digit.finger and digit.hand are in HandBuilders.cpp).
#include "rigging/builders/Builders.h"

#include "rigging/builders/BuilderKit.h"
#include "rigging/builders/ChainOrient.h"
#include "rigging/builders/ControlNodes.h"
#include "rigging/builders/SplinePath.h"

#include "eval/SplineCurve.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <limits>

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
        if (!chain || !readChainOrient(ctx) || !readControlNodes(ctx))
            return false;
        if (tweakers(ctx) != "off" && chain->size() > spline::kMaxCurvePoints) {
            ctx.error("tweakers put a curve point on every guide joint, at most " + std::to_string(spline::kMaxCurvePoints) +
                          "; this chain has " + std::to_string(chain->size()), "tweakers");
            return false;
        }
        if (ctx.optionString("fk_easing") != "off" && tweakers(ctx) == "off")
            ctx.warning("fk_easing eases the end tweakers: it does nothing without tweakers", "fk_easing");
        if (ctx.optionInt("bones") == 1) {
            ctx.error("bones puts a skin joint at each end of the curve and between: 0 (one on every guide joint) or at least 2", "bones");
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
        // do_pose, add_nodes, parent_scale, rotate_order, flip_orient: every control's stack (gather checked them).
        const ControlNodeOptions stacks = readControlNodes(ctx).value_or(ControlNodeOptions{});
        const spline::Controls controls = spline::addControls(ctx, chain, points, frames, static_cast<int>(ctx.optionInt("controls")),
                                                              ctx.hookNode(), ctx.optionBool("uniform_ik"), &stacks);
        const model::AttributeRef stretch = ctx.addAttribute(controls.controllers.front(), "stretch", ctx.optionBool("stretch") ? 1.0 : 0.0, 0.0, 1.0);
        // With tweakers the curve goes through a point on every guide joint
        // (following the controllers around it), each with a control on it;
        // chained, each tweaker also carries the ones after it.
        const std::string easing = ctx.optionString("fk_easing");
        const std::vector<RigNodeIndex> through =
            tweakers(ctx) != "off"
                ? spline::addCurvePoints(ctx, chain, frames, controls, true,
                                         {.in = easing == "in" || easing == "in-out", .out = easing == "out" || easing == "in-out"},
                                         {.chained = tweakers(ctx) == "chained", .stacks = &stacks})
                : controls.nodes;
        // The driven chain follows the curve; skin joints ride on it (on an FK control each with `fk`).
        std::vector<RigNodeIndex> driven;
        if (const int bones = static_cast<int>(ctx.optionInt("bones")); bones >= 2) {
            std::vector<model::JointId> sources;
            const auto boneFrames = placeBones(ctx, chain, points, through, bones, sources);
            driven = spline::addDrivenChain(ctx, chain, boneFrames, ctx.optionBool("fk"), sources, &stacks);
        } else {
            driven = spline::addDrivenChain(ctx, chain, frames, ctx.optionBool("fk"), {}, &stacks);
        }
        ctx.addConstraint("cns.spline", driven, through, model::SplineConstraint{.stretch = stretch});
    }

private:
    // tweakers: off / unchained / chained (on and off load as unchained and off).
    static std::string tweakers(const BuildContext& ctx) { return ctx.optionString("tweakers"); }

    // `count` bone frames (bones) where bone_length puts them: on the guide
    // chain spread by guide joint (cvs), or on the rest curve through
    // `through` evenly by its parameter (parametric) or length (equal); each
    // turned by the orientation options as if a guide joint stood there, and
    // deriving from the guide joint before it (`sources`).
    static std::vector<Mat4> placeBones(const BuildContext& ctx, const std::vector<model::JointId>& chain,
                                        const std::vector<Vec3>& points, const std::vector<RigNodeIndex>& through, int count,
                                        std::vector<model::JointId>& sources)
    {
        const std::string mode = ctx.optionString("bone_length");
        std::vector<Vec3> at;
        std::vector<double> guideAt; // where each bone is along the guides, in guide joints (for its source and roll)
        if (mode != "cvs") {
            std::vector<eval::Affine> targets;
            for (RigNodeIndex node : through)
                targets.push_back(eval::Affine::fromMatrix(ctx.nodeWorld(node)));
            at = eval::restCurvePoints(targets, count, mode == "equal");
            for (const Vec3& p : at) // the nearest guide segment's start
                guideAt.push_back(double(nearestSegment(points, p)));
            if (at.size() != std::size_t(count)) { // no curve: two of its points at one place
                ctx.warning("the curve has two points at one place, so the bones are spread by guide joint (as with "
                            "bone_length: cvs) until they are apart", "bone_length");
                at.clear();
                guideAt.clear();
            }
        }
        if (at.empty()) { // cvs: along the guide chain, evenly by guide joint
            for (int j = 0; j < count; ++j) {
                const double g = double(points.size() - 1) * j / (count - 1);
                const std::size_t k = std::min(std::size_t(g), points.size() - 2);
                at.push_back(glm::mix(points[k], points[k + 1], g - double(k)));
                guideAt.push_back(g);
            }
        }
        std::vector<Mat4> standIns;
        for (std::size_t j = 0; j < at.size(); ++j) {
            const std::size_t k = j == 0 ? 0 : std::min(std::size_t(guideAt[j]), points.size() - 1);
            Mat4 m = rigidFrame(ctx.guideWorldMatrix(chain[k]));
            m[3] = Vec4(at[j], 1.0);
            standIns.push_back(m);
            sources.push_back(chain[k]);
        }
        return orientFrames(ctx, standIns, false, true);
    }

    static std::size_t nearestSegment(const std::vector<Vec3>& points, const Vec3& p)
    {
        std::size_t best = 0;
        double bestDistance = std::numeric_limits<double>::max();
        for (std::size_t k = 0; k + 1 < points.size(); ++k) {
            const Vec3 d = points[k + 1] - points[k];
            const double t = glm::dot(d, d) > 1e-18 ? std::clamp(glm::dot(p - points[k], d) / glm::dot(d, d), 0.0, 1.0) : 0.0;
            if (const double distance = glm::length(points[k] + d * t - p); distance < bestDistance)
                best = k, bestDistance = distance;
        }
        return best;
    }
};

} // namespace

std::unique_ptr<TemplateBuilder> makeSplineBuilder() { return std::make_unique<SplineBuilder>(); }

} // namespace rs::rigging
