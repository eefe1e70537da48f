// Finalize stage: the virtual hierarchy per domain (ctrls, skin...) from the
// manifests' `hierarchy` sections. It drives pickwalk (ctrls) and the export
// skeleton (skin), independent of the physical parenting.
#include "rigging/RigAssembly.h"
#include "templates/Condition.h"
#include "templates/Structure.h"

#include <cmath>
#include <string_view>
#include <unordered_map>

namespace rs::rigging {

using model::kNoNode;
using model::RigNodeIndex;

namespace {

// Nodes of the instance registered under `id`: the node itself, or the id branch.
std::vector<RigNodeIndex> nodesOf(const RigAssembly& a, const NodesByInstance& index, const InstanceRecord& r,
                                  const std::string& id)
{
    std::vector<RigNodeIndex> out;
    auto own = index.find(a.copyOf(r.instance->id).key());
    if (own == index.end())
        return out;
    for (RigNodeIndex i : own->second) {
        const std::string_view tag = a.rig.nodes[i].key.tag;
        if (tag.size() >= id.size() && tag.compare(0, id.size(), id) == 0 && (tag.size() == id.size() || tag[id.size()] == '.'))
            out.push_back(i);
    }
    return out;
}

templates::HierarchyRule effectiveRule(RigAssembly& a, const InstanceRecord& r, const templates::HierarchyEntry& e)
{
    templates::HierarchyRule rule = e.base;
    for (const auto& [expression, overrides] : e.conditional) {
        const auto holds = templates::evaluateCondition(expression, r.options);
        if (!holds) {
            a.report(Severity::Warning, r.instance,
                     "hierarchy." + e.id + ": condition '" + expression + "': " + firstError(holds.diagnostics()));
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
    std::vector<model::JointId> joints;
    for (const std::string& tag : *rule.hook) {
        const auto& resolved = a.structureTag(*r.manifest, *r.instance, tag);
        if (!resolved.joints) {
            a.report(Severity::Warning, r.instance, "hierarchy." + e.id + ".hook: " + resolved.error);
            continue;
        }
        joints.insert(joints.end(), resolved.joints->begin(), resolved.joints->end());
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
            auto found = a.rig.find(a.keyOf(*r.instance, id));
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
    const NodesByInstance index = indexNodesByInstance(a.rig);
    for (const InstanceRecord& r : a.records)
        for (const auto& e : r.manifest->hierarchy) {
            Pending p{&r, &e, effectiveRule(a, r, e), nodesOf(a, index, r, e.id)};
            registerHooks(a, r, e, p.rule, p.nodes);
            pending.push_back(std::move(p));
        }
    for (const Pending& p : pending)
        linkParents(a, *p.record, *p.entry, p.rule, p.nodes);
}

} // namespace rs::rigging
