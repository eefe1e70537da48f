// rig.slide: joints that slide along a path. Two guide joints make a straight
// rail with one sliding control (a door, a drawer, a seat: its translation
// along the rail is the slide, within limits in metres); three or more lay a
// curve through every guide joint, shaped by spline controllers (and tweakers),
// along which a chain of skin joints slides by a `slide` attribute, keeping
// its spacing along the arc unless it stretches (rig.spline's curve and
// model::SplineConstraint).
#include "rigging/builders/Builders.h"

#include "rigging/builders/BuilderKit.h"
#include "rigging/builders/SplinePath.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace rs::rigging {

namespace {

using model::JointId;
using model::RigNodeIndex;
using model::RigNodeKind;

constexpr int kTranslate = 0, kScale = 6; // first channel of each (ChannelSettings)
using spline::kMaxCurvePoints;

int axisIndex(const std::string& name) { return name == "z" ? 2 : name == "y" ? 1 : 0; }

// up_dir: auto (the world axis most across the rail) or a signed world axis.
Vec3 upDirection(const std::string& choice, const Vec3& rail)
{
    static const std::array<std::pair<const char*, Vec3>, 6> axes = {{{"+x", {1, 0, 0}}, {"-x", {-1, 0, 0}}, {"+y", {0, 1, 0}},
                                                                      {"-y", {0, -1, 0}}, {"+z", {0, 0, 1}}, {"-z", {0, 0, -1}}}};
    for (const auto& [name, direction] : axes)
        if (choice == name && glm::length(glm::cross(direction, rail)) > 1e-3)
            return direction;
    Vec3 best(1, 0, 0);
    for (const auto& [name, direction] : axes)
        if (std::abs(glm::dot(direction, rail)) < std::abs(glm::dot(best, rail)))
            best = direction;
    return best;
}

// The slide's limits in metres: [limit_min, limit_max], limit_max negative
// meaning `ahead` (the path's length past the sliding part).
std::pair<double, double> slideLimits(const BuildContext& ctx, double ahead)
{
    double low = ctx.optionFloat("limit_min"), high = ctx.optionFloat("limit_max");
    if (high < 0.0)
        high = ahead;
    if (low > high) {
        ctx.warning("limit_min (" + std::to_string(low) + " m) is above limit_max (" + std::to_string(high) + " m): the slide is held at limit_min", "limit_min");
        high = low;
    }
    return {low, high};
}

class SlideBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                            const std::map<std::string, Value>& guides) const override
    {
        const int count = std::clamp(static_cast<int>(kit::guideNumber(guides, "number", 6)), 2, int(kMaxCurvePoints));
        const double length = kit::guideNumber(guides, "length", 2.5);
        std::vector<GuideJointSpec> specs;
        if (count == 2) { // the rail's start, where the slid part rests, and its end, `length` forward
            kit::appendChain(specs, 2, Vec3(0.0), Vec3(0.0, 0.0, length));
            return specs;
        }
        // A path bending up a quarter turn from forward (+Z), its segments
        // `length` / (count - 1) long: 0.5 m by default, as long as a 0.5 m
        // rail's, so the manifest's control sizes (for the default guide:
        // ControlSize.cpp) give rails what they had when they were the default.
        const double step = 0.5 * std::numbers::pi / (count - 1);
        const double radius = length / (count - 1) / (2.0 * std::sin(0.5 * step));
        int parent = -1;
        Vec3 previous(0.0);
        for (int i = 0; i < count; ++i) {
            const Vec3 point(0.0, radius * (1.0 - std::cos(step * i)), radius * std::sin(step * i));
            parent = kit::appendJoint(specs, parent, point - previous);
            previous = point;
        }
        return specs;
    }

    bool gather(const BuildContext& ctx) const override
    {
        const auto chain = kit::chainOfAtLeast(ctx, 2, "a slide", " (the rail's start and end)");
        if (!chain)
            return false;
        if (chain->size() == 2 && ctx.optionString("aim") == ctx.optionString("up")) {
            ctx.error("the aim and up axes of a slide must differ", "up");
            return false;
        }
        if (chain->size() > kMaxCurvePoints) {
            ctx.error("a slide's path has at most " + std::to_string(kMaxCurvePoints) + " guide joints (a curve point each); it has " +
                          std::to_string(chain->size()), "number");
            return false;
        }
        return true;
    }

    void generate(BuildContext& ctx) const override
    {
        if (ctx.structure("chain")->size() == 2)
            generateRail(ctx);
        else
            generateCurve(ctx);
    }

