#pragma once
// The built rig: a flat, index-based node table (ozz style), produced by
// rs::build::RigBuilder from a guide and consumed by the viewport, the evaluator
// and the exporters. Nodes are stored parents-first. Matrices are the rest pose,
// metres, Y-up. Node ids follow Mikan's rig ids: "<instance>::<tag>", e.g.
// "spine::ctrls.0", "world::skin.root".
#include "base/Diagnostic.h"
#include "base/Math.h"
#include "model/GuideDocument.h"

#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rs::model {

using RigNodeIndex = std::uint32_t;
constexpr RigNodeIndex kNoNode = std::numeric_limits<RigNodeIndex>::max();

enum class RigNodeKind { Group, Controller, Joint };
const char* kindName(RigNodeKind kind);

// One drawn curve of a controller, as a polyline in the controller's local space.
struct ControllerCurve {
    std::vector<Vec3> points;
    Vec3 color{1.0, 1.0, 0.0}; // sRGB, [0, 1]
};

struct RigNode {
    std::string id;                    // unique: "<instance>::<tag>"
    std::string name;                  // unique display/export name from the naming engine
    RigNodeKind kind = RigNodeKind::Group;
    RigNodeIndex parent = kNoNode;     // physical parent; kNoNode only for the rig root
    RigNodeIndex virtualParent = kNoNode; // parent in the node's domain hierarchy
    InstanceId owner = kNoId;          // instance that created it (kNoId for the rig root)
    Mat4 localMatrix{1.0};             // relative to parent
    Mat4 worldMatrix{1.0};             // rest pose
    std::string shape;                 // shape library name, controllers only
    std::vector<ControllerCurve> curves;

    // The first segment of the tag: "ctrls", "skin", "hooks"...
    std::string domain() const;
    bool isInVirtualHierarchy() const { return m_inHierarchy; }
    void setInVirtualHierarchy(bool in) { m_inHierarchy = in; }

private:
    bool m_inHierarchy = false;
};

struct Rig {
    std::vector<RigNode> nodes;
    std::map<std::string, RigNodeIndex> byId;
    Diagnostics diagnostics;

    std::optional<RigNodeIndex> find(const std::string& id) const;
    // Nodes of one domain hierarchy whose virtual parent is none, in node order.
    std::vector<RigNodeIndex> virtualRoots(const std::string& domain) const;
    std::vector<RigNodeIndex> virtualChildren(RigNodeIndex node) const;
    std::vector<RigNodeIndex> children(RigNodeIndex node) const;
    std::size_t count(RigNodeKind kind) const;
};

} // namespace rs::model
