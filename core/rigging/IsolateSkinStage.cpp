// Finalize stage: the common option `isolate_skin` (Mikan's build_isolate_skin,
// its `sk_` skeleton under `::bind`). Builders hang skin joints under the
// controllers and setup joints that move them, so the physical hierarchy of an
// instance's skin joints is mixed with its rig. With the option on, each skin
// joint of that instance copy is reparented onto its nearest skin-joint
// ancestor in the skin virtual hierarchy (the export skeleton), or, at the top,
// onto the world's joint group (the space `joint`; a rig without one gets a
// `::bind` group under its root), and a parent constraint keeping the rest
// offset makes it follow the node it hung under. Evaluated poses are unchanged:
// the constraint reproduces the old parent's world times the rest local (a
// one-target parent constraint copies the whole transform, eval/Solvers.cpp),
// and it is put before every other constraint on the joint, so a twist or a
// point constraint still acts on the placement it acted on before.
//
// Not inherited, as in Mikan (get_opt reads the template's own option): each
// instance that wants it sets it. A skin joint is kept where it is, with a
// warning, when it compensates its parent's scale (no builder makes one; a mod
// can) or when its skin ancestor hangs physically below it (a loop).
#include "rigging/RigAssembly.h"

#include <map>
#include <set>

namespace rs::rigging {

using model::kNoNode;
using model::RigNodeIndex;
using model::RigNodeKind;

namespace {

bool isSkinJoint(const model::RigNode& node) { return node.kind == RigNodeKind::Joint && node.domain() == "skin"; }

bool isOn(const InstanceRecord& r)
{
    auto it = r.options.find("isolate_skin");
    return it != r.options.end() && std::holds_alternative<bool>(it->second) && std::get<bool>(it->second);
}

std::set<CopyKey> isolatedCopies(const RigAssembly& a)
{
    std::set<CopyKey> out;
    for (const InstanceRecord& r : a.records)
        if (r.built && isOn(r))
            out.insert(a.copyOf(r.instance->id).key());
    return out;
}

// The world's joint group (`::bind` in Mikan), made under the rig's root when no world names one.
RigNodeIndex jointGroup(RigAssembly& a)
{
    if (auto it = a.spaces.find("joint"); it != a.spaces.end() && it->second != kNoNode)
        return it->second;
    const NodeKey key{model::kNoId, {}, "bind"};
    if (auto found = a.rig.find(key))
        return *found;
    model::RigNode bind;
    bind.key = key;
    bind.path = "::bind";
    bind.name = "bind";
    bind.parent = 0;
    bind.hidden = false;
    return a.addNode(std::move(bind));
}

// The nearest skin joint above `node` in the skin virtual hierarchy, kNoNode at the top.
RigNodeIndex skinAncestor(const model::Rig& rig, RigNodeIndex node)
{
    RigNodeIndex p = rig.nodes[node].virtualParent;
    for (std::size_t guard = 0; p != kNoNode && !isSkinJoint(rig.nodes[p]) && guard <= rig.nodes.size(); ++guard)
        p = rig.nodes[p].virtualParent;
    return p != kNoNode && isSkinJoint(rig.nodes[p]) ? p : kNoNode;
}

bool hangsBelow(const model::Rig& rig, RigNodeIndex node, RigNodeIndex ancestor)
{
    for (std::size_t guard = 0; node != kNoNode && guard <= rig.nodes.size(); ++guard, node = rig.nodes[node].parent)
        if (node == ancestor)
            return true;
    return false;
}

model::RigConstraint followConstraint(const model::RigNode& joint, RigNodeIndex index, RigNodeIndex target)
{
    model::RigConstraint c;
    c.key = joint.key;
    c.key.tag = "cns.isolate." + joint.key.tag;
    c.path = joint.path.substr(0, joint.path.find("::")) + "::" + c.key.tag;
    c.owner = joint.owner;
    c.driven = {index};
    c.targets = {target};
    c.settings = model::ParentConstraint{.weights = {}, .keepOffset = true};
    return c;
}

} // namespace

bool wantsIsolatedSkin(const RigAssembly& a)
{
    for (const InstanceRecord& r : a.records)
        if (r.built && isOn(r))
            return true;
    return false;
}

void isolateSkin(RigAssembly& a)
{
    const std::set<CopyKey> copies = isolatedCopies(a);
    if (copies.empty())
        return;
    std::map<CopyKey, const model::TemplateInstance*> instances; // for the log's subject
    for (const InstanceRecord& r : a.records)
        instances[a.copyOf(r.instance->id).key()] = r.instance;
    std::vector<model::RigConstraint> follows;
    RigNodeIndex group = kNoNode;
    const std::size_t count = a.rig.nodes.size();
    for (RigNodeIndex i = 1; i < count; ++i) {
        if (!isSkinJoint(a.rig.nodes[i]) || !copies.count(a.rig.nodes[i].key.copy()))
            continue;
        RigNodeIndex parent = skinAncestor(a.rig, i);
        if (parent == kNoNode)
            parent = group != kNoNode ? group : (group = jointGroup(a));
        model::RigNode& joint = a.rig.nodes[i];
        const RigNodeIndex old = joint.parent;
        if (old == parent)
            continue;
        const model::TemplateInstance* instance = instances[joint.key.copy()];
        if (joint.scaleCompensate) {
            a.report(Severity::Warning, instance, "isolate_skin: '" + joint.path +
                                                      "' compensates its parent's scale; it stays under '" + a.rig.nodes[old].path + "'");
            continue;
        }
        if (hangsBelow(a.rig, parent, i)) {
            a.report(Severity::Warning, instance, "isolate_skin: '" + a.rig.nodes[parent].path + "' hangs below '" + joint.path +
                                                      "' (a loop); it stays under '" + a.rig.nodes[old].path + "'");
            continue;
        }
        joint.parent = parent;
        follows.push_back(followConstraint(joint, i, old));
    }
    // First among the constraints: each joint's follow comes before any other constraint on it.
    a.rig.constraints.insert(a.rig.constraints.begin(), std::make_move_iterator(follows.begin()),
                             std::make_move_iterator(follows.end()));
}

} // namespace rs::rigging
