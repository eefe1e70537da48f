#pragma once
// Internal to rs::eval: one constraint compiled for the evaluator (indices,
// rest offsets and rest lengths precomputed) and the solver of each kind. See
// model/Constraint.h for the semantics; RigProgram orders and runs them.
#include "eval/Affine.h"
#include "eval/Channels.h"
#include "model/Rig.h"

#include <limits>
#include <string>
#include <vector>

namespace rs::eval {

struct EvalState;

struct CompiledConstraint {
    model::ConstraintKind kind = model::ConstraintKind::Parent;
    std::vector<model::RigNodeIndex> driven, targets;
    std::vector<double> weights;       // normalised, one per target
    std::vector<Affine> offsets;       // per target: inverse(target rest) * driven rest
    std::vector<bool> identityOffset;  // per target: the offset is the identity (skipped)
    int weightChannel = -1, stretchChannel = -1, softChannel = -1, valueChannel = -1, breakChannel = -1,
        spaceChannel = -1, volumeChannel = -1, pinChannel = -1, slideChannel = -1; // -1: none
    int rigidityStartChannel = -1, rigidityEndChannel = -1; // spline: tangent rigidity at its ends (-1: 1)
    bool scaleStretch = false;                               // spline: stretch by scale
    double fraction = 0;               // twist
    bool nonRolling = false;           // twist: the start's roll relative to targets[2]
    bool bendy = false, bendyLower = false, byLength = true; // twist: rides the curve of its last six targets (BendyCurve.h)
    double restKink = 0.0;             // bendy twist: the angle between the two bones at rest, radians
    double volumePower = -0.5;         // IK: the volume compensation's power
    bool showAbove = false;            // visibility: shown while value > threshold, else while value < threshold
    double threshold = 0;
    bool orientOnly = false;           // space
    // Drive: the local rotation axis (0 x, 1 y, 2 z) unless it scales, the
    // response (model::DriveResponse's index) and its limits.
    int axis = 0, driveResponse = 0;
    double factor = 1, low = -std::numeric_limits<double>::infinity(), high = std::numeric_limits<double>::infinity();
    bool scaleDrive = false;
    // Driven key: the driver is valueChannel; the curve (tangents empty: linear).
    int drivenChannel = -1;
    std::vector<model::CurveKey> keys;
    std::vector<double> tangents;
    model::CurveInfinity pre = model::CurveInfinity::Constant, post = model::CurveInfinity::Constant;
    model::RigNodeIndex chainParent = model::kNoNode; // parent of driven[0]
    double restParentScale = 1.0;
    Mat3 restParentRotation{1.0};

    // IK: rest positions/rotations of the chain, rest lengths, rest pole and effector.
    std::vector<Vec3> restPositions;
    std::vector<Mat3> restRotations;
    std::vector<double> lengths;
    Vec3 restPole{0.0};
    Mat3 restEffectorRotation{1.0};
    std::vector<Mat3> restBoneFrames;  // per bone: (bone dir, plane normal) frames at rest
    std::vector<int> boneAxes;         // per bone: the joint's local axis along it (volume scales the others)
    Vec3 midOffset{0.0};               // 3-segment IK: joint 2 in the rest virtual-bone frame

    // Twist: rest relative rotation of targets[1] to targets[0], twist axis in targets[0]'s frame.
    int slot = 0;                      // this constraint's index (its scratch in EvalState)
    int shareTwistOf = -1;             // an earlier twist with the same targets: reuse its angle
    int biasChannel = -1;              // twist: the share's bias (model::TwistConstraint::bias), none: linear
    Quat restRelative{1, 0, 0, 0};
    Vec3 twistAxis{1, 0, 0};
    Vec3 restDelta{0.0};
    Quat restFromReference{1, 0, 0, 0}; // non-rolling twist: the start's rest rotation relative to targets[2]

    // Spline: rest tangents in each control's frame, per-driven curve parameter,
    // rest arc length and offset from the curve frame.
    std::vector<Vec3> localTangents;
    std::vector<double> parameters, restArc;
    double restLength = 0.0; // the curve's length at rest
    std::vector<Affine> curveOffsets;
    int samplesPerSegment = 12;

    // Carry (OffsetCarry.h): per carried node, the node, its first transform
    // channel and its rest offset from its pivot (targets[k]).
    std::vector<model::RigNodeIndex> carried;
    std::vector<int> carriedChannels;
    std::vector<Affine> carriedOffsets;

    // Aim: axes and rest offset (offsets[0]); weightChannel is its weight (-1: 1).
    int aimAxis = 0, upAxis = 1;

    // Roll: the driven's axle and forward axes (0 x, 1 y, 2 z), the wheel's
    // radius and its rest place in the reference's (targets[0]) rest frame.
    // weightChannel is the roll's amount. Path mode: its memory in
    // EvalState::rolls (pathSlot, -1 in axis mode) and the longest step that
    // rolls (metres, the circumference when the settings say 0).
    int axle = 0, forward = 2;
    double radius = 1.0;
    Vec3 restInReference{0.0};
    // Path mode: the wheel's rest up (its third axis, from the ground contact
    // to the centre) in the reference's rest frame: the ground plane it rolls
    // on is across it, whichever way the rig or the wheel stands.
    Vec3 upInReference{0.0, 1.0, 0.0};
    int pathSlot = -1;
    double jump = 0.0;
};

// Reads the typed settings of `rc` into `c` (its kind, driven and targets
// already set): attribute channels resolved, weights normalised, rest offsets
// measured. False, with an error naming the constraint and the attribute for
// each reference that is not a custom attribute of its node.
bool readSettings(const model::RigConstraint& rc, const model::Rig& rig, const ChannelLayout& channels,
                  const std::vector<Affine>& restWorld, CompiledConstraint& c, Diagnostics& diagnostics);
// Fills the rest data of `c` (offsets, lengths, spline parameters) from the rig's
// rest pose; returns an error message, empty when the constraint is usable.
std::string prepareConstraint(CompiledConstraint& c, const model::Rig& rig, const std::vector<Affine>& restWorld);
void solveConstraint(const CompiledConstraint& c, const Pose& pose, EvalState& state);

// Rotation helpers shared with the pose tools.
Quat rotationOf(const Affine& a);
Mat3 frameFromAxes(const Vec3& x, const Vec3& normal); // X along x, Z as close to normal as X allows
// The shortest-arc rotation taking unit vector `from` onto unit vector `to`
// (about any perpendicular axis when they are opposite; AimSolver.cpp).
Quat shortestArc(const Vec3& from, const Vec3& to);

} // namespace rs::eval
