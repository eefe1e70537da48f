#pragma once
// What a rig's constraints refer to (Constraint.h): nodes by index into
// Rig::nodes, a node's local axis, and a node's animatable custom attribute.
#include <cstdint>
#include <limits>
#include <string>

namespace rs::model {

using RigNodeIndex = std::uint32_t; // into Rig::nodes
constexpr RigNodeIndex kNoNode = std::numeric_limits<RigNodeIndex>::max();

// A local axis of a node: column 0, 1 or 2 of its world matrix.
enum class Axis : std::uint8_t { X, Y, Z };
const char* axisName(Axis axis); // "x", "y", "z"

// An animatable custom attribute of a node (RigNode::attributes: `ik_blend`,
// `roll`, `space`), read by a constraint as a channel of the pose.
struct AttributeRef {
    RigNodeIndex node = kNoNode;
    std::string attribute{};
    bool operator==(const AttributeRef&) const = default;
};

} // namespace rs::model
