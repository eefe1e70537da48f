#include "rigging/builders/SplinePath.h"

#include "rigging/builders/BuilderKit.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <string>

namespace rs::rigging::spline {

using model::JointId;
using model::RigNodeIndex;
using model::RigNodeKind;

namespace {

// One animator's control: kit::addControl, or with `stacks` a control stack
// (`chained`: its parent is the previous link's controller).
struct Made {
    kit::Control control;
    RigNodeIndex follow = model::kNoNode;     // what constraints and the curve follow
    RigNodeIndex skinParent = model::kNoNode; // what a skin joint on it hangs under
};
Made addOne(BuildContext& ctx, const ControlNodeOptions* stacks, const std::string& key, const std::string& token, int index,
            RigNodeIndex parent, const Mat4& frame, JointId source, bool chained)
{
    if (!stacks) {
        const kit::Control c = kit::addControl(ctx, key, token, index, parent, frame, source);
        return {c, c.ctrl, c.ctrl};
    }
    const ControlStack stack = addControlStack(ctx, *stacks, key, token, index, parent, frame, source, chained);
    Made made{stack.control(), stack.skinParent, stack.skinParent};
    // flip_orient reflects the controller's frame; constraints blend
    // rotations, so they follow a group with the mirror frame under it (on
    // both sides, so both have the same nodes). A group after `c` has it already.
    if (stacks->flipOrient && stacks->below.empty())
        made.follow = ctx.createNode(RigNodeKind::Group, "mch.follow." + key, ctx.markedName("follow", token, index), stack.skinParent,
                                     frame, source);
    return made;
}

// Chained tweakers: tweaker i's carry group takes the offsets of the
// tweakers before it, each about its ride; eased out, the second to last
// tweaker's ride (its ease group) takes the last tweaker's.
void addCarries(BuildContext& ctx, const std::vector<RigNodeIndex>& rides, const std::vector<RigNodeIndex>& carries,
                const std::vector<RigNodeIndex>& tweaks, bool easedOut)
{
    const std::size_t last = tweaks.size() - 1;
    if (easedOut && last >= 2)
        ctx.addConstraint("cns.ease." + std::to_string(last - 1), {rides[last - 1]}, {rides[last]},
                          model::CarryConstraint{.carried = {tweaks[last]}});
    for (std::size_t i = 1; i <= last; ++i) {
        const auto before = std::ptrdiff_t(i);
        ctx.addConstraint("cns.carry." + std::to_string(i), {carries[i]}, std::vector<RigNodeIndex>(rides.begin(), rides.begin() + before),
                          model::CarryConstraint{.carried = std::vector<RigNodeIndex>(tweaks.begin(), tweaks.begin() + before)});
    }
}

} // namespace

Vec3 rootNormal(const BuildContext& ctx, JointId root) { return kit::guideAxis(ctx, root, 2, Vec3(0.0, 0.0, 1.0)); }

Controls addControls(BuildContext& ctx, const std::vector<JointId>& chain, const std::vector<Vec3>& points,
                     const std::vector<Mat4>& frames, int count, RigNodeIndex parent, bool byGuide, const ControlNodeOptions* stacks)
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
        const Made made = addOne(ctx, stacks, "spline." + std::to_string(c), "", c + 1, parent, frame, chain[s], c > 0);
        kit::animate(ctx, made.control, kit::kTranslate | kit::kRotate); // a curve's controls: placed and turned
        parent = made.control.ctrl;
        out.nodes.push_back(made.follow);
        out.controllers.push_back(parent);
        out.at.push_back(at);
    }
    return out;
}

std::vector<RigNodeIndex> addCurvePoints(BuildContext& ctx, const std::vector<JointId>& chain, const std::vector<Mat4>& frames,
                                         const Controls& controls, bool tweakers, Easing easing, const TweakerStyle& style)
{
    std::vector<RigNodeIndex> curve, points;
    std::vector<RigNodeIndex> rides, carries, tweaks; // chained: each tweaker's ride (its pivot), carry group, controller
    const std::size_t last = chain.size() - 1;
    const bool chained = tweakers && style.chained;
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
        RigNodeIndex holder = point;
        if (chained && easing.out && i + 1 == last && i > 0) // takes the last tweaker's offset, below
            holder = kit::addSetup(ctx, RigNodeKind::Group, "mch.ease." + index, "ease", int(i) + 1, holder, frames[i], chain[i]);
        rides.push_back(holder);
        if (chained && i > 0)
            holder = kit::addSetup(ctx, RigNodeKind::Group, "mch.carry." + index, "carry", int(i) + 1, holder, frames[i], chain[i]);
        carries.push_back(holder);
        const Made tweak = addOne(ctx, style.stacks, "tweak." + index, "tweak", int(i) + 1, holder, frames[i], chain[i], false);
        kit::animate(ctx, tweak.control, kit::kTranslate | kit::kRotate);
        tweaks.push_back(tweak.control.ctrl);
        curve.push_back(tweak.follow);
    }
    // Eased points ride on their end tweaker; chained, on its curve point,
    // the tweaker's own offset reaching them through the carries below.
    const std::vector<RigNodeIndex>& ends = chained ? points : curve;
    for (std::size_t i = 1; i < last; ++i) {
        if (!eased(i))
            continue;
        std::vector<RigNodeIndex> on;
        if (easing.in && i == 1) on.push_back(ends.front());
        if (easing.out && i + 1 == last) on.push_back(ends.back());
        ctx.addConstraint("cns.curve." + std::to_string(i), {points[i]}, on, model::ParentConstraint{});
    }
    if (chained)
        addCarries(ctx, rides, carries, tweaks, easing.out);
    return curve;
}

std::vector<RigNodeIndex> addDrivenChain(BuildContext& ctx, const std::vector<JointId>& chain, const std::vector<Mat4>& frames,
                                         bool fk, const std::vector<JointId>& sources, const ControlNodeOptions* stacks)
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
        RigNodeIndex carrier = parent, skinParent = parent;
        if (fk) { // what hangs on the joint follows what its skin joint does (a mirror frame with flip_orient)
            const Made control = addOne(ctx, stacks, "fk." + index, "fk", int(i) + 1, parent, frames[i], source, false);
            kit::animate(ctx, control.control, kit::kRotate);
            carrier = control.follow;
            skinParent = control.skinParent;
        }
        kit::addSkin(ctx, index, "", int(i) + 1, skinParent, frames[i], source);
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
