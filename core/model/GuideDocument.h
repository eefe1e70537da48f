#pragma once
// The guide: what a rigger authors. A forest of template instances; each instance
// owns a small tree of guide joints whose root hangs under a joint of its parent
// instance (any joint: every joint is a hook). Identity is by id; names are for
// people and files. Joint transforms are local to the parent joint (for an
// instance root: local to the joint it hangs under, or to the world).
//
// The document is plain data; edits go through rs::edit so undo stays in step.
#include "base/Identity.h"
#include "base/Math.h"
#include "model/Mesh.h"
#include "model/Naming.h"
#include "model/Value.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rs::model {

using rs::InstanceId;
using rs::JointId;
using rs::kNoId;
using rs::NodeKey;

// The rigger's test pose of the built rig: node key -> channel name -> value,
// only values that differ from the defaults. Keys are stable across rebuilds
// and renames, so the pose survives them; values of nodes a rebuild no longer
// makes are reported by the build and kept until the rigger removes them.
using PoseValues = std::map<NodeKey, std::map<std::string, double>>;
// Pose records of an older guide whose instance name matched no instance when
// they were migrated to keys: kept verbatim ("arm.L::ctrls.fk.0") and written back.
using LegacyPoseValues = std::map<std::string, std::map<std::string, double>>;

struct GuideJoint {
    JointId id = kNoId;
    JointId parent = kNoId;          // kNoId for the instance root
    Transform local;
    std::vector<std::string> tags;   // explicit structure tags (heel, hips...)
    std::string name;                // optional; "_name" marks a helper (off the /* chain)

    bool hasTag(const std::string& tag) const;
    bool isHelper() const { return !name.empty() && name.front() == '_'; }
    bool operator==(const GuideJoint&) const = default;
};

// A rigger's edit of one controller's shape: control points (CVs) moved one
// by one, then the whole shape moved, turned and scaled, both in the
// controller's space: final CV = transform * (CV as the template places it + offset).
struct ShapeEdit {
    Transform transform;
    std::map<std::pair<int, int>, Vec3> cvs; // (curve index, CV index) -> offset

    bool isIdentity() const { return transform == Transform{} && cvs.empty(); }
    bool operator==(const ShapeEdit&) const = default;
};

struct TemplateInstance {
    InstanceId id = kNoId;
    std::string templateId;          // "core.joints"
    std::string name;                // unique in the document, e.g. "arm_L"
    InstanceId parent = kNoId;       // kNoId: top-level instance
    JointId parentJoint = kNoId;     // the parent's joint this instance hangs under
    std::map<std::string, Value> options; // only values that differ from the defaults
    std::map<std::string, std::string> structure; // per-instance structure overrides: tag -> address
    std::map<std::string, std::string> names;     // per-instance name overrides: token -> name
    // The rigger's edits of controller shapes, by controller tag ("ctrls.ik").
    std::map<std::string, ShapeEdit> shapes;
    std::vector<GuideJoint> joints;  // joints[0] is the root; parents come before children

    const GuideJoint* joint(JointId id) const;
    GuideJoint* joint(JointId id);
    std::vector<JointId> childJoints(JointId id) const;
    bool operator==(const TemplateInstance&) const = default;
};

class GuideDocument {
public:
    static constexpr int kSchemaVersion = 2; // 2: the pose is keyed by instance id, branch and tag

    const std::vector<TemplateInstance>& instances() const { return m_instances; }
    const TemplateInstance* instance(InstanceId id) const;
    TemplateInstance* instance(InstanceId id);
    const TemplateInstance* instanceNamed(const std::string& name) const;
    const TemplateInstance* ownerOf(JointId joint) const;
    const GuideJoint* joint(JointId id) const;
    std::vector<InstanceId> childInstances(InstanceId id) const; // in document order
    // The instance and every instance hanging below it, parents first.
    std::vector<InstanceId> subtree(InstanceId id) const;

    Mat4 jointWorldMatrix(JointId id) const;
    // The world matrix a joint's parent provides (the hook joint for roots).
    Mat4 parentWorldMatrix(JointId id) const;

    // Low-level mutators for rs::edit and readers. Insert keeps `index` order.
    void insertInstance(TemplateInstance instance, std::size_t index);
    std::optional<std::size_t> indexOf(InstanceId id) const;
    // Removes and returns the instance; nullopt (the document untouched) when there is none with `id`.
    std::optional<TemplateInstance> takeInstance(InstanceId id);

    InstanceId nextInstanceId() const;
    JointId nextJointId() const;
    // "base" if free, else "base1", "base2"...
    std::string uniqueName(const std::string& base) const;

    std::string name;                // asset name
    NamingRules naming;              // how rig nodes are named (preset "mikan" unless the file says)
    PoseValues pose;                 // edited through rs::edit::SetPose
    LegacyPoseValues legacyPose;     // unmatched records of an older guide, kept
    // The character's models (any format io::importModel reads), bound to the
    // rig by skin weights kept beside the guide (`<guide>.weights`); drawn
    // see-through for placing guides until bound. Absolute paths in memory;
    // the guide file keeps them relative to itself. (An older guide's
    // `reference_model:` is read as one of them.)
    std::vector<std::string> models;
    // The skin weights of the models' meshes, kept in `<guide>.weights` beside
    // the guide file (io/GuideBindings.h), not in it. A record whose model or
    // mesh is gone, or whose mesh changed, is kept (and reported), never dropped.
    std::vector<MeshBinding> bindings;
    bool operator==(const GuideDocument&) const = default;

private:
    std::vector<TemplateInstance> m_instances; // parents before children
};

} // namespace rs::model
