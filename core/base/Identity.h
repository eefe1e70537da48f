#pragma once
// Identity: the typed ids that name things of a guide and its rig. Ids are
// stable (they survive renames, rebuilds, saves); names are for people and
// files. Nothing in Rigsmith finds a thing by its display name, and no id has a
// text form that is parsed again, except at file boundaries (rs::io).
#include <cstdint>
#include <functional>
#include <string>

namespace rs {

using InstanceId = std::uint32_t; // a template instance of a guide
using JointId = std::uint32_t;    // a guide joint
constexpr std::uint32_t kNoId = 0;

// One copy of an authored instance in the built rig. An instance without
// branches has one copy (branch ""); `branches: [L, R]` gives copies "L" and
// "R"; nested branches compose ("A.L").
struct CopyKey {
    InstanceId instance = kNoId; // the authored instance
    std::string branch;

    auto operator<=>(const CopyKey&) const = default;
};

// A rig node (or constraint): its instance copy and its tag path in the
// template's rig ("ctrls.fk.0", "skin.limb.2"). The rig root is the key with
// instance kNoId and tag "rig". Renaming an instance keeps every key.
struct NodeKey {
    InstanceId instance = kNoId;
    std::string branch;
    std::string tag;

    CopyKey copy() const { return {instance, branch}; }
    bool isRoot() const { return instance == kNoId; }
    auto operator<=>(const NodeKey&) const = default;
};

// What a diagnostic is about, so a log can select the cause: an instance (a
// branch copy of it), a rig node, a guide joint, a controller's shape, a file
// or a mesh (files and meshes are named by their path or name).
struct Subject {
    enum class Kind : std::uint8_t { None, Instance, Node, GuideJoint, Shape, File, Mesh };
    Kind kind = Kind::None;
    NodeKey node;            // Instance: instance + branch; Node and Shape: the whole key
    JointId joint = kNoId;   // GuideJoint
    std::string name;        // File: path; Mesh: mesh name

    static Subject ofInstance(InstanceId id, std::string branch = {}) { return {Kind::Instance, {id, std::move(branch), {}}, kNoId, {}}; }
    static Subject ofNode(NodeKey key) { return {Kind::Node, std::move(key), kNoId, {}}; }
    static Subject ofShape(NodeKey key) { return {Kind::Shape, std::move(key), kNoId, {}}; }
    static Subject ofJoint(InstanceId instance, JointId joint) { return {Kind::GuideJoint, {instance, {}, {}}, joint, {}}; }
    static Subject ofFile(std::string path) { return {Kind::File, {}, kNoId, std::move(path)}; }
    static Subject ofMesh(std::string name) { return {Kind::Mesh, {}, kNoId, std::move(name)}; }

    bool isNone() const { return kind == Kind::None; }
    // The authored instance the subject belongs to (kNoId for files, meshes, none).
    InstanceId instance() const { return node.instance; }
    bool operator==(const Subject&) const = default;
};

} // namespace rs

// Hashes, for the rig's node index (an unordered map: looked up for every node
// a build creates).
template <>
struct std::hash<rs::NodeKey> {
    std::size_t operator()(const rs::NodeKey& key) const noexcept
    {
        std::size_t h = std::hash<std::string>{}(key.tag);
        h ^= std::hash<std::string>{}(key.branch) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
        h ^= std::size_t(key.instance) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
        return h;
    }
};
