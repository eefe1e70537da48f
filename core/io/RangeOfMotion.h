#pragma once
// The range-of-motion clip an export carries (ExportOptions::rangeOfMotion):
// the keyed poses, planned from the rig's own channels, limits, switches and
// constraints (no template or node names are looked at).
//
// The clip starts from a start pose (the guide's test pose, with the rig's
// settings as that pose has them: ik_blend, stretch, spaces) and exercises
// each controller in node order, one motion per channel:
//  - a channel the rig limits goes to its limits (a foot's roll -90..90, a
//    finger's curl -30..120); a custom channel is exercised only when it
//    drives something (a drive constraint's value), never a setting (blend
//    weights, spaces, stretch, soft IK, break angles keep the start values);
//  - an unlimited rotation goes +-90 degrees about a limb's hinge axis (the FK
//    control's local axis nearest the IK chain's bend normal), +-30 degrees
//    about any other axis; scale channels are not exercised;
//  - an unlimited translation goes a quarter of the skeleton's size each way,
//    or, for a control carrying aim goals (a finger's or an eye's target:
//    an aim constraint's goal is the control or hangs from it, the aimed node
//    does not), as far as the aimed chain reaches (the farthest rest distance
//    from an aimed node to the control): a talon's target goes 11 cm, not
//    half a metre that would pull its goals through the phalanges;
//  - every peak is cut back (bisection) until no deform joint lies more than
//    0.5% farther from its parent than at rest and every IK goal stays within
//    the chain's reach, so IK goals stay reachable and root or fly moves never
//    stretch a limb; a control whose moves only pass this with its limbs in FK
//    (a fly control turning a body whose hands are held by IK) is exercised
//    with every FK/IK-switched chain snapped to FK;
//  - FK controls of a switched chain (the FK side of blend constraints) are
//    exercised with the chain switched to FK (FK snapped onto the IK pose
//    first, so the switch moves nothing) and switched back after; IK controls
//    (the nodes an IK or spline constraint reads) with the chain in IK;
//  - a peak is also cut back until no deform joint comes closer than half its
//    rest distance to its skin parent along the rest direction, in the
//    parent's frame, at the peak or on the way to it (a chain folded back on
//    itself: a tweaker or spline controller pulling a curve past its
//    neighbours, the vehicle shutter's track folding with its slats turned
//    over, the antenna's tip folding behind the joint before it and out
//    again; this also keeps a body control from driving its joint through
//    the root joint below it), unless the start pose already has it so;
//  - a peak is also cut back until no deform joint flips on the way to it
//    (turns more than 45 degrees, in its skin parent's frame as its exported
//    track has it, in a tenth of the way, a frame at 30 fps: a solver's twist,
//    up vector or aim giving way, e.g. the quadruped's spline tail half
//    turned, a world-held aim target with the hand swept past it);
//  - a motion that moves no deform joint is left out (no dead segments).
// Keys sit `framesPerKey` frames apart on a grid of `framesPerSecond`; every
// peak is a key (peak, opposite peak, start), and a channel that would turn
// more than 120 degrees from one key to the next goes through the start
// between its peaks (peak, start, opposite peak, start), so interpolating
// the joints' rotations never takes the wrong way round; so does a channel
// whose way from one peak straight to the other (twice as fast as the way
// from the start to each) flips a joint or folds a chain.
#include "eval/RigProgram.h"
#include "model/Rig.h"

#include <functional>
#include <string>
#include <vector>

namespace rs::io {

// A controller's part of the clip: keys [firstKey, lastKey] (inclusive; the
// first is the start pose the previous part ended on).
struct RangeOfMotionPart {
    model::RigNodeIndex control = model::kNoNode;
    std::size_t firstKey = 0;
    std::size_t lastKey = 0;
};

struct RangeOfMotionPlan {
    std::vector<eval::Pose> keys;          // keys[0] is the start pose, and so is the last
    std::vector<RangeOfMotionPart> parts;  // one per exercised controller, in key order
};

// The frames between two keys for a frame rate (about a third of a second,
// even, so a resampling at half the rate still lands on every key).
int framesPerKey(double framesPerSecond);

// `start` has program.channels().size() values. `progress` as ExportOptions';
// false cancels (an empty plan is returned).
RangeOfMotionPlan planRangeOfMotion(const model::Rig& rig, const eval::RigProgram& program, const eval::Pose& start,
                                    const std::function<bool(double)>& progress = {});

// The largest relative stretch of the rig in `state`: max over deform joints
// of (distance to parent / rest distance - 1) and over IK constraints of
// (goal distance / chain reach - 1 + 0.005). What the plan keeps at or below
// 0.005 (or the start pose's own measure when that is larger): joints 0.5%
// longer at most, goals never past the chain's reach.
// IK constraints count only while their chain is blended in (a blend weight
// above 0, or no blend). `state` is the evaluation of `pose`.
double stretchOf(const model::Rig& rig, const eval::RigProgram& program, const eval::Pose& pose, const eval::EvalState& state);

} // namespace rs::io
