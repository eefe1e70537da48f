#pragma once
// Internal to rs::rigging: one instance copy's generated output and the inputs
// it was generated from (BuildCache.h says what for). Node indices in the
// outputs are stored relative to the fragment's first node; an index of a node
// made before it (the hook, a named space) is stored as the node's key, so the
// fragment can be replayed where the rig's numbering has moved.
#include "rigging/BranchStage.h"
#include "rigging/BuildCache.h"
#include "rigging/RigAssembly.h"
#include "model/Rig.h"
#include "templates/TemplateRegistry.h"

#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace rs::rigging {

class BuilderRegistry;
class TemplateBuilder;
struct InstanceRecord;
struct RigAssembly;

struct Fragment {
    // --- inputs: a replay is valid while every one of them is unchanged.
    model::TemplateInstance instance; // the expanded copy
    BranchCopy copy;
    const templates::TemplateManifest* manifest = nullptr;
    const TemplateBuilder* builder = nullptr;
    std::map<std::string, Value> options;
    NodeKey hook;
    // What the builder read beyond its own instance, as it was then.
    struct NodeRead {
        model::RigNode node; // as read (its parent by key below: indices move)
        NodeKey parent;
    };
    std::vector<NodeRead> nodeReads;
    std::vector<std::pair<model::JointId, Mat4>> guideReads;
    std::vector<std::pair<std::string, std::optional<NodeKey>>> spaceReads;
    // False when the builder changed a node it did not make, or read the whole
    // guide: such a copy is generated every time.
    bool replayable = true;

    // --- outputs
    bool failed = false; // rolled back: only its diagnostics remain
    std::vector<model::RigNode> nodes;
    std::vector<model::RigConstraint> constraints;
    std::vector<std::pair<model::JointId, model::RigNodeIndex>> hooks;
    std::vector<std::pair<std::string, model::RigNodeIndex>> spaces;
    Diagnostics diagnostics;
    std::vector<NodeKey> externals; // nodes made before this fragment that its outputs refer to

    static constexpr model::RigNodeIndex kExternal = 0x80000000u;
};

struct BuildCache::Impl {
    const templates::TemplateRegistry* templates = nullptr;
    const BuilderRegistry* builders = nullptr;
    model::NamingRules naming;
    std::map<CopyKey, Fragment> fragments;
    Stats stats;
    std::optional<Result<eval::RigProgram>> program;
    std::size_t lastNodeCount = 0; // the last build's: the next one reserves as much
    ShapeSamples shapeSamples;     // the library's shapes, sampled once
    std::map<std::string, double> defaultSegments; // by template id: its default guide's mean segment (ControlSize.cpp)

    // Drops everything when the library, builders or naming rules differ from the last build's.
    void begin(const templates::TemplateRegistry& library, const BuilderRegistry& registry, const model::NamingRules& rules);
};

// The inputs of generating `record` now (everything but the reads, which the
// build context records as the builder runs).
void captureInputs(Fragment& fragment, const RigAssembly& a, const InstanceRecord& record, const TemplateBuilder* builder,
                   model::RigNodeIndex hook);
// The outputs of a generation that began with the rig at `before` sizes and `spacesBefore`.
struct AssemblySizes {
    std::size_t nodes = 0, constraints = 0, diagnostics = 0;
};
void captureOutputs(Fragment& fragment, const RigAssembly& a, AssemblySizes before,
                    const std::map<std::string, model::RigNodeIndex>& spacesBefore, bool failed);
// True when replaying `fragment` now gives what generating `record` would.
bool matches(const Fragment& fragment, const RigAssembly& a, const InstanceRecord& record, const TemplateBuilder* builder,
             model::RigNodeIndex hook);
// Appends the fragment's outputs to the assembly (nothing, and false, when a
// node it refers to is missing).
bool replay(const Fragment& fragment, RigAssembly& a);

} // namespace rs::rigging
