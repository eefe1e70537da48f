#pragma once
// What one template instance's builder sees of the build: its manifest, guide,
// typed options, structure lookups, naming, and the calls that create rig nodes
// and register hooks. Diagnostics name the instance (and option) they are about.
//
// Builders work in *authored space*: guide matrices are those of the authored
// (unmirrored) guide, and every matrix handed to createNode is mapped through
// the branch mirror (W' = M W M). A mirrored branch is then the exact mirror of
// its twin whatever the builder computes from the guide.
#include "model/Rig.h"
#include "templates/Manifest.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rs::rigging {

struct RigAssembly;
struct Fragment;

class BuildContext {
public:
    BuildContext(RigAssembly& assembly, const templates::TemplateManifest& manifest,
                 const model::TemplateInstance& instance, std::map<std::string, Value> options);

    const templates::TemplateManifest& manifest() const { return m_manifest; }
    const model::TemplateInstance& instance() const { return m_instance; }
    const model::GuideDocument& guide() const;

    // Options and guide parameters with defaults merged, typed as the manifest says.
    const Value& option(const std::string& name) const;
    bool optionBool(const std::string& name) const;
    long long optionInt(const std::string& name) const;
    double optionFloat(const std::string& name) const;
    std::string optionString(const std::string& name) const;
    // A `yaml: on` option parsed from its flow-YAML text: "[L, R]" -> {"L", "R"}; a
    // scalar gives one item. Reports an error and returns nullopt when it is no list.
    std::optional<std::vector<std::string>> optionList(const std::string& name) const;

    // Joints of a structure tag; reports an error and returns nullopt when it fails.
    std::optional<std::vector<model::JointId>> structure(const std::string& tag) const;
    Mat4 guideWorldMatrix(model::JointId joint) const; // authored space
    Vec3 guidePosition(model::JointId joint) const { return translationOf(guideWorldMatrix(joint)); }
    // Joints of the instance with `tag` among their explicit tags (off-chain guides: heel, banks).
    std::vector<model::JointId> taggedJoints(const std::string& tag) const;

    // The rig node this instance attaches to (its parent's hook, else the rig root).
    model::RigNodeIndex hookNode() const { return m_hookNode; }
    void setHookNode(model::RigNodeIndex node) { m_hookNode = node; }

    // Naming engine: core name of a token ("spine", "spine_cog"), optionally indexed.
    std::string name(const std::string& token = {}, std::optional<int> index = std::nullopt) const;
    // The full node name by the document's naming rules: role mark, core name, branch.
    std::string nodeName(model::NameRole role, const std::string& token = {}, std::optional<int> index = std::nullopt) const;
    // The same with a mark of the builder's in place of the role's ("pose":
    // pose_finger_1_L, or finger_1_L_pose with the suffix preset).
    std::string markedName(const std::string& mark, const std::string& token = {}, std::optional<int> index = std::nullopt) const;

    // Creates a node "<instance>::<tag>" at a rest world matrix (authored space)
    // under `parent` (kNoNode: the hook node); `source` is the guide joint it derives from.
    model::RigNodeIndex createNode(model::RigNodeKind kind, const std::string& tag, const std::string& name,
                                   model::RigNodeIndex parent, const Mat4& worldMatrix,
                                   model::JointId source = model::kNoId);
    const model::RigNode& node(model::RigNodeIndex index) const;
    Mat4 nodeWorld(model::RigNodeIndex index) const; // authored space
    // A node of this instance by tag ("ctrls.ik"); nullopt when it was not created.
    std::optional<model::RigNodeIndex> findNode(const std::string& tag) const;
    void setHidden(model::RigNodeIndex index);
    // Adds an animatable attribute (value clamped to [min, max], in the
    // attribute's unit) and returns the reference constraints read it by.
    model::AttributeRef addAttribute(model::RigNodeIndex index, const std::string& name, double value, double min, double max);
    // An enum attribute: one label per value 0, 1, 2...
    model::AttributeRef addEnumAttribute(model::RigNodeIndex index, const std::string& name, int value,
                                         std::vector<std::string> labels);
    // A controller's transform channels (locks, limits, rotate order).
    model::ChannelSettings& channels(model::RigNodeIndex index);
    // Adds the constraint "<instance>::<tag>"; `settings` (one struct per kind,
    // model/Constraint.h) are in authored space: on a mirrored copy a drive's
    // rotation factor is flipped to match. Reports an error, and adds nothing,
    // when a driven node or a target is kNoNode.
    void addConstraint(const std::string& tag, std::vector<model::RigNodeIndex> driven, std::vector<model::RigNodeIndex> targets,
                       model::ConstraintSettings settings);
    // Named spaces other instances can follow ("world", "cog", "chest", "head").
    // The latest definition wins; space() gives kNoNode when none is defined.
    void defineSpace(const std::string& name, model::RigNodeIndex index);
    model::RigNodeIndex space(const std::string& name) const;
    bool mirrored() const;
    // The branch mirror M of this copy (W' = M W M): identity unless mirrored.
    const Mat4& mirrorMatrix() const;
    // Segment scale compensation on one of this instance's nodes (RigNode::scaleCompensate).
    void setScaleCompensate(model::RigNodeIndex index, bool on);
    // Children templates hanging under `joint` attach to `node`.
    void setHook(model::JointId joint, model::RigNodeIndex node);

    void error(const std::string& message, const std::string& option = {}) const;
    void warning(const std::string& message, const std::string& option = {}) const;
    bool failed() const { return m_failed; }

    // Live rebuilds (BuildCache.h): records into `fragment` what the builder
    // reads beyond its own instance (guide matrices, nodes made before
    // `firstNode`, named spaces), and marks it unreplayable if it changes a
    // node made before `firstNode`.
    void recordInto(Fragment* fragment, model::RigNodeIndex firstNode)
    {
        m_record = fragment;
        m_firstNode = firstNode;
    }

private:
    // A node made before this instance is about to be changed.
    void touch(model::RigNodeIndex index);

    void report(Severity severity, const std::string& message, const std::string& option) const;

    RigAssembly& m_assembly;
    const templates::TemplateManifest& m_manifest;
    const model::TemplateInstance& m_instance;
    std::map<std::string, Value> m_options;
    model::RigNodeIndex m_hookNode = model::kNoNode;
    mutable bool m_failed = false;
    Fragment* m_record = nullptr;
    model::RigNodeIndex m_firstNode = 0;
};

} // namespace rs::rigging
