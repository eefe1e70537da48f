#include "rigging/builders/SplinePath.h"

#include "rigging/builders/BuilderKit.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <string>

namespace rs::rigging::spline {

using model::JointId;
using model::RigNodeIndex;
using model::RigNodeKind;

Vec3 rootNormal(const BuildContext& ctx, JointId root) { return kit::guideAxis(ctx, root, 2, Vec3(0.0, 0.0, 1.0)); }

Controls addControls(BuildContext& ctx, const std::vector<JointId>& chain, const std::vector<Vec3>& points,
                     const std::vector<Mat4>& frames, int count, RigNodeIndex parent, bool byGuide)
{
    Controls out;
    out.along.push_back(0.0);
    for (std::size_t i = 1; i < points.size(); ++i)
        out.along.push_back(out.along.back() + glm::length(points[i] - points[i - 1]));
    const std::vector<double>& along = out.along;
    for (int c = 0; c < count; ++c) {
        double at = along.back() * c / (count - 1);
        if (byGuide) {
            const double g = double(points.size() - 1) * c / (count - 1);
            const std::size_t k = std::min(std::size_t(g), points.size() - 2);
            at = along[k] + (g - double(k)) * (along[k + 1] - along[k]);
        }
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
        out.nodes.push_back(parent);
        out.at.push_back(at);
    }
    return out;
}

std::vector<RigNodeIndex> addCurvePoints(BuildContext& ctx, const std::vector<JointId>& chain, const std::vector<Mat4>& frames,
                                         const Controls& controls, bool tweakers, Easing easing)
{
    std::vector<RigNodeIndex> curve, points;
    const std::size_t last = chain.size() - 1;
    auto eased = [&](std::size_t i) { return tweakers && ((easing.in && i == 1) || (easing.out && i + 1 == last)); };
    for (std::size_t i = 0; i < chain.size(); ++i) {
        const std::string index = std::to_string(i);
        const double at = controls.along[i];
        std::size_t c = 0;
        while (c + 2 < controls.at.size() && controls.at[c + 1] < at)
            ++c;
        const double span = controls.at[c + 1] - controls.at[c];
        const double share = span > 1e-12 ? std::clamp((at - controls.at[c]) / span, 0.0, 1.0) : 0.0;
        const RigNodeIndex point =
            kit::addSetup(ctx, RigNodeKind::Group, "mch.curve." + index, "curve", int(i) + 1, ctx.hookNode(), frames[i], chain[i]);
        points.push_back(point);
        if (eased(i)) {
            // on its end tweaker, made below
        } else if (share < 1e-9 || share > 1.0 - 1e-9)
            ctx.addConstraint("cns.curve." + index, {point}, {controls.nodes[share < 0.5 ? c : c + 1]}, model::ParentConstraint{});
        else
            ctx.addConstraint("cns.curve." + index, {point}, {controls.nodes[c], controls.nodes[c + 1]},
                              model::ParentConstraint{.weights = {1.0 - share, share}});
        if (!tweakers) {
            curve.push_back(point);
            continue;
        }
        const kit::Control tweak = kit::addControl(ctx, "tweak." + index, "tweak", int(i) + 1, point, frames[i], chain[i]);
        kit::animate(ctx, tweak, kit::kTranslate | kit::kRotate);
        curve.push_back(tweak.ctrl);
    }
    for (std::size_t i = 1; i < last; ++i) {
        if (!eased(i))
            continue;
        std::vector<RigNodeIndex> ends;
        if (easing.in && i == 1) ends.push_back(curve.front());
        if (easing.out && i + 1 == last) ends.push_back(curve.back());
        ctx.addConstraint("cns.curve." + std::to_string(i), {points[i]}, ends, model::ParentConstraint{});
    }
    return curve;
}

std::vector<RigNodeIndex> addDrivenChain(BuildContext& ctx, const std::vector<JointId>& chain, const std::vector<Mat4>& frames,
                                         bool fk, const std::vector<JointId>& sources)
{
    std::vector<RigNodeIndex> driven, carriers;
    if (frames.empty())
        return driven;
    RigNodeIndex parent = ctx.hookNode();
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const std::string index = std::to_string(i);
        const JointId source = sources.empty() ? chain[i] : sources[i];
        parent = kit::addSetup(ctx, RigNodeKind::Joint, "drv." + index, "drv", int(i) + 1, parent, frames[i], source);
        driven.push_back(parent);
        RigNodeIndex carrier = parent;
        if (fk) {
            const kit::Control control = kit::addControl(ctx, "fk." + index, "fk", int(i) + 1, parent, frames[i], source);
            kit::animate(ctx, control, kit::kRotate);
            carrier = control.ctrl;
        }
        kit::addSkin(ctx, index, "", int(i) + 1, carrier, frames[i], source);
        carriers.push_back(carrier);
    }
    for (std::size_t g = 0; g < chain.size(); ++g) { // one per guide joint, or the nearest (bones)
        std::size_t nearest = g;
        if (!sources.empty()) {
            const Vec3 at = ctx.guidePosition(chain[g]);
            nearest = 0;
            for (std::size_t i = 1; i < frames.size(); ++i)
                if (glm::length(Vec3(frames[i][3]) - at) < glm::length(Vec3(frames[nearest][3]) - at))
                    nearest = i;
        }
        ctx.setHook(chain[g], carriers[nearest]);
    }
    return driven;
}

} // namespace rs::rigging::spline
