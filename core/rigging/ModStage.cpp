// The mod stage: which copies a mod applies to, how a reference finds its
// node, the warnings, the checks that keep the rig evaluable (no cycle), and
// the nodes put back parents first after a reparent.
#include "rigging/ModStage.h"

#include <algorithm>
#include <functional>
#include <map>

namespace rs::rigging {

using model::kNoNode;
using model::RigNodeIndex;

namespace {

std::string ownerText(const model::GuideDocument& guide, const model::ModInstance& owner)
{
    if (const model::TemplateInstance* i = guide.instance(owner.id))
        return i->name;
    return owner.name.empty() ? "#" + std::to_string(owner.id) : owner.name;
}

// The branch copies of each authored instance this build made.
std::map<InstanceId, std::vector<std::string>> builtCopies(const RigAssembly& a)
{
    std::map<InstanceId, std::vector<std::string>> out;
    for (const InstanceRecord& r : a.records) {
        const BranchCopy& copy = a.copyOf(r.instance->id);
        out[copy.original].push_back(copy.branch());
    }
    return out;
}

// The mirrored branch copies and the plane each is reflected through.
std::map<CopyKey, int> mirrorPlanes(const RigAssembly& a)
{
    std::map<CopyKey, int> out;
    for (const InstanceRecord& r : a.records) {
        const BranchCopy& copy = a.copyOf(r.instance->id);
        for (int axis = 0; axis < 3; ++axis)
            if (copy.mirror[axis][axis] < 0.0) {
                out[{copy.original, copy.branch()}] = axis;
                break;
            }
    }
    return out;
}

// Runs `apply` once per copy of each mod (reporting an owner with none).
void forEachCopy(RigAssembly& a, const model::GuideDocument& guide, bool quiet,
                 const std::function<void(ModApplication&)>& apply)
{
    const auto copies = builtCopies(a);
    const auto planes = mirrorPlanes(a);
    for (std::size_t i = 0; i < guide.mods.size(); ++i) {
        const model::Mod& mod = guide.mods[i];
        if (mod.isGlobal()) {
            ModApplication app(a, guide, mod, i, {}, quiet);
            apply(app);
            continue;
        }
        const auto it = copies.find(mod.owner.id);
        if (it == copies.end()) {
            if (!quiet) {
                ModApplication app(a, guide, mod, i, {}, quiet);
                app.warn(guide.instance(mod.owner.id) ? "its instance was not built; the mod is kept in the guide"
                                                       : "the guide has no instance '" + ownerText(guide, mod.owner) +
                                                             "'; the mod is kept in the guide",
                         guide.instance(mod.owner.id) ? Subject::ofInstance(mod.owner.id) : Subject{});
            }
            continue;
        }
        for (const std::string& branch : it->second) {
            ModApplication app(a, guide, mod, i, branch, quiet);
            app.mirrorPlanes = &planes;
            apply(app);
        }
    }
}

// Nodes stored parents first again after a reparent put a node before its
// new parent: every index the assembly holds is renumbered.
void reorderParentsFirst(RigAssembly& a)
{
    model::Rig& rig = a.rig;
    const std::size_t n = rig.nodes.size();
    std::vector<RigNodeIndex> order, newIndex(n, kNoNode);
    order.reserve(n);
    std::vector<RigNodeIndex> stack;
    for (RigNodeIndex i = 0; i < n; ++i) {
        for (RigNodeIndex k = i; k != kNoNode && newIndex[k] == kNoNode; k = rig.nodes[k].parent)
            stack.push_back(k); // the node and its ancestors not placed yet, nearest first
        for (auto it = stack.rbegin(); it != stack.rend(); ++it) {
            newIndex[*it] = RigNodeIndex(order.size());
            order.push_back(*it);
        }
        stack.clear();
    }
    auto remap = [&](RigNodeIndex& i) {
        if (i != kNoNode) i = newIndex[i];
    };
    std::vector<model::RigNode> nodes;
    nodes.reserve(n);
    for (RigNodeIndex old : order)
        nodes.push_back(std::move(rig.nodes[old]));
    rig.nodes = std::move(nodes);
    rig.byKey.clear();
    rig.byPath.clear();
    for (RigNodeIndex i = 0; i < n; ++i) {
        model::RigNode& node = rig.nodes[i];
        remap(node.parent);
        remap(node.virtualParent);
        remap(node.twin);
        rig.byKey[node.key] = i;
        rig.byPath[node.path] = i;
    }
    for (model::RigConstraint& c : rig.constraints)
        model::forEachNodeIndex(c, remap);
    for (auto& [name, members] : rig.sets)
        for (RigNodeIndex& i : members) remap(i);
    for (auto& [joint, node] : a.hooks) remap(node);
    for (auto& [domain, table] : a.virtualHooks)
        for (auto& [joint, node] : table) remap(node);
    for (auto& [name, node] : a.spaces) remap(node);
}

} // namespace

std::string ModApplication::text(const model::ModRef& ref) const
{
    std::string out;
    if (!ref.instance.isNone()) {
        out = ownerText(guide, ref.instance);
        const std::string b = ref.branch.value_or(branch);
        if (!b.empty())
            out += "." + b;
    }
    out += "::" + ref.tag;
    if (!ref.channel.empty())
        out += "@" + ref.channel;
    return out;
}

void ModApplication::warn(const std::string& message, Subject subject)
{
    if (quiet)
        return;
    std::string who = std::string(model::modKindName(mod.kind())) + " mod";
    if (mod.isGlobal())
        who = "global " + who;
    else
        who += " of '" + ownerText(guide, mod.owner) + (branch.empty() ? "" : "." + branch) + "'";
    Diagnostic d = makeWarning(mod.where, who + ": " + message);
    if (subject.isNone() && guide.instance(mod.owner.id))
        subject = Subject::ofInstance(mod.owner.id, branch);
    d.subject = std::move(subject);
    a.rig.diagnostics.push_back(std::move(d));
}

std::optional<RigNodeIndex> ModApplication::resolve(const model::ModRef& ref, const std::string& role)
{
    if (ref.instance.isNone()) {
        if (auto node = a.rig.find(NodeKey{kNoId, {}, ref.tag}))
            return node;
        warn(role + " '" + text(ref) + "': the rig has no such node; the mod is kept in the guide");
        return std::nullopt;
    }
    const model::TemplateInstance* instance = guide.instance(ref.instance.id);
    if (!instance) {
        warn(role + " '" + text(ref) + "': the guide has no instance '" + ownerText(guide, ref.instance) +
             "'; the mod is kept in the guide");
        return std::nullopt;
    }
    const std::string b = ref.branch.value_or(branch);
    if (auto node = a.rig.find(NodeKey{instance->id, b, ref.tag}))
        return node;
    if (!ref.branch && !b.empty())
        if (auto node = a.rig.find(NodeKey{instance->id, {}, ref.tag}))
            return node;
    std::string hint;
    if (!ref.branch && b.empty()) { // a branched instance named without its branch
        std::set<std::string> branches;
        for (const InstanceRecord& r : a.records)
            if (const BranchCopy& copy = a.copyOf(r.instance->id); copy.original == instance->id && !copy.branch().empty())
                branches.insert(copy.branch());
        if (!branches.empty())
            hint = " (the instance is built as branches " + *branches.begin() + (branches.size() > 1 ? ", " + *branches.rbegin() : "") +
                   ": name one, e.g. " + instance->name + "." + *branches.begin() + "::" + ref.tag + ")";
    }
    warn(role + " '" + text(ref) + "': the rig has no such node" + hint + "; the mod is kept in the guide",
         Subject::ofInstance(instance->id, b));
    return std::nullopt;
}

double ModApplication::channelSign(RigNodeIndex node, const std::string& channel) const
{
    const int t = model::channelIndex(channel);
    if (!mirrorPlanes || t < 0 || t >= 6 || !mirrorPlanes->count(CopyKey{mod.owner.id, branch}))
        return 1.0;
    const auto plane = mirrorPlanes->find(a.rig.nodes[node].key.copy());
    if (plane == mirrorPlanes->end())
        return 1.0;
    // A reflection negates the translation along its normal and the rotations about the other two axes.
    const bool along = t % 3 == plane->second;
    return (t < 3) == along ? -1.0 : 1.0;
}

NodeKey ModApplication::constraintKey(const std::string& what) const
{
    const std::string tag = "mods." + std::to_string(index) + "." + what;
    return guide.instance(mod.owner.id) ? NodeKey{mod.owner.id, branch, tag} : NodeKey{kNoId, {}, tag};
}

std::string ModApplication::constraintPath(const std::string& what) const
{
    const NodeKey key = constraintKey(what);
    const model::TemplateInstance* owner = guide.instance(key.instance);
    return (owner ? owner->name + (branch.empty() ? "" : "." + branch) : std::string()) + "::" + key.tag;
}

bool ModApplication::dependsOn(RigNodeIndex node, RigNodeIndex source) const
{
    const model::Rig& rig = a.rig;
    std::vector<std::vector<RigNodeIndex>> followers(rig.nodes.size()); // node -> nodes placed from it
    for (RigNodeIndex i = 0; i < rig.nodes.size(); ++i)
        if (rig.nodes[i].parent != kNoNode)
            followers[rig.nodes[i].parent].push_back(i);
    for (const model::RigConstraint& c : rig.constraints) {
        if (c.kind() == model::ConstraintKind::Visibility || c.kind() == model::ConstraintKind::DrivenKey)
            continue;
        for (RigNodeIndex t : c.targets)
            followers[t].insert(followers[t].end(), c.driven.begin(), c.driven.end());
    }
    std::vector<bool> seen(rig.nodes.size(), false);
    std::vector<RigNodeIndex> work{source};
    seen[source] = true;
    while (!work.empty()) {
        const RigNodeIndex i = work.back();
        work.pop_back();
        if (i == node)
            return true;
        for (RigNodeIndex f : followers[i])
            if (!seen[f]) { seen[f] = true; work.push_back(f); }
    }
    return false;
}

void applyRigMods(RigAssembly& a, const model::GuideDocument& guide)
{
    if (guide.mods.empty())
        return;
    bool reorder = false;
    forEachCopy(a, guide, false, [&](ModApplication& app) {
        std::visit(
            [&](const auto& m) {
                using T = std::decay_t<decltype(m)>;
                if constexpr (std::is_same_v<T, model::SpaceMod>) app.space(m);
                else if constexpr (std::is_same_v<T, model::ConstraintMod>) app.constraint(m);
                else if constexpr (std::is_same_v<T, model::ParentMod>) reorder = app.parent(m) || reorder;
                else if constexpr (std::is_same_v<T, model::HideMod>) app.hide(m);
                else if constexpr (std::is_same_v<T, model::PlugMod>) app.plug(m);
                else if constexpr (std::is_same_v<T, model::DriveMod>) app.drive(m);
                else static_assert(std::is_same_v<T, model::VdagMod>); // after the virtual hierarchy
            },
            app.mod.settings);
    });
    if (reorder)
        reorderParentsFirst(a);
}

void applyHierarchyMods(RigAssembly& a, const model::GuideDocument& guide)
{
    if (guide.mods.empty())
        return;
    forEachCopy(a, guide, true, [&](ModApplication& app) {
        if (const auto* hide = std::get_if<model::HideMod>(&app.mod.settings))
            app.hideCurves(*hide);
        if (const auto* vdag = std::get_if<model::VdagMod>(&app.mod.settings)) {
            app.quiet = false; // reported here only
            app.vdag(*vdag);
        }
    });
}

} // namespace rs::rigging
