#pragma once
// The constraints of a built rig, typed: one settings struct per kind holding
// exactly what the evaluator (rs::eval::RigProgram) reads for that kind, so a
// setting nothing reads cannot be written. Builders add them through
// rs::rigging::BuildContext::addConstraint; the evaluator solves them in
// dependency order after the node hierarchy; the rig dump writes every field
// by name.
//
// Nodes are indices into Rig::nodes. Units: metres; every angle a setting or
// an attribute holds is in degrees. A custom attribute is referenced by node
// and name (AttributeRef), never by a text path: compiling the rig fails with
// an error naming the constraint and the attribute when the node has no such
// attribute. A constraint whose settings do not fit (an IK with one target,
// weights that are not one per target, an aim whose aim and up axes are the
// same, a drive whose low limit is above its high one) or whose rest setup is
// degenerate is skipped by the evaluator with a warning.
#include "base/Identity.h"
#include "model/ConstraintRefs.h"
#include "model/DriveConstraints.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace rs::model {

// Parent, orient, point and scale constraints: driven[0] takes the weighted
// average of its targets' transforms (positions and scales averaged linearly,
// rotations as a normalised quaternion mix), each target's taken with the
// driven's rest offset from it.
//  - weights: the relative share of each target, in target order, normalised
//    to sum 1. Empty: equal shares. Otherwise exactly one per target (the
//    constraint is skipped with a warning if not); a sum <= 0 gives equal shares.
//  - keepOffset: true keeps the driven's rest offset from each target (the
//    rest pose is unchanged); false snaps it onto the targets.
struct ParentConstraint { // position, rotation and scale
    std::vector<double> weights{};
    bool keepOffset = true;
    bool operator==(const ParentConstraint&) const = default;
};
struct OrientConstraint { // rotation only
    std::vector<double> weights{};
    bool keepOffset = true;
    bool operator==(const OrientConstraint&) const = default;
};
struct PointConstraint { // position only
    std::vector<double> weights{};
    bool keepOffset = true;
    bool operator==(const PointConstraint&) const = default;
};
struct ScaleConstraint { // scale only
    std::vector<double> weights{};
    bool keepOffset = true;
    bool operator==(const ScaleConstraint&) const = default;
};

// FK/IK blend: driven[0] = mix(targets[0] (FK), targets[1] (IK)) by `weight`
// clamped to [0, 1]: 0 all FK, 1 all IK. Positions and scales mix linearly,
// rotations by a normalised quaternion lerp. Exactly two targets.
struct BlendConstraint {
    AttributeRef weight{};
    bool keepOffset = true; // as ParentConstraint's
    bool operator==(const BlendConstraint&) const = default;
};

// Limb IK. driven is the chain, root first, each joint a child of the one
// before: 3 joints (the analytic two-bone solution) or 4 (a quadruped hind
// leg: joint 2 keeps its place in the frame of a virtual bone from joint 1 to
// the end). targets = [effector, pole]: the end reaches for the effector's
// position and takes its rotation (rest offset kept); the pole sets the bend
// plane; an optional third target is the pin the middle joint (elbow, knee;
// joint 1) locks to. Every attribute is clamped to [0, 1].
struct IkConstraint {
    // 0: the chain stops at full reach; 1: the bones lengthen to reach the
    // effector; in between, part of the way. None: 0.
    std::optional<AttributeRef> stretch{};
    // The soft zone in metres (at the rig's rest scale) before full reach,
    // over which the reach eases out instead of snapping straight. None: 0
    // (hard IK).
    std::optional<AttributeRef> soft{};
    // Volume: a bone stretched by s (its length over its rest length) is
    // scaled across (its local Y and Z) by s^(volumePower * volume), so a
    // fully volume-preserving limb with the default power keeps its volume:
    // 1 / sqrt(s). None: 0.
    std::optional<AttributeRef> volume{};
    // Pin: the middle joint moves to targets[2] by this share (1: locked on
    // the pin, both bones then reaching from it); needs the third target.
    // None: 0.
    std::optional<AttributeRef> pin{};
    // The power of the volume compensation (Mikan's stomp_power), in [-1, 0]:
    // -0.5 is 1 / sqrt(s), -1 is 1 / s, 0 keeps the thickness. Clamped.
    double volumePower = -0.5;
    bool operator==(const IkConstraint&) const = default;
};

