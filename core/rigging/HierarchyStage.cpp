// Finalize stage: the virtual hierarchy per domain (ctrls, skin...) from the
// manifests' `hierarchy` sections. It drives pickwalk (ctrls) and the export
// skeleton (skin), independent of the physical parenting. The common option
// `virtual_parent` (an instance's name) attaches an instance's root nodes to
// the closest node of that instance in the same domain instead of its hook's.
#include "rigging/RigAssembly.h"
#include "templates/Condition.h"
#include "templates/Structure.h"

#include <cmath>
#include <optional>
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

// The common option `virtual_parent` (an instance name): the nodes of that
// instance in `domain`, from its copy on this instance's branch if it has one,
// else its unbranched copy, else its first. Empty with a warning when there is
// no such instance or it has no node in the domain.
std::vector<RigNodeIndex> virtualParentCandidates(RigAssembly& a, const NodesByInstance& index, const InstanceRecord& r,
                                                  const std::string& domain)
{
    auto option = r.options.find("virtual_parent");
    const std::string* name = option == r.options.end() ? nullptr : std::get_if<std::string>(&option->second);
    if (!name || name->empty())
        return {};
    const std::string branch = a.copyOf(r.instance->id).branch();
    std::optional<CopyKey> best;
    int bestRank = 3;
    for (const auto& [expanded, copy] : a.expanded.copies) {
        if (copy.baseName != *name)
            continue;
        const int rank = copy.branch() == branch ? 0 : copy.branch().empty() ? 1 : 2;
        if (rank < bestRank || (rank == bestRank && best && copy.key() < *best)) {
            best = copy.key();
            bestRank = rank;
        }
    }
    std::vector<RigNodeIndex> out;
    if (best)
        if (auto nodes = index.find(*best); nodes != index.end())
            for (RigNodeIndex i : nodes->second) {
                const std::string& tag = a.rig.nodes[i].key.tag;
                if (tag.compare(0, domain.size(), domain) == 0 && tag.size() > domain.size() && tag[domain.size()] == '.')
                    out.push_back(i);
            }
    if (out.empty())
        a.report(Severity::Warning, r.instance, "virtual_parent: " +
                                                   (best ? "instance '" + *name + "' has no " + domain + " node"
                                                         : "no instance named '" + *name + "'") +
                                                   "; the " + domain + " hierarchy attaches to the parent as usual");
    return out;
}

RigNodeIndex closestOf(const model::Rig& rig, const std::vector<RigNodeIndex>& candidates, RigNodeIndex to)
{
    const Vec3 at = translationOf(rig.nodes[to].worldMatrix);
    RigNodeIndex best = kNoNode;
    double bestDistance = 0.0;
    for (RigNodeIndex c : candidates) {
        const double d = glm::length(translationOf(rig.nodes[c].worldMatrix) - at);
        if (best == kNoNode || d < bestDistance) {
            best = c;
            bestDistance = d;
        }
    }
    return best;
}

// A node `virtual_parent` attached elsewhere, with the parent it would have had.
struct Redirected {
    const InstanceRecord* record;
    RigNodeIndex node;
    RigNodeIndex usual;
};

void linkParents(RigAssembly& a, const NodesByInstance& index, const InstanceRecord& r, const templates::HierarchyEntry& e,
                 const templates::HierarchyRule& rule, const std::vector<RigNodeIndex>& nodes,
                 std::vector<Redirected>& redirected)
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
    std::vector<RigNodeIndex> chosen; // `virtual_parent`: the closest of these instead of rootParent
    if (rule.root.value_or(false) && !nodes.empty())
        chosen = virtualParentCandidates(a, index, r, e.domain());
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        auto& node = a.rig.nodes[nodes[k]];
        node.setInVirtualHierarchy(true);
        if (chain && k > 0)
            node.virtualParent = nodes[k - 1];
        else if (!parents.empty())
            node.virtualParent = parents[std::min(k, parents.size() - 1)];
        else if (rule.root.value_or(false)) {
            node.virtualParent = chosen.empty() ? rootParent : closestOf(a.rig, chosen, nodes[k]);
            if (!chosen.empty())
                redirected.push_back({&r, nodes[k], rootParent});
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
    for (const InstanceRecord& r : a.records)
        for (const auto& e : r.manifest->hierarchy) {
            Pending p{&r, &e, effectiveRule(a, r, e), nodesOf(a, index, r, e.id)};
            registerHooks(a, r, e, p.rule, p.nodes);
            pending.push_back(std::move(p));
        }
    std::vector<Redirected> redirected;
    for (const Pending& p : pending)
        linkParents(a, index, *p.record, *p.entry, p.rule, p.nodes, redirected);
    // A `virtual_parent` below the instance itself would close a loop: refused.
    for (const Redirected& r : redirected) {
        RigNodeIndex at = a.rig.nodes[r.node].virtualParent;
        for (std::size_t guard = 0; at != kNoNode && at != r.node && guard <= a.rig.nodes.size(); ++guard)
            at = a.rig.nodes[at].virtualParent;
        if (at != r.node)
            continue;
        a.report(Severity::Warning, r.record->instance, "virtual_parent: '" + a.rig.nodes[a.rig.nodes[r.node].virtualParent].path +
                                                            "' hangs below '" + a.rig.nodes[r.node].path +
                                                            "' in the virtual hierarchy (a loop); it attaches to the parent as usual");
        a.rig.nodes[r.node].virtualParent = r.usual;
    }
}

} // namespace rs::rigging
