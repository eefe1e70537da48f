#pragma once
// The built rig: a flat, index-based node table (ozz style), produced by
// rs::rigging::RigBuilder from a guide and consumed by the viewport, the evaluator
// and the exporters. Nodes are stored parents-first. Matrices are the rest pose,
// metres, Y-up. A node is identified by its NodeKey (authored instance id,
// branch, tag path); its `path` ("arm.L::ctrls.fk.0", Mikan's rig id made of
// the instance's current name) is for people, dumps and name maps only.
// Constraints are typed per kind (model/Constraint.h).
#include "base/Diagnostic.h"
#include "base/Math.h"
#include "model/Constraint.h"
#include "model/GuideDocument.h"

#include <array>
#include <compare>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <unordered_map>
#include <vector>

namespace rs::model {

enum class RigNodeKind { Group, Controller, Joint };
const char* kindName(RigNodeKind kind);

// One drawn curve of a controller, in the controller's local space: the
// B-spline's control points (CVs, degree, closed or not) and the polyline
// sampled from them (rs::evaluateNurbs) that views draw.
struct ControllerCurve {
    std::vector<Vec3> points;
    Vec3 color{1.0, 1.0, 0.0}; // sRGB, [0, 1]
    std::vector<Vec3> cvs;
    int degree = 1;
    bool periodic = false;
    double lineWidth = 1.0;   // pixels (a shape override)
    bool visible = true;      // false: not drawn nor picked (a shape override hides the shape)

    // Moves the CVs and the polyline by an affine map (which maps the curve
    // exactly); resample() samples the polyline again after CVs moved.
    void transform(const Mat4& m);
    void resample();
};

// One control point of a built controller's curve: what CV mode selects.
struct CurveCv {
    RigNodeIndex node = kNoNode;
    int curve = 0;
    int cv = 0;
    auto operator<=>(const CurveCv&) const = default;
};

// An animatable custom attribute of a node: `ik_blend` on a limb's switch
// controller, `roll` on a foot. Value, min and max are in the attribute's unit.
// An enum attribute (`space`) has one label per integer value from min to max.
// Attributes on nodes other than controllers are locked for animators
// (`post_scale` is set by the rigger, not animated).
struct RigAttribute {
    std::string name;
    double value = 0.0;                 // the default
    double min = 0.0;
    double max = 1.0;
    std::vector<std::string> labels;    // enum labels; empty for a number
    bool locked = false;                // a lock override: animators cannot change it
    bool keyable = true;                // false: shown but not keyed
};

// Rotate orders as Maya names them: the first letter is applied first
// ("xyz": R = Rz * Ry * Rx for column vectors).
enum class RotateOrder : std::uint8_t { Xyz, Yzx, Zxy, Xzy, Yxz, Zyx };
const char* rotateOrderName(RotateOrder order);
std::optional<RotateOrder> parseRotateOrder(const std::string& name);

// The transform channels of a controller, in the controller's rest frame:
// translate x y z (metres), rotate x y z (degrees), scale x y z. Channel index
// i: 0-2 translate, 3-5 rotate, 6-8 scale. Defaults are 0 and scale 1.
struct ChannelSettings {
    static constexpr int kCount = 9;
    // Masks of ChannelSettings bits.
    static constexpr std::uint16_t kTranslateChannels = 0x007, kRotateChannels = 0x038, kScaleChannels = 0x1c0;
    static constexpr std::uint16_t kNoChannels = 0, kAllChannels = 0x1ff;
    RotateOrder rotateOrder = RotateOrder::Xyz;
    std::uint16_t locked = 0;           // bit i: channel i cannot be animated
    std::uint16_t limited = 0;          // bit i: channel i is clamped to [minimum[i], maximum[i]]
    std::array<double, kCount> minimum{};
    std::array<double, kCount> maximum{};
    std::uint16_t unkeyable = 0;        // bit i: channel i is shown but not keyed
    // Bit i: animators should touch channel i. Each builder declares it per
    // controller (translate and rotate unless it says otherwise); cleanup
    // (rigging/CleanupStage.h) locks and hides every other channel.
    std::uint16_t animatable = kTranslateChannels | kRotateChannels;
    std::uint16_t hidden = 0;           // bit i: channel i is not shown (cleanup's lock and hide)
    // What reset returns to (a default-value override): 0, scale 1.
    std::array<double, kCount> defaults{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0};

