#pragma once
// Overrides: every manual adjustment a rigger makes to a built rig, kept in
// the guide so that building again never undoes it. One record per rig node,
// keyed by the node's typed identity (NodeKey: instance id, branch, tag), never
// by a display name, so a record survives rebuilds, option changes and
// instance renames. One build stage (rigging/OverrideStage) applies them all
// after generation; a record whose node a build does not make is an orphan:
// reported, kept, and applied again when the node comes back.
//
// Keys: a controller shape of a branched instance is keyed by the authored
// side with branch "" (the mirrored copy takes the edited curves reflected);
// every other kind names its copy's branch. The post transform lives on the
// rig root's key (instance kNoId, tag "rig").
//
// Channels are named as the channel box names them: tx ty tz rx ry rz sx sy sz
// (metres, degrees, factors) or a custom attribute's name (ik_blend, space).
#include "base/Identity.h"
#include "base/Math.h"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rs::model {

// A rigger's edit of one controller's shape: control points (CVs) moved one
// by one, then the whole shape moved, turned and scaled, both in the
// controller's space: final CV = transform * (CV as the template places it + offset).
struct ShapeEdit {
    Transform transform;
    std::map<std::pair<int, int>, Vec3> cvs; // (curve index, CV index) -> offset

    bool isIdentity() const { return transform == Transform{} && cvs.empty(); }
    bool operator==(const ShapeEdit&) const = default;
};

// Everything a rigger can change about a controller's look.
struct ShapeOverride {
    ShapeEdit edit;
    std::optional<Vec3> color;      // sRGB [0, 1], every curve of the shape
    std::optional<double> lineWidth; // pixels, > 0
    std::optional<bool> visible;    // false hides the controller's curves

    bool isEmpty() const { return edit.isIdentity() && !color && !lineWidth && !visible; }
    bool operator==(const ShapeOverride&) const = default;
};

struct ChannelLimit {
    double min = 0.0;
    double max = 0.0; // min <= max
    bool operator==(const ChannelLimit&) const = default;
};

// A channel's lock and keyable state (Maya's channel box): a locked channel
// cannot be changed; a channel that is not keyable is shown but not animated.
struct ChannelState {
    bool locked = false;
    bool keyable = true;
    bool operator==(const ChannelState&) const = default;
};

// The kinds of override; each can be left out of a build (restore toggles).
enum class OverrideKind : std::uint8_t { Shapes, Defaults, Limits, Locks, Post, Names, Pose };
constexpr int kOverrideKindCount = 7;
// "shapes", "defaults", "limits", "locks", "post", "names", "pose".
const char* overrideKindName(OverrideKind kind);
std::optional<OverrideKind> parseOverrideKind(const std::string& name);

// One node's overrides; an empty field is "not overridden".
struct Override {
    std::optional<ShapeOverride> shape;
    std::map<std::string, double> defaults;       // channel -> value reset returns to (and export writes as rest)
    std::map<std::string, ChannelLimit> limits;   // channel -> [min, max]
    std::map<std::string, ChannelState> locks;    // channel -> locked / keyable
    std::optional<Transform> post;                // root only: the whole rig's offset and scale
    std::optional<std::string> displayName;       // the node's name in views and exports
    std::map<std::string, double> pose;           // the test pose: channel -> value

    bool has(OverrideKind kind) const;
    // Clears one kind; the record is empty when every kind is.
    void clear(OverrideKind kind);
    bool isEmpty() const;
    bool operator==(const Override&) const = default;
};

using Overrides = std::map<NodeKey, Override>;

// The key of the rig root, where the post transform is kept.
NodeKey rigRootKey();

// The rigger's test pose: node key -> channel -> value (only values that differ from the defaults).
using PoseValues = std::map<NodeKey, std::map<std::string, double>>;
// The pose kind of every record, as the evaluator takes it.
PoseValues testPose(const Overrides& overrides);
// Replaces the pose kind of every record by `pose`; records left empty are removed.
void setTestPose(Overrides& overrides, const PoseValues& pose);

// Which kinds a build restores (all by default): `--no-restore KIND`.
struct RestoreToggles {
    std::array<bool, kOverrideKindCount> on{true, true, true, true, true, true, true};

    bool restores(OverrideKind kind) const { return on[static_cast<int>(kind)]; }
    void set(OverrideKind kind, bool restore) { on[static_cast<int>(kind)] = restore; }
    bool operator==(const RestoreToggles&) const = default;
};

} // namespace rs::model
