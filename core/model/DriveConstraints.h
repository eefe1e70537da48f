#pragma once
// The constraints that a channel drives (Constraint.h holds the others and
// the variant of all kinds): a drive turns or scales a node by an attribute
// (finger curl, foot roll pivots, the rig's post scale), driven keys set a
// channel from a keyed curve of another channel (Mikan's `drive` mod).
#include "model/ConstraintRefs.h"

#include <limits>
#include <string>
#include <variant>
#include <vector>

namespace rs::model {

// What a drive does with its amount (below): turn driven[0] about its local
// X, Y or Z axis by `amount` degrees, or scale it uniformly by `amount` (1
// keeps its size, 0 collapses it).
enum class DriveOutput : std::uint8_t { RotateX = 0, RotateY = 1, RotateZ = 2, Scale = 3 }; // rotations: the axis index
const char* driveOutputName(DriveOutput output); // "rotate_x" ... "scale"

// How a drive's amount follows its value (`factor` as DriveConstraint's):
// amount = factor * clamp(value, low, high); no limit by default.
struct DriveClamped {
    double low = -std::numeric_limits<double>::infinity();
    double high = std::numeric_limits<double>::infinity();
    bool operator==(const DriveClamped&) const = default;
};
// amount = factor * clamp(value, 0, max(break, 0)): a ball roll up to the break angle.
struct DriveUpToBreak {
    AttributeRef breakAngle{}; // degrees
    bool operator==(const DriveUpToBreak&) const = default;
};
// amount = factor * max(value - break, 0): a toe roll past the break angle.
struct DrivePastBreak {
    AttributeRef breakAngle{}; // degrees
    bool operator==(const DrivePastBreak&) const = default;
};
using DriveResponse = std::variant<DriveClamped, DriveUpToBreak, DrivePastBreak>;

// An attribute-driven rotation or scale: `value` turns or scales driven[0]
// after its parent placed it (finger curl, foot roll pivots, the rig's post
// scale). No targets.
struct DriveConstraint {
    AttributeRef value{};
    DriveOutput output = DriveOutput::RotateX;
    // Degrees per unit of value for a rotation, scale per unit for Scale. On a
    // mirrored branch copy the builder flips its sign for rotations about the
    // axes the mirror reverses, so both sides turn as mirror images.
    double factor = 1.0;
    DriveResponse response{};
    bool operator==(const DriveConstraint&) const = default;
};

// A channel of a node: a controller's transform channel ("tx".."sz", in the
// channel box's units: metres, degrees, factors) or any node's custom
// attribute (`curl`, `ik_blend`).
struct ChannelRef {
    RigNodeIndex node = kNoNode;
    std::string channel{};
    bool operator==(const ChannelRef&) const = default;
};

// A keyed curve's point: at driver value `in` the driven channel is `out`.
struct CurveKey {
    double in = 0.0;
    double out = 0.0;
    bool operator==(const CurveKey&) const = default;
};
// What a keyed curve gives before its first key (pre) and after its last (post):
// the end key's value, the end segment's slope continued, or the keys repeated.
enum class CurveInfinity : std::uint8_t { Constant = 0, Linear = 1, Cycle = 2 };
const char* curveInfinityName(CurveInfinity infinity); // "constant", "linear", "cycle"

// Driven keys (Maya's set driven key, Mikan's `drive` mod): the `driven`
// channel takes the keyed curve's value at the `driver` channel's value. It
// works on channels, not transforms: the evaluator computes every driven
// channel from the pose before placing any node (drivers first when one drives
// another's driver), and the driven channel's own pose value is ignored (the
// builder locks it for animators). A driven channel driven twice takes the
// last; a loop of driven keys is a compile error. driven = {driven.node},
// targets = {driver.node}; it places nothing. Keys sorted by `in`, strictly
// increasing, at least one (else the evaluator skips it with a warning);
// linear between keys or, `smooth`, monotone cubic (never overshooting a key).
struct DrivenKeyConstraint {
    ChannelRef driver{};
    ChannelRef driven{};
    std::vector<CurveKey> keys{};
    bool smooth = false;
    CurveInfinity pre = CurveInfinity::Constant;
    CurveInfinity post = CurveInfinity::Constant;
    bool operator==(const DrivenKeyConstraint&) const = default;
};

} // namespace rs::model
