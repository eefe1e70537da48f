#pragma once
// Internal to rs::rigging: the rig under construction plus the lookup tables the
// stages share (physical hooks per guide joint, virtual hooks per domain).
#include "rigging/BranchStage.h"
#include "eval/RigProgram.h"
#include "model/Rig.h"
#include "templates/Structure.h"
#include "templates/TemplateRegistry.h"

#include <map>
#include <set>
#include <optional>
#include <memory>
#include <vector>
#include <string>
#include <string_view>
#include <unordered_map>

namespace rs::rigging {

struct InstanceRecord {
    const templates::TemplateManifest* manifest = nullptr;
    const model::TemplateInstance* instance = nullptr;
    std::map<std::string, Value> options;
    bool built = false;
};

struct RigAssembly {
    RigAssembly(const model::GuideDocument& guide, const ExpandedGuide& expanded, const templates::TemplateRegistry& templates)
        : guide(guide), expanded(expanded), templates(templates)
    {
    }

    const model::GuideDocument& guide;   // the expanded guide: one instance per branch copy
    const ExpandedGuide& expanded;
    const templates::TemplateRegistry& templates;
    model::Rig rig;
    std::map<model::JointId, model::RigNodeIndex> hooks;                          // physical
    std::map<std::string, std::map<model::JointId, model::RigNodeIndex>> virtualHooks; // domain -> joint -> node
    std::map<std::string, model::RigNodeIndex> spaces;                             // named spaces
    std::vector<InstanceRecord> records;                                            // document order
    // Guide lookups computed once per build (the document only offers linear scans).
    struct GuideEntry {
        const model::TemplateInstance* owner = nullptr;
        const model::GuideJoint* joint = nullptr;
        Mat4 world{1.0};
    };
    std::unordered_map<model::JointId, GuideEntry> guideIndex;

    // Structure lookups memoised per build (instance name + tag or address):
    // builders, shapes and the hierarchy ask for the same tags many times.
    struct Resolved {
        std::optional<std::vector<model::JointId>> joints;
        std::string error;
    };
    std::unordered_map<std::string, Resolved> structureCache;
    // One resolver per instance: it memoises the chain and the tags, so the
    // many addresses of one instance (`chain[0]`, `chain[1]`...) share them.
    std::unordered_map<const model::TemplateInstance*, templates::StructureResolver> resolvers;
    // The finished rig compiled by the evaluation check (a session takes it
    // through its BuildCache instead of compiling the rig a second time).
    std::optional<Result<eval::RigProgram>> program;
    // Set by the override stage's first half for its second: the post transform
    // it applied to every node (the shapes are placed in the guide's frame, so
    // they undo it), the mirrored branch copies, the records that found a node.
    Mat4 post{1.0};
    std::set<CopyKey> mirroredCopies;
    std::set<NodeKey> appliedOverrides;
    // Per built instance copy: how much its shapes are scaled (ControlSize.cpp).
    std::unordered_map<model::InstanceId, double> controlScales;
    double controlScaleOf(model::InstanceId expandedInstance) const;
    const Resolved& structureTag(const templates::TemplateManifest& manifest, const model::TemplateInstance& instance,
                                 const std::string& tag)
    {
        return resolveStructure(manifest, instance, true, tag);
    }
    const Resolved& structureAddress(const templates::TemplateManifest& manifest, const model::TemplateInstance& instance,
                                     const std::string& address)
    {
        return resolveStructure(manifest, instance, false, address);
    }
    const Resolved& resolveStructure(const templates::TemplateManifest& manifest, const model::TemplateInstance& instance,
                                     bool isTag, const std::string& text);

    void indexGuide(); // also places mirrored branch copies
    model::JointId authoredJoint(model::JointId expandedJoint) const;
    const BranchCopy& copyOf(model::InstanceId expandedInstance) const { return expanded.copies.at(expandedInstance); }
    // The joint a guide joint hangs from: its parent, or for a root the hook joint.
    model::JointId upstreamJoint(model::JointId joint) const;
    Mat4 guideWorldMatrix(model::JointId joint) const;

