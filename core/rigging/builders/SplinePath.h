#pragma once
// The pieces of a spline rig that rig.spline and rig.slide share: the spline
// controllers spread along a guide chain, and the driven chain with its skin
// joints that a model::SplineConstraint moves along the curve.
#include "rigging/TemplateBuilder.h"
#include "rigging/builders/ControlNodes.h"

#include <vector>

namespace rs::rigging::spline {

// The Z axis of a chain's root guide: the bend axis used where the chain is straight.
Vec3 rootNormal(const BuildContext& ctx, model::JointId root);

struct Controls {
    std::vector<model::RigNodeIndex> nodes;       // what the curve follows: the controllers, or their follow groups
    std::vector<model::RigNodeIndex> controllers; // "ctrls.spline.<i>", each under the previous one (attributes go here)
    std::vector<double> at;                 // each one's length along the guides from the first guide, metres
    std::vector<double> along;              // each guide joint's length along the guides, metres
};
// `count` controllers spread evenly by length along the guide chain (`points`,
// with `frames` from kit::chainFrames), or with `byGuide` evenly by guide
// joint (controller c at guide joint c * (n - 1) / (count - 1), between two
// joints by its share of the segment: Mikan's uniform_ik), the first under
// `parent`; animators place and turn them. With `stacks` (rig.spline's
// control hierarchy options, ControlNodes.h) each is a control stack, the
// next hanging under its controller; the curve follows what a skin joint on
// it would (Controls::nodes): with flip_orient a group with the mirror frame
// under the controller ("mch.follow.spline.<i>"), as rotations blend there.
Controls addControls(BuildContext& ctx, const std::vector<model::JointId>& chain, const std::vector<Vec3>& points,
                     const std::vector<Mat4>& frames, int count, model::RigNodeIndex parent, bool byGuide = false,
                     const ControlNodeOptions* stacks = nullptr);

// The most targets a model::SplineConstraint takes: a curve through its
// guide joints (tweakers) has at most this many.
constexpr std::size_t kMaxCurvePoints = 16;

// A curve point ("mch.curve.<i>") on each guide joint of `chain` (with
// `frames`), so that the curve passes through them all: each follows the two
// spline controllers around it, shared by its length between them. With
// `tweakers` an animator's control ("ctrls.tweak.<i>", translations and
// rotations) rides on each point. Returns what the curve goes through: the
// tweakers, or the points.
// Easing (rig.spline's fk_easing, with tweakers): the second point rides on
// the first tweaker (`in`) and the second to last on the last (`out`),
// instead of on the spline controllers: a point eased both ways (a chain of
// three) follows both tweakers, half each.
struct Easing {
    bool in = false, out = false;
};
// rig.spline's tweakers: `chained` (Mikan's tweakers in a hierarchy), each
// tweaker also carries every tweaker after it, as an FK chain does, while
// each still rides on the spline controllers around it: a group
// "mch.carry.<i>" between curve point i and its tweaker takes the animated
// offsets of tweakers 0..i-1, each about its own place on the curve
// (model::CarryConstraint). With easing, the eased point rides on the end
// tweaker's curve point instead of the tweaker, and takes the end tweaker's
// offset through the chain (in) or a group "mch.ease.<i>" (out): the same
// curve as unchained while only the end tweaker moves. `stacks`: each
// tweaker a control stack (ControlNodes.h; null: an offset and a controller).
struct TweakerStyle {
    bool chained = false;
    const ControlNodeOptions* stacks = nullptr;
};
std::vector<model::RigNodeIndex> addCurvePoints(BuildContext& ctx, const std::vector<model::JointId>& chain,
                                                const std::vector<Mat4>& frames, const Controls& controls, bool tweakers,
                                                Easing easing = {}, const TweakerStyle& style = {});

// A driven joint ("drv.<i>", each under the previous one, the first under the
// instance's hook) and a skin joint on it ("skin.<i>") at each of `frames`;
// chain[i] hooks on drv.<i>. With `fk`, an FK control ("ctrls.fk.<i>",
// rotations) rides on each driven joint and carries its skin joint and hook,
// so animators turn each joint on top of the curve. Returns the driven
// joints, for the constraint.
// With `sources` (rig.spline's bones: as many as `frames`, which need not be
// one per guide joint), joint j derives from guide joint sources[j] and every
// guide joint of `chain` hooks on the carrier of the joint nearest to it.
// With `stacks`, each FK control is a control stack (ControlNodes.h), its
// skin joint under the stack's last group.
std::vector<model::RigNodeIndex> addDrivenChain(BuildContext& ctx, const std::vector<model::JointId>& chain,
                                                const std::vector<Mat4>& frames, bool fk = false,
                                                const std::vector<model::JointId>& sources = {},
                                                const ControlNodeOptions* stacks = nullptr);

} // namespace rs::rigging::spline
