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
#include "model/BuildSettings.h"
#include "model/Mesh.h"
#include "model/Mod.h"
#include "model/Naming.h"
#include "model/Override.h"
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

struct TemplateInstance {
    InstanceId id = kNoId;
    std::string templateId;          // "core.joints"
    std::string name;                // unique in the document, e.g. "arm_L"
    InstanceId parent = kNoId;       // kNoId: top-level instance
    JointId parentJoint = kNoId;     // the parent's joint this instance hangs under
    std::map<std::string, Value> options; // only values that differ from the defaults
    // Where each option was read (file:line, for the build's messages about its
    // value); an edited option has none. Not part of equality.
    struct OptionSources {
        std::map<std::string, SourceLocation> at;
        bool operator==(const OptionSources&) const { return true; }
    } optionSources;
    std::map<std::string, std::string> structure; // per-instance structure overrides: tag -> address
    // Per-instance naming: manifest name token -> name (the names of every node
    // the token makes). One node's own name is a display-name override (`overrides`).
    std::map<std::string, std::string> names;
    std::vector<GuideJoint> joints;  // joints[0] is the root; parents come before children

    const GuideJoint* joint(JointId id) const;
    GuideJoint* joint(JointId id);
    std::vector<JointId> childJoints(JointId id) const;
    bool operator==(const TemplateInstance&) const = default;
};

class GuideDocument {
public:
    // 2: the pose is keyed by instance id, branch and tag; 3: one `overrides:` section
    // (an older guide's instance `shapes:` and `pose:` migrate into it on load).
    static constexpr int kSchemaVersion = 3;

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
    // Every manual adjustment of the built rig (shapes, default values, limits,
    // locks, post transform, display names, the test pose), one record per node
    // (model/Override.h); edited through rs::edit. Records of nodes a build does
    // not make are kept.
    Overrides overrides;
    LegacyPoseValues legacyPose;     // unmatched records of an older guide, kept
    // Modifications of the built rig (model/Mod.h), global or per instance,
    // applied in this order; edited through rs::edit. Mods whose nodes a build
    // does not make are reported and kept.
    Mods mods;
    BuildSettings build;             // restore toggles and cleanup (model/BuildSettings.h)
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
