// Finalize stage: the virtual hierarchy per domain (ctrls, skin...) from the
// manifests' `hierarchy` sections. It drives pickwalk (ctrls) and the export
// skeleton (skin), independent of the physical parenting.
#include "build/RigAssembly.h"
#include "templates/Condition.h"
#include "templates/Structure.h"

#include <cmath>

namespace rs::build {

using model::kNoNode;
using model::RigNodeIndex;

namespace {

std::string tagOf(const model::RigNode& node) { return node.id.substr(node.id.find("::") + 2); }

// Nodes of the instance registered under `id`: the node itself, or the id branch.
std::vector<RigNodeIndex> nodesOf(const RigAssembly& a, const InstanceRecord& r, const std::string& id)
{
    std::vector<RigNodeIndex> out;
    const std::string prefix = r.instance->name + "::";
    for (RigNodeIndex i = 0; i < a.rig.nodes.size(); ++i) {
        const auto& n = a.rig.nodes[i];
        if (n.id.compare(0, prefix.size(), prefix) != 0)
            continue;
        const std::string tag = tagOf(n);
        if (tag == id || tag.rfind(id + ".", 0) == 0)
            out.push_back(i);
    }
    return out;
}

templates::HierarchyRule effectiveRule(RigAssembly& a, const InstanceRecord& r, const templates::HierarchyEntry& e)
{
    templates::HierarchyRule rule = e.base;
    for (const auto& [expression, overrides] : e.conditional) {
        std::string error;
        auto holds = templates::evaluateCondition(expression, r.options, error);
        if (!holds) {
            a.report(Severity::Warning, r.instance, "hierarchy." + e.id + ": condition '" + expression + "': " + error);
            continue;
        }
        if (!*holds)
            continue;
        if (overrides.root) rule.root = overrides.root;
        if (overrides.parent) rule.parent = overrides.parent;
        if (overrides.hook) rule.hook = overrides.hook;
        if (overrides.chain) rule.chain = overrides.chain;
    }
    return rule;
}

void registerHooks(RigAssembly& a, const InstanceRecord& r, const templates::HierarchyEntry& e,
                   const templates::HierarchyRule& rule, const std::vector<RigNodeIndex>& nodes)
{
    if (!rule.hook || nodes.empty())
        return;
    templates::StructureResolver resolver(*r.manifest, *r.instance);
    std::vector<model::JointId> joints;
    for (const std::string& tag : *rule.hook) {
        std::string error;
        auto resolved = resolver.tag(tag, &error);
        if (!resolved) {
            a.report(Severity::Warning, r.instance, "hierarchy." + e.id + ".hook: " + error);
            continue;
        }
        joints.insert(joints.end(), resolved->begin(), resolved->end());
    }
    // Counts that differ are resampled evenly along the nodes.
    for (std::size_t j = 0; j < joints.size(); ++j) {
        const std::size_t k = joints.size() == 1 ? 0
            : static_cast<std::size_t>(std::lround(double(j) * double(nodes.size() - 1) / double(joints.size() - 1)));
        a.virtualHooks[e.domain()][joints[j]] = nodes[std::min(k, nodes.size() - 1)];
    }
}

void linkParents(RigAssembly& a, const InstanceRecord& r, const templates::HierarchyEntry& e,
                 const templates::HierarchyRule& rule, const std::vector<RigNodeIndex>& nodes)
{
    const bool chain = rule.chain.value_or(false);
    std::vector<RigNodeIndex> parents;
    if (rule.parent)
        for (const std::string& id : *rule.parent) {
            auto found = a.rig.find(r.instance->name + "::" + id);
            if (found) parents.push_back(*found);
            else a.report(Severity::Warning, r.instance, "hierarchy." + e.id + ".parent: no rig node '" + id + "'");
        }
    const RigNodeIndex rootParent = r.instance->parentJoint == model::kNoId
        ? kNoNode : a.virtualHookFor(e.domain(), r.instance->parentJoint);
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        auto& node = a.rig.nodes[nodes[k]];
        node.setInVirtualHierarchy(true);
        if (chain && k > 0)
            node.virtualParent = nodes[k - 1];
        else if (!parents.empty())
            node.virtualParent = parents[std::min(k, parents.size() - 1)];
        else if (rule.root.value_or(false))
            node.virtualParent = rootParent;
    }
}

} // namespace

void buildVirtualHierarchy(RigAssembly& a)
{
    struct Pending {
        const InstanceRecord* record;
        const templates::HierarchyEntry* entry;
        templates::HierarchyRule rule;
        std::vector<RigNodeIndex> nodes;
    };
    std::vector<Pending> pending;
    for (const InstanceRecord& r : a.records)
        for (const auto& e : r.manifest->hierarchy) {
            Pending p{&r, &e, effectiveRule(a, r, e), nodesOf(a, r, e.id)};
            registerHooks(a, r, e, p.rule, p.nodes);
            pending.push_back(std::move(p));
        }
    for (const Pending& p : pending)
        linkParents(a, *p.record, *p.entry, p.rule, p.nodes);
}

} // namespace rs::build