private:
    // Two guide joints: one control whose translation along its aim axis is the slide.
    static void generateRail(BuildContext& ctx)
    {
        const auto chain = *ctx.structure("chain");
        const Vec3 start = ctx.guidePosition(chain.front()), end = ctx.guidePosition(chain.back());
        const double length = glm::length(end - start);
        const Vec3 rail = (end - start) / length;
        // The control's aim axis along the rail, its up axis towards up_dir.
        const int aim = axisIndex(ctx.optionString("aim")), upAxis = axisIndex(ctx.optionString("up"));
        const int third = 3 - aim - upAxis;
        Vec3 up = upDirection(ctx.optionString("up_dir"), rail);
        up = glm::normalize(up - rail * glm::dot(up, rail));
        Mat4 frame(1.0);
        frame[aim] = Vec4(rail, 0.0);
        frame[upAxis] = Vec4(up, 0.0);
        const bool cyclic = upAxis == (aim + 1) % 3;
        frame[third] = Vec4(cyclic ? glm::cross(rail, up) : glm::cross(up, rail), 0.0);
        frame[3] = Vec4(start, 1.0);

        const auto slide = kit::addControl(ctx, "slide", "", {}, ctx.hookNode(), frame, chain.front());
        kit::addSkin(ctx, "slide", "", {}, slide.ctrl, frame, chain.front());
        for (JointId joint : chain) // what hangs on the rail rides on the slide
            ctx.setHook(joint, slide.ctrl);
        if (slide.ctrl == slide.offset)
            return;

        const auto [low, high] = slideLimits(ctx, length);
        model::ChannelSettings& channels = ctx.channels(slide.ctrl);
        channels.limit(kTranslate + aim, low, high);
        // Animators slide it along the rail (and off it with do_translate), turn it, and scale it with do_scale.
        std::uint16_t animatable = std::uint16_t(1u << (kTranslate + aim)) | kit::kRotate;
        if (ctx.optionBool("do_translate"))
            animatable |= kit::kTranslate;
        if (ctx.optionBool("do_scale"))
            animatable |= kit::kScale;
        kit::animate(ctx, slide, animatable);
        if (!ctx.optionBool("do_translate")) {
            channels.lock(kTranslate + upAxis);
            channels.lock(kTranslate + third);
        }
        if (!ctx.optionBool("do_scale"))
            channels.lock(kScale, 3);
        std::string order = ctx.optionString("rotate_order");
        if (order == "auto")
            order = std::string{"xyz"[aim], "xyz"[upAxis], "xyz"[third]};
        if (const auto parsed = model::parseRotateOrder(order))
            channels.rotateOrder = *parsed;
    }

    // Three or more: a curve through every guide joint, a chain sliding on it.
    static void generateCurve(BuildContext& ctx)
    {
        const auto chain = *ctx.structure("chain");
        const auto points = *kit::positions(ctx, chain);
        const auto frames = kit::chainFrames(points, spline::rootNormal(ctx, chain.front()));
        const spline::Controls iks =
            spline::addControls(ctx, chain, points, frames, static_cast<int>(ctx.optionInt("controls")), ctx.hookNode());

        // A curve point on each guide joint, so the curve passes through them
        // all; with `tweakers` an animator's control rides on each.
        const std::vector<RigNodeIndex> curve = spline::addCurvePoints(ctx, chain, frames, iks, ctx.optionBool("tweakers"));

        // The sliding chain: skin joints on the first `sliders` guide joints;
        // the guides past them lay the path ahead, and what hangs on them
        // rides on the curve there.
        const auto wanted = ctx.optionInt("sliders");
        const std::size_t sliders = wanted <= 0 || std::size_t(wanted) > chain.size() ? chain.size() : std::size_t(wanted);
        const std::vector<JointId> sliding(chain.begin(), chain.begin() + std::ptrdiff_t(sliders));
        const std::vector<Mat4> slidingFrames(frames.begin(), frames.begin() + std::ptrdiff_t(sliders));
        const auto driven = spline::addDrivenChain(ctx, sliding, slidingFrames, ctx.optionBool("fk"));
        for (std::size_t i = sliders; i < chain.size(); ++i)
            ctx.setHook(chain[i], curve[i]);

        // The guides' length ahead is at most the curve's (a chord is never
        // longer than its arc): slid to the end, the chain stays on the curve.
        const auto [low, high] = slideLimits(ctx, iks.along.back() - iks.along[sliders - 1]);
        const RigNodeIndex holder = iks.nodes.front();
        const model::AttributeRef slide = ctx.addAttribute(holder, "slide", std::clamp(0.0, low, high), low, high);
        const model::AttributeRef stretch = ctx.addAttribute(holder, "stretch", ctx.optionBool("stretch") ? 1.0 : 0.0, 0.0, 1.0);
        ctx.addConstraint("cns.spline", driven, curve, model::SplineConstraint{.stretch = stretch, .slide = slide});
    }
};

} // namespace

std::unique_ptr<TemplateBuilder> makeSlideBuilder() { return std::make_unique<SlideBuilder>(); }

} // namespace rs::rigging