    model::RigNodeIndex addNode(model::RigNode node) { return rig.add(std::move(node)); }
    // The key and display path of a node (or constraint) `tag` of an expanded instance.
    NodeKey keyOf(const model::TemplateInstance& instance, const std::string& tag) const;
    std::string pathOf(const model::TemplateInstance& instance, const std::string& tag) const { return instance.name + "::" + tag; }
    // The hook node a child hanging under `joint` attaches to, walking up the guide.
    model::RigNodeIndex physicalHookFor(model::JointId joint) const;
    model::RigNodeIndex virtualHookFor(const std::string& domain, model::JointId joint) const;
    // A build message about an (expanded) instance: its subject is the authored
    // instance and the branch copy, so the log selects the cause.
    void report(Severity severity, const model::TemplateInstance* instance, const std::string& message);
    Subject subjectOf(const model::TemplateInstance& instance) const;
};

// Node indices per instance copy, in node order, so a stage scans only one
// instance's nodes.
using NodesByInstance = std::map<CopyKey, std::vector<model::RigNodeIndex>>;
NodesByInstance indexNodesByInstance(const model::Rig& rig);

// The library's shapes sampled as polylines. A BuildCache keeps them across
// live rebuilds (the library stays; see BuildCache::Impl::begin).
struct SampledShape {
    std::vector<std::vector<Vec3>> curves;
    double extent = 0.0;
};
using ShapeSamples = std::map<const templates::Shape*, SampledShape>;

// Stages run by buildRig after generation. The override stage comes in two
// halves (OverrideStage.cpp): `applyRigOverrides` sets channels, display names
// and the post transform, which the program compiles from; then, beside the
// compile, `applyShapes` gives the template shapes, `applyShapeOverrides` the
// rigger's shape edits and the mirrored branch copies' curves (their twins',
// reflected), and reports the records that found no node (kept in the guide).
void applyRigOverrides(RigAssembly& assembly, const model::GuideDocument& guide, const model::RestoreToggles& restore);
void applyShapes(RigAssembly& assembly, ShapeSamples& samples);
// Before the shapes: each built instance's control scale, its guide's mean
// segment over its template's default guide's (ControlSize.cpp).
// `defaultSegments` (by template id) memoises the default guides' across live
// rebuilds; may be null.
class BuilderRegistry;
void computeControlScales(RigAssembly& assembly, const BuilderRegistry& builders, std::map<std::string, double>* defaultSegments);
void applyShapeOverrides(RigAssembly& assembly, const model::GuideDocument& guide, const model::RestoreToggles& restore);
void mirrorBranchShapes(RigAssembly& assembly);
void buildVirtualHierarchy(RigAssembly& assembly);
// The common option `isolate_skin` (IsolateSkinStage.cpp): the skin joints of
// the instances that set it hang from skin joints only, following the skin
// virtual hierarchy, each constrained to the node it hung under. Needs the
// virtual hierarchy; must run before the program compiles (it adds constraints).
bool wantsIsolatedSkin(const RigAssembly& assembly);
void isolateSkin(RigAssembly& assembly);

// Cross-cutting work after every instance is built (Rigify's generator plugins):
// each plugin sees the whole rig and reports through the assembly.
class GeneratorPlugin {
public:
    virtual ~GeneratorPlugin() = default;
    virtual const char* name() const = 0;
    virtual void finalize(RigAssembly& assembly) const = 0;
};
// Controller set, skin-root and naming checks, in the order they run.
const std::vector<std::unique_ptr<GeneratorPlugin>>& builtinPlugins();

// Seed 004's cleanup, the part a rig model needs: FK chains compensate the
// parent segment's scale (scaling the upper arm control lengthens the upper
// arm, the forearm keeps its size and follows the elbow).
void compensateSegmentScale(RigAssembly& assembly);
// The evaluation check: the rig must evaluate. Constraint cycles and dangling
// attribute paths are build errors, reported when the rig is built rather than
// when the animator first moves a control. The compiled program is the one the
// session evaluates. Compiling reads only what generation and configuration
// made (nodes, their rest placement, channels and attributes, constraints),
// so it may run beside the shape and hierarchy stages; `reportProgram` adds its
// messages to the build log afterwards.
void compileProgram(RigAssembly& assembly);
void reportProgram(RigAssembly& assembly);

} // namespace rs::rigging
