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
                     const std::vector<Mat4>& frames, int count, RigNodeIndex parent)
{
    Controls out;
    out.along.push_back(0.0);
    for (std::size_t i = 1; i < points.size(); ++i)
        out.along.push_back(out.along.back() + glm::length(points[i] - points[i - 1]));
    const std::vector<double>& along = out.along;
    for (int c = 0; c < count; ++c) {
        const double at = along.back() * c / (count - 1);
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
                                         const Controls& controls, bool tweakers)
{
    std::vector<RigNodeIndex> curve;
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
        if (share < 1e-9 || share > 1.0 - 1e-9)
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
    return curve;
}

std::vector<RigNodeIndex> addDrivenChain(BuildContext& ctx, const std::vector<JointId>& chain, const std::vector<Mat4>& frames,
                                         bool fk)
{
    std::vector<RigNodeIndex> driven;
    RigNodeIndex parent = ctx.hookNode();
    for (std::size_t i = 0; i < chain.size(); ++i) {
        const std::string index = std::to_string(i);
        parent = kit::addSetup(ctx, RigNodeKind::Joint, "drv." + index, "drv", int(i) + 1, parent, frames[i], chain[i]);
        driven.push_back(parent);
        RigNodeIndex carrier = parent;
        if (fk) {
            const kit::Control control = kit::addControl(ctx, "fk." + index, "fk", int(i) + 1, parent, frames[i], chain[i]);
            kit::animate(ctx, control, kit::kRotate);
            carrier = control.ctrl;
        }
        kit::addSkin(ctx, index, "", int(i) + 1, carrier, frames[i], chain[i]);
        ctx.setHook(chain[i], carrier);
    }
    return driven;
}

} // namespace rs::rigging::spline
