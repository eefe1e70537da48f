// RigAssembly's lookups (guide index, structure tags, hooks) and its build
// messages: what every stage of buildRig shares.
#include "rigging/RigAssembly.h"
#include "templates/Structure.h"

#include <algorithm>

namespace rs::rigging {

using model::JointId;
using model::kNoNode;
using model::RigNodeIndex;

NodeKey RigAssembly::keyOf(const model::TemplateInstance& instance, const std::string& tag) const
{
    const BranchCopy& copy = copyOf(instance.id);
    return {copy.original, copy.branch(), tag};
}

Subject RigAssembly::subjectOf(const model::TemplateInstance& instance) const
{
    const BranchCopy& copy = copyOf(instance.id);
    return Subject::ofInstance(copy.original, copy.branch());
}

void RigAssembly::indexGuide()
{
    for (const auto& instance : guide.instances())
        for (const auto& joint : instance.joints)
            guideIndex[joint.id] = {&instance, &joint, Mat4(1.0)};
    // Instances and joints are stored parents first, so one pass composes worlds.
    for (const auto& instance : guide.instances())
        for (const auto& joint : instance.joints) {
            const JointId up = upstreamJoint(joint.id);
            auto parent = guideIndex.find(up);
            guideIndex[joint.id].world =
                (parent == guideIndex.end() ? Mat4(1.0) : parent->second.world) * joint.local.matrix();
        }
    // A mirrored branch copy is the reflection of the authored guide: M * W * M
    // keeps rotations proper (no negative scale) and positions mirrored.
    for (const auto& instance : guide.instances()) {
        const Mat4& m = copyOf(instance.id).mirror;
        if (m == Mat4(1.0))
            continue;
        for (const auto& joint : instance.joints)
            guideIndex[joint.id].world = m * guideIndex.at(expanded.original.at(joint.id)).world * m;
    }
}

const RigAssembly::Resolved& RigAssembly::resolveStructure(const templates::TemplateManifest& manifest,
                                                            const model::TemplateInstance& instance, bool isTag,
                                                            const std::string& text)
{
    std::string key = instance.name + (isTag ? "\nt" : "\na") + text;
    auto it = structureCache.find(key);
    if (it == structureCache.end()) {
        Resolved r;
        const auto& resolver = resolvers.try_emplace(&instance, manifest, instance).first->second;
        auto joints = isTag ? resolver.tag(text) : resolver.address(text);
        if (joints)
            r.joints = joints.take();
        else
            r.error = firstError(joints.diagnostics());
        it = structureCache.emplace(std::move(key), std::move(r)).first;
    }
    return it->second;
}

NodesByInstance indexNodesByInstance(const model::Rig& rig)
{
    NodesByInstance out;
    for (RigNodeIndex i = 0; i < rig.nodes.size(); ++i)
        if (!rig.nodes[i].key.isRoot())
            out[rig.nodes[i].key.copy()].push_back(i);
    return out;
}

JointId RigAssembly::authoredJoint(JointId expandedJoint) const
{
    auto it = expanded.original.find(expandedJoint);
    return it == expanded.original.end() ? expandedJoint : it->second;
}

JointId RigAssembly::upstreamJoint(JointId joint) const
{
    auto it = guideIndex.find(joint);
    if (it == guideIndex.end())
        return model::kNoId;
    return it->second.joint->parent != model::kNoId ? it->second.joint->parent : it->second.owner->parentJoint;
}

Mat4 RigAssembly::guideWorldMatrix(JointId joint) const
{
    auto it = guideIndex.find(joint);
    return it == guideIndex.end() ? guide.jointWorldMatrix(joint) : it->second.world;
}

RigNodeIndex RigAssembly::physicalHookFor(JointId joint) const
{
    for (std::size_t guard = 0; joint != model::kNoId && guard < 100000; ++guard) {
        if (auto it = hooks.find(joint); it != hooks.end())
            return it->second;
        joint = upstreamJoint(joint);
    }
    return 0; // the rig root
}

RigNodeIndex RigAssembly::virtualHookFor(const std::string& domain, JointId joint) const
{
    auto table = virtualHooks.find(domain);
    if (table == virtualHooks.end())
        return kNoNode;
    for (std::size_t guard = 0; joint != model::kNoId && guard < 100000; ++guard) {
        if (auto it = table->second.find(joint); it != table->second.end())
            return it->second;
        joint = upstreamJoint(joint);
    }
    return kNoNode;
}

void RigAssembly::report(Severity severity, const model::TemplateInstance* instance, const std::string& message)
{
    Diagnostic d;
    d.severity = severity;
    if (instance) {
        d.message = "instance '" + instance->name + "' (" + instance->templateId + "): " + message;
        d.subject = subjectOf(*instance);
    } else {
        d.message = message;
    }
    rig.diagnostics.push_back(std::move(d));
}

} // namespace rs::rigging