// A twist joint between targets[0] (segment start) and targets[1] (segment
// end): driven[0] sits `fraction` of the way along the segment (its rest
// offset kept) and turns by `fraction` of the end's twist about the bone
// relative to the start (taken within +-180 degrees). Consecutive twist
// constraints with the same targets share one twist angle.
//
// Non-rolling (an upper arm or thigh, whose start joint rolls with the
// shoulder or hip): targets = [start, end, reference], reference being what
// the limb hangs under (the clavicle side). The twist shared is then the
// start's own roll about its bone relative to the reference, measured from the
// frame that swings the start's rest frame (as seen from the reference) onto
// its bone by the shortest arc; driven[0] takes that frame turned by
// `fraction` of the roll. So a joint at the start (fraction 0) does not roll
// and one at the end (fraction 1) rolls fully, like the start joint itself:
// no candy wrapper at the shoulder. The swing is undefined when the bone
// points straight opposite its rest direction relative to the reference.
//
// Bendy (a limb's bend controls): six more targets follow the two or three
// above: [limb start, middle joint, limb end, tweak, tweak's space, bend
// control] (shoulder, elbow, wrist; the tweak control at the elbow and its
// offset parent). The joint then rides a curve instead of the straight
// segment: two cubic Hermite pieces through the segment's start, its bend
// control and its end, the tweak standing for the middle joint (the upper
// segment ends there, the lower starts there; `lower` says which). Tangents:
// at the limb's start and end along the bone; at the bend control along its
// rest direction of the segment, turned with it; at the tweak, the two bones'
// directions each turned towards the other until the angle between them is
// no more than at rest (so the curve is smooth through an elbow bent past its
// rest angle, and follows the bones when straighter), then turned by the
// tweak's own rotation in its space. Each tangent is as long as the chord it
// spans. Everything but the tweak's and the bend control's own channels comes
// from joint positions, so the curve does not depend on the bones' roll. At
// rest the curve is the straight segment travelled at constant speed and
// nothing moves. The joint sits at `fraction` of the curve by parameter or,
// with byLength, by arc length; it keeps its twist (above), swung by the
// shortest arc from its bone onto the curve's tangent.
struct TwistConstraint {
    double fraction = 0.0; // 0 at targets[0], 1 at targets[1]
    bool nonRolling = false; // the start's roll relative to targets[2] (above)
    bool bendy = false; // rides the curve of the six last targets (above)
    bool lower = false; // bendy: the lower segment (from the tweak), else the upper (to it)
    bool byLength = true; // bendy: `fraction` of the curve's arc length, else of its parameter
    // Shapes the share (a limb's advanced_twist): the joint turns by
    // fraction^(2^bias) of the twist instead of `fraction`, bias clamped to
    // [-1, 1]. 0 (and none) is linear; 1 (fraction squared) leaves more of the
    // twist to the end, -1 (its square root) moves it towards the start. The
    // joint's place along the segment does not change.
    std::optional<AttributeRef> bias{};
    bool operator==(const TwistConstraint&) const = default;
};

// Spline IK (spines, necks, tails, rig.slide's sliding chains): driven is a
// chain, root first; targets are 2 to 16 controls a cubic curve passes through
// (tangents along the controls' rest chain direction, its frame blending their
// rotations). Each joint keeps its rest offset from the curve frame.
struct SplineConstraint {
    // Clamped to [0, 1]. 1: each joint keeps its rest curve parameter, so the
    // chain stretches with the curve; 0: each keeps its rest arc length, so the
    // chain keeps its length and slides along the curve. None: 1.
    std::optional<AttributeRef> stretch{};
    // Squash and stretch keep the volume: with the chain stretched by s (the
    // curve's length over its rest length, by the stretch share), every
    // driven joint but the last is scaled across (its local Y and Z) by
    // s^(-volume / 2). The last keeps its size, so what hangs on it (a neck,
    // arms) does too. Clamped to [0, 1]. None: 0.
    std::optional<AttributeRef> volume{};
    // Slides the driven chain along the curve by this many metres of arc
    // (times the chain parent's scale; forward towards the last control,
    // negative back): each joint's arc position moves by it, and with stretch
    // by it times the curve's length over its rest length. A joint slid past
    // an end of the curve goes on straight along the end's tangent. None: 0.
    std::optional<AttributeRef> slide{};
    // Tangent rigidity at the first and last target (necks: at the base and
    // the head). 1: the curve leaves that end along the control's rest chain
    // direction, turning with the control; 0: it is free there, aiming along
    // the chord to its neighbouring control; in between the two directions
    // blend. At rest they agree, so the rest pose does not depend on it.
    // Clamped to [0, 1]. None: 1.
    std::optional<AttributeRef> rigidityStart{};
    std::optional<AttributeRef> rigidityEnd{};
    // Stretch by scale: every driven joint but the last is also scaled along
    // its local X axis (its bone) by the chain's stretch (as volume measures
    // it), so a stretched chain's joints grow with their spacing; off, they
    // only move apart and keep the chain parent's scale.
    bool scaleStretch = false;
    bool operator==(const SplineConstraint&) const = default;
};