    // What a new controller gets: every channel free, scale kept in [0.01, 100]
    // (a zero or negative scale would collapse or turn the rig inside out).
    static ChannelSettings controllerDefaults();
    bool isLocked(int channel) const { return (locked >> channel) & 1u; }
    bool isLimited(int channel) const { return (limited >> channel) & 1u; }
    bool isKeyable(int channel) const { return !((unkeyable >> channel) & 1u); }
    bool isAnimatable(int channel) const { return (animatable >> channel) & 1u; }
    bool isHidden(int channel) const { return (hidden >> channel) & 1u; }
    void lock(int first, int count = 1);
    void limit(int channel, double low, double high);
    bool operator==(const ChannelSettings&) const = default;
};
const char* channelName(int channel); // "tx" ... "sz"
// The index of "tx" ... "sz", -1 for any other name.
int channelIndex(const std::string& name);

struct RigNode {
    NodeKey key;                       // identity: instance copy + tag, stable across renames
    std::string path;                  // display only: "<instance name>.<branch>::<tag>"; never parsed
    std::string name;                  // unique display/export name from the naming engine
    RigNodeKind kind = RigNodeKind::Group;
    RigNodeIndex parent = kNoNode;     // physical parent; kNoNode only for the rig root
    RigNodeIndex virtualParent = kNoNode; // parent in the node's domain hierarchy
    InstanceId owner = kNoId;          // instance that created it (kNoId for the rig root)
    Mat4 localMatrix{1.0};             // relative to parent
    Mat4 worldMatrix{1.0};             // rest pose
    std::string shape;                 // shape library name, controllers only
    std::vector<ControllerCurve> curves;
    std::vector<RigAttribute> attributes;
    JointId guide = kNoId;             // authored guide joint the node derives from (kNoId: none)
    bool hidden = false;               // setup nodes the animator never sees
    ChannelSettings channels;          // controllers only: locks, limits and rotate order
    // Segment scale compensation: the node ignores its parent's channel scale
    // (an FK child keeps its size when the parent control is scaled; its
    // position still follows the scaled parent).
    bool scaleCompensate = false;
    // The node's mirror image on the other branch of an L/R pair (rest world
    // matrices are exact reflections), kNoNode on centre nodes.
    RigNodeIndex twin = kNoNode;
    int mirrorPlane = -1;              // reflection plane with the twin: 0 x, 1 y, 2 z; -1 none
    // The curves are the twin's reflected (a mirrored branch copy): shape
    // edits are made on the twin and this side follows.
    bool shapeFromTwin = false;
    // Cleanup's record (rigging/CleanupStage.h): the default value of each
    // channel an animator may touch (transform channels in channel box units
    // tx..sz, then custom attributes), what reset returns to and what exports
    // write as custom properties. Empty when the build did not clean up.
    std::vector<std::pair<std::string, double>> defaultValues;

    const RigAttribute* attribute(const std::string& attributeName) const;

    // The first segment of the tag: "ctrls", "skin", "hooks"...
    std::string domain() const { return key.tag.substr(0, key.tag.find('.')); }
    bool isInVirtualHierarchy() const { return m_inHierarchy; }
    void setInVirtualHierarchy(bool in) { m_inHierarchy = in; }

private:
    bool m_inHierarchy = false;
};

// An animator's controller group (Mikan's common options `group` and
// `parent`): the controllers of one or more template instances, nested like the
// instances, to select (or hide) a body part at once. Built by the generator's
// controller group plugin (rigging/Plugins.cpp).
struct ControllerGroup {
    std::string name;                       // the `group` option, or the instance copy's name ("arm.L")
    std::size_t parent = kNoGroup;          // index into Rig::groups; kNoGroup for a top-level group
    std::vector<RigNodeIndex> controllers;  // in node order
    static constexpr std::size_t kNoGroup = static_cast<std::size_t>(-1);
};

struct Rig {
    std::vector<RigNode> nodes;
    std::vector<RigConstraint> constraints; // in build order; the evaluator orders them by dependency
    // "controllers": every animatable controller; "cameras": each util.camera's
    // camera node (what exports write as cameras: io/ExportCamera.h).
    std::map<std::string, std::vector<RigNodeIndex>> sets;
    std::vector<ControllerGroup> groups;                   // parents before children
    std::unordered_map<NodeKey, RigNodeIndex> byKey;
    std::unordered_map<std::string, RigNodeIndex> byPath;
    Diagnostics diagnostics;

    std::optional<RigNodeIndex> find(const NodeKey& key) const;
    // By display path ("arm.L::ctrls.ik"): for text boundaries (command line,
    // name maps, tests), never for identity inside Rigsmith.
    std::optional<RigNodeIndex> findPath(std::string_view path) const;
    // Adds a node at the end, indexed by key and path.
    RigNodeIndex add(RigNode node);
    // Drops the nodes from index `count` on (a failed instance's), with their index entries.
    void truncate(std::size_t count);
    // Nodes of one domain hierarchy whose virtual parent is none, in node order.
    std::vector<RigNodeIndex> virtualRoots(const std::string& domain) const;
    // One node's children: a scan of every node. To walk a whole hierarchy
    // use the tables below, made in one pass (index = node, children in node order).
    std::vector<RigNodeIndex> virtualChildren(RigNodeIndex node) const;
    std::vector<RigNodeIndex> children(RigNodeIndex node) const;
    std::vector<std::vector<RigNodeIndex>> virtualChildTable() const;
    std::vector<std::vector<RigNodeIndex>> childTable() const;
    std::size_t count(RigNodeKind kind) const;
    // Joints of the skin domain: what the export skeleton holds.
    std::size_t skinJointCount() const;
};

} // namespace rs::model
