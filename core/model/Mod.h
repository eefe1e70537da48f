#pragma once
// Mods: declarative modifications of the built rig, authored in the guide
// (Mikan's mods, ../shared/reference/mikan-format.md §5). Where an override
// (model/Override.h) keeps a value the rigger set on one node, a mod adds
// structure the templates do not make: a space for a switch, a constraint, a
// new parent, a hidden controller, a custom channel or a connection, driven
// keys, a virtual parent. One build stage (rigging/ModStage.cpp) applies them
// in document order after generation, before the rig's evaluation program
// compiles.
//
// A mod is global or belongs to an instance (its owner). It names rig nodes by
// typed reference (ModRef): the instance by id (resolved from the rig id text
// `instance[.branch]::tag[@channel]` when the guide is read, by io/ModFile), so
// renaming an instance keeps its mods. In an instance's mod a bare tag
// (`ctrls.ik`) is the owner's node; a mod of a branched instance applies to
// each branch copy, and a reference without a branch takes the copy's branch
// (else the unbranched node), so the L mod drives L nodes and the R copy R
// nodes, mirrored as the copies are. Values are written for the authored side:
// on a mirrored copy a transform channel's value (a default, a limit, a drive's
// keys) that the reflection negates (tx, ry, rz for the x plane) is negated, so
// that copy moves as the mirror image; custom channels take values as written.
//
// A mod whose node does not exist in a build is reported in the build log
// (with the mod's file:line when it was read from a file) and kept.
#include "base/Diagnostic.h"
#include "base/Identity.h"
#include "model/Constraint.h"

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace rs::model {

// An instance a mod names: its id, and the name it was read or last written
// with (what a file says for an instance that is gone). Id kNoId with a name:
// no instance of the guide has that name (reported by a build, kept). Id kNoId
// without a name: none (a global mod's owner; the rig root in a reference).
// Equal by id when both have one.
struct ModInstance {
    InstanceId id = kNoId;
    std::string name;

    bool isNone() const { return id == kNoId && name.empty(); }
    bool operator==(const ModInstance& o) const { return id != kNoId || o.id != kNoId ? id == o.id : name == o.name; }
};

// A rig node, and a channel of it for the kinds that take one.
struct ModRef {
    ModInstance instance;
    std::optional<std::string> branch; // nullopt: the branch of the copy the mod applies to (else "")
    std::string tag;                   // "ctrls.ik"; the rig root is "rig" with no instance
    std::string channel;               // "tx".."sz" or a custom attribute's name; empty: none
    bool operator==(const ModRef&) const = default;
};

// space: `node` (a controller) gets one more space, `target`, in its switch
// (the space constraint choosing by the enum attribute `attribute`, "space"
// unless the node has another switch); a node without a switch gets one,
// driving its offset group, with the group's own parent as space 0 ("parent").
struct SpaceMod {
    ModRef node;
    ModRef target;
    std::string label;               // the enum label; empty: the target's last tag segment
    std::string attribute = "space";
    bool operator==(const SpaceMod&) const = default;
};

// constraint: `node` follows `targets` (ConstraintKind Parent, Point, Orient,
// Scale or Aim; settings as model/Constraint.h's).
struct ConstraintMod {
    ConstraintKind kind = ConstraintKind::Parent;
    ModRef node;
    std::vector<ModRef> targets;
    std::vector<double> weights;     // empty: equal; else one per target
    bool keepOffset = true;          // parent, point, orient, scale
    Axis aim = Axis::X, up = Axis::Y; // aim
    bool operator==(const ConstraintMod&) const = default;
};

// parent: `node` hangs under `parent`, keeping its world rest placement.
struct ParentMod {
    ModRef node;
    ModRef parent;
    bool operator==(const ParentMod&) const = default;
};

// hide: the nodes are hidden from the animator (not drawn, picked, walked to
// nor animated; not in the controllers set).
struct HideMod {
    std::vector<ModRef> nodes;
    bool operator==(const HideMod&) const = default;
};

// The type of a custom channel a plug creates.
enum class PlugType : std::uint8_t { Float, Bool, Enum };
const char* plugTypeName(PlugType type); // "float", "bool", "enum"
std::optional<PlugType> parsePlugType(const std::string& name);

// plug: `channel` (a node and a channel name) is created as a custom
// attribute when the node has none of that name (`type`, default float), then
// given what is set here: its default value (what a reset returns to and
// export writes as rest), limits, keyable and locked state. With `from` it
// follows that channel instead (times `factor`) and is locked for animators.
struct PlugMod {
    ModRef channel;
    std::optional<PlugType> type;
    std::optional<double> value;     // the default value
    std::optional<double> min, max;
    std::optional<bool> keyable, locked;
    std::vector<std::string> labels; // enum
    std::optional<ModRef> from;
    double factor = 1.0;
    bool operator==(const PlugMod&) const = default;
};

// drive: driven keys, the `driven` channel following a keyed curve of the
// `driver` channel (model::DrivenKeyConstraint); the driven channel is locked
// for animators.
struct DriveMod {
    ModRef driver;
    ModRef driven;
    std::vector<CurveKey> keys;      // sorted by `in`
    bool smooth = false;
    CurveInfinity pre = CurveInfinity::Constant, post = CurveInfinity::Constant;
    bool operator==(const DriveMod&) const = default;
};

// vdag: `node`'s virtual parent (pickwalk for controllers, the export
// skeleton for skin joints) becomes `parent`, of the same domain.
struct VdagMod {
    ModRef node;
    ModRef parent;
    bool operator==(const VdagMod&) const = default;
};

enum class ModKind : std::uint8_t { Space, Constraint, Parent, Hide, Plug, Drive, Vdag };
constexpr int kModKindCount = 7;
const char* modKindName(ModKind kind); // "space", "constraint", "parent", "hide", "plug", "drive", "vdag"
std::optional<ModKind> parseModKind(const std::string& name);

using ModSettings = std::variant<SpaceMod, ConstraintMod, ParentMod, HideMod, PlugMod, DriveMod, VdagMod>;

struct Mod {
    ModInstance owner;    // none: a global mod
    ModSettings settings;
    SourceLocation where; // file:line:col of the mod when read from a file (not part of equality)

    ModKind kind() const { return static_cast<ModKind>(settings.index()); }
    bool isGlobal() const { return owner.isNone(); }
    bool operator==(const Mod& o) const { return owner == o.owner && settings == o.settings; }
};

using Mods = std::vector<Mod>;

} // namespace rs::model