// Space switch: driven[0] follows targets[i], i the `choice` enum attribute's
// value (rounded, clamped to the targets).
struct SpaceConstraint {
    AttributeRef choice{};
    bool orientOnly = false; // only the target's rotation: the driven keeps its own position and scale
    bool keepOffset = true;  // as ParentConstraint's
    bool operator==(const SpaceConstraint&) const = default;
};

// driven[0]'s `aim` axis points at targets[0]; its `up` axis towards
// targets[1] when there is one, else world +Y (target positions only). The
// driven's rest orientation relative to that frame is kept, so the rest pose
// is unchanged. `aim` and `up` must differ. `weight` (an attribute, its value
// clamped to 0..1; none: 1) blends by angle (slerp) between the rotation the
// driven's parent gives it (0) and the aimed one (1); its position and scale
// are its parent's either way.
struct AimConstraint {
    Axis aim = Axis::X;
    Axis up = Axis::Y;
    std::optional<AttributeRef> weight{};
    bool operator==(const AimConstraint&) const = default;
};

// Visibility driven by a channel: the driven nodes are shown only while
// `value` is below (or above) `threshold`, strictly. A limb's FK controls are
// shown while ik_blend < 1 and its IK controls while ik_blend > 0, so at full
// IK only the IK controls are seen, at full FK only the FK ones, and both in
// between. It places nothing: it has no targets, writes no transform and
// orders no other step; the evaluator writes EvalState::visible, which the
// viewport (drawing and picking in Rig mode) and the pickwalk honour. A node
// under several is shown when all of them hold. Visibility is not inherited:
// each node that hides has its own.
enum class ShowWhen : std::uint8_t { Below = 0, Above = 1 };
const char* showWhenName(ShowWhen when); // "below", "above"
struct VisibilityConstraint {
    AttributeRef value{};
    ShowWhen when = ShowWhen::Below;
    double threshold = 1.0; // in the attribute's unit
    bool operator==(const VisibilityConstraint&) const = default;
};

// A wheel rolling as it travels (wheel.legacy): driven[0] turns about its
// local `axle` axis by amount * travel / radius radians, after its parent
// placed it. Travel is measured in targets[0]'s frame: the ground the vehicle
// travels over (the world control), so moving that reference carries the
// wheel without rolling it, while moving the vehicle's or the wheel's own
// controls rolls it. A positive travel turns it positively about `axle`, which
// rolls it forward when its ground contact lies along axle x forward from its
// centre (axle X, forward Z: the ground below, -Y); the builder picks the axes
// so. How travel is measured (RollMode):
//  - Path (Mikan's auto_rotate): the wheel accumulates. Each evaluation turns
//    it by amount * (the step its centre made since the previous evaluation,
//    projected on its rolling direction: perpendicular to its axle in the
//    reference's ground plane, XZ, signed by `forward`) / radius. So the roll
//    follows the path taken: a vehicle that turns keeps rolling on its new
//    heading, one that comes back the way it went unrolls. The state lives in
//    the evaluation state (eval::EvalState), not in the rig: a new state has
//    rolled nothing, and its first evaluation only records where the wheel is.
//    A step longer than `jump` metres (a scrub, a snap) rolls nothing.
//  - Axis: stateless, the displacement from rest along the wheel's current
//    `forward` axis (a vehicle that drives away, turns and comes back ends
//    unrolled); every evaluation of a pose gives the same roll.
// Exactly one target; `axle` and `forward` must differ; `radius` must be
// positive; `jump` must not be negative.
enum class RollMode : std::uint8_t { Path, Axis };
const char* rollModeName(RollMode mode); // "path", "axis"

struct RollConstraint {
    Axis axle = Axis::X;
    Axis forward = Axis::Z;
    double radius = 1.0; // metres, in the reference's rest frame (the rig's rest scale)
    // The share of the automatic roll, clamped to [0, 1] (Mikan's auto_rotate):
    // 0 keeps the wheel still whatever it travels. None: 1. In path mode it
    // scales each step, so animating it stops the wheel where it is.
    std::optional<AttributeRef> amount{};
    RollMode mode = RollMode::Path;
    // Path mode: the longest step (metres, in the reference's frame) that still
    // rolls the wheel; 0: one circumference (2 pi radius).
    double jump = 0.0;
    bool operator==(const RollConstraint&) const = default;
};

