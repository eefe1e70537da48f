// Finalize stage: the virtual hierarchy per domain (ctrls, skin...) from the
// manifests' `hierarchy` sections. It drives pickwalk (ctrls) and the export
// skeleton (skin), independent of the physical parenting. A `root: on` node
// hangs from the parent template's hook, or with the `virtual_parent` option
// from the closest node (of its domain) of the template instance it names.
#include "rigging/RigAssembly.h"
#include "templates/Condition.h"
#include "templates/Structure.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <map>
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

// The `virtual_parent` option: the instance copy named by it (the copy of the
// same branch when the named instance is branched too, else its first), or
// nothing, with a warning naming the option, when no instance has that name or
// it is the instance itself or hangs below it (a loop).
const std::vector<RigNodeIndex>* virtualParentNodes(RigAssembly& a, const NodesByInstance& index, const InstanceRecord& r)
{
    const auto option = r.options.find("virtual_parent");
    if (option == r.options.end() || !std::holds_alternative<std::string>(option->second))
        return nullptr;
    const std::string& name = std::get<std::string>(option->second);
    if (name.empty())
        return nullptr;
    const BranchCopy& own = a.copyOf(r.instance->id);
    const InstanceRecord* found = nullptr;
    for (const InstanceRecord& other : a.records) {
        const BranchCopy& copy = a.copyOf(other.instance->id);
        if (copy.baseName != name && other.instance->name != name)
            continue;
        if (!found || copy.branch() == own.branch())
            found = &other;
    }
    auto refuse = [&](const std::string& why) {
        a.report(Severity::Warning, r.instance, "option virtual_parent = '" + name + "': " + why +
                                                    "; the virtual hierarchy keeps the parent template's hook");
        return nullptr;
    };
    if (!found)
        return refuse("no template instance has that name");
    for (const model::TemplateInstance* at = found->instance; at; at = at->parent == model::kNoId ? nullptr : a.guide.instance(at->parent))
        if (a.copyOf(at->id).original == own.original)
            return refuse("it is this instance or hangs below it");
    const auto nodes = index.find(a.copyOf(found->instance->id).key());
    return nodes == index.end() ? nullptr : &nodes->second;
}

// Of `candidates`, the node of `domain` closest (at rest) to `node`.
RigNodeIndex closestInDomain(const RigAssembly& a, const std::vector<RigNodeIndex>& candidates, const std::string& domain,
                             RigNodeIndex node)
{
    const Vec3 at = translationOf(a.rig.nodes[node].worldMatrix);
    RigNodeIndex best = kNoNode;
    double bestDistance = 0.0;
    for (RigNodeIndex c : candidates) {
        if (a.rig.nodes[c].domain() != domain)
            continue;
        const double d = glm::length(translationOf(a.rig.nodes[c].worldMatrix) - at);
        if (best == kNoNode || d < bestDistance) {
            best = c;
            bestDistance = d;
        }
    }
    return best;
}

void linkParents(RigAssembly& a, const InstanceRecord& r, const templates::HierarchyEntry& e,
                 const templates::HierarchyRule& rule, const std::vector<RigNodeIndex>& nodes,
                 const std::vector<RigNodeIndex>* virtualParents)
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
        else if (rule.root.value_or(false)) {
            const RigNodeIndex chosen = virtualParents ? closestInDomain(a, *virtualParents, e.domain(), nodes[k]) : kNoNode;
            node.virtualParent = chosen != kNoNode ? chosen : rootParent;
        }
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
    std::map<const InstanceRecord*, const std::vector<RigNodeIndex>*> virtualParents;
    for (const InstanceRecord& r : a.records) {
        virtualParents[&r] = virtualParentNodes(a, index, r);
        for (const auto& e : r.manifest->hierarchy) {
            Pending p{&r, &e, effectiveRule(a, r, e), nodesOf(a, index, r, e.id)};
            registerHooks(a, r, e, p.rule, p.nodes);
            pending.push_back(std::move(p));
        }
    }
    for (const Pending& p : pending)
        linkParents(a, *p.record, *p.entry, p.rule, p.nodes, virtualParents[p.record]);
}

} // namespace rs::rigging