// Carry (rig.spline's chained tweakers: an FK chain's offsets without its
// hierarchy): driven[0], once its parent placed it, also moves by the
// animated offset of each node of `carried`, first one outermost:
//   world(driven) = D_0 D_1 ... D_n-1 world(driven),
//   D_k = F_k C_k F_k^-1, F_k = world(targets[k]) rest(targets[k])^-1 rest(carried[k]),
// C_k being carried[k]'s own channel transform (translate, rotate in its
// rotate order, scale): the carried node's animation about its zero pose,
// where F_k puts that pose as its pivot targets[k] (what it rides on,
// uncarried) moves. Exactly one target per carried node; each carried node
// must have transform channels (a controller), else the rig does not
// compile. A carried node is read by its channels, not its world, so it may
// itself be carried by the driven node's chain. At rest (every C_k the
// identity) the driven node is where its parent puts it.
struct CarryConstraint {
    std::vector<RigNodeIndex> carried{};
    bool operator==(const CarryConstraint&) const = default;
};

// What a constraint does; the index of its settings in ConstraintSettings.
enum class ConstraintKind { Parent, Orient, Point, Blend, Ik, Twist, Spline, Space, Drive, Aim, Scale, Visibility, Roll, DrivenKey, Carry };
const char* constraintKindName(ConstraintKind kind); // "parent", "orient"...

using ConstraintSettings = std::variant<ParentConstraint, OrientConstraint, PointConstraint, BlendConstraint, IkConstraint,
                                        TwistConstraint, SplineConstraint, SpaceConstraint, DriveConstraint, AimConstraint,
                                        ScaleConstraint, VisibilityConstraint, RollConstraint, DrivenKeyConstraint,
                                        CarryConstraint>;

template <ConstraintKind kind>
using SettingsOf = std::variant_alternative_t<static_cast<std::size_t>(kind), ConstraintSettings>;
static_assert(std::is_same_v<SettingsOf<ConstraintKind::Parent>, ParentConstraint>);
static_assert(std::is_same_v<SettingsOf<ConstraintKind::Orient>, OrientConstraint>);
static_assert(std::is_same_v<SettingsOf<ConstraintKind::Point>, PointConstraint>);
static_assert(std::is_same_v<SettingsOf<ConstraintKind::Blend>, BlendConstraint>);
static_assert(std::is_same_v<SettingsOf<ConstraintKind::Ik>, IkConstraint>);
static_assert(std::is_same_v<SettingsOf<ConstraintKind::Twist>, TwistConstraint>);
static_assert(std::is_same_v<SettingsOf<ConstraintKind::Spline>, SplineConstraint>);
static_assert(std::is_same_v<SettingsOf<ConstraintKind::Space>, SpaceConstraint>);
static_assert(std::is_same_v<SettingsOf<ConstraintKind::Drive>, DriveConstraint>);
static_assert(std::is_same_v<SettingsOf<ConstraintKind::Aim>, AimConstraint>);
static_assert(std::is_same_v<SettingsOf<ConstraintKind::Scale>, ScaleConstraint>);
static_assert(std::is_same_v<SettingsOf<ConstraintKind::Visibility>, VisibilityConstraint>);
static_assert(std::is_same_v<SettingsOf<ConstraintKind::Roll>, RollConstraint>);
static_assert(std::is_same_v<SettingsOf<ConstraintKind::DrivenKey>, DrivenKeyConstraint>);
static_assert(std::is_same_v<SettingsOf<ConstraintKind::Carry>, CarryConstraint>);
static_assert(std::variant_size_v<ConstraintSettings> == 15);

struct RigConstraint {
    NodeKey key;                       // identity, as a node's
    std::string path;                  // display only, as a node's
    InstanceId owner = kNoId;
    std::vector<RigNodeIndex> driven;  // what it writes, in the order its kind documents
    std::vector<RigNodeIndex> targets; // what it reads, in the order its kind documents
    ConstraintSettings settings;

    ConstraintKind kind() const { return static_cast<ConstraintKind>(settings.index()); }
};

// Calls `visit` on every node index a constraint holds: driven, targets and
// the node of every attribute its settings read (a rig copied or spliced
// renumbers its nodes through this, so no kind's reference is missed).
void forEachNodeIndex(RigConstraint& constraint, const std::function<void(RigNodeIndex&)>& visit);

} // namespace rs::model
