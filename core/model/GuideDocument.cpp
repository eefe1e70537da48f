#include "model/GuideDocument.h"

#include <algorithm>
#include <unordered_map>
#include <utility>

namespace rs::model {

bool GuideJoint::hasTag(const std::string& tag) const
{
    return std::find(tags.begin(), tags.end(), tag) != tags.end();
}

const GuideJoint* TemplateInstance::joint(JointId id) const
{
    auto it = std::find_if(joints.begin(), joints.end(), [&](const GuideJoint& j) { return j.id == id; });
    return it == joints.end() ? nullptr : &*it;
}

GuideJoint* TemplateInstance::joint(JointId id)
{
    return const_cast<GuideJoint*>(std::as_const(*this).joint(id));
}

std::vector<JointId> TemplateInstance::childJoints(JointId id) const
{
    std::vector<JointId> out;
    for (const GuideJoint& j : joints)
        if (j.parent == id && j.id != joints.front().id)
            out.push_back(j.id);
    return out;
}

const TemplateInstance* GuideDocument::instance(InstanceId id) const
{
    auto it = std::find_if(m_instances.begin(), m_instances.end(), [&](const TemplateInstance& i) { return i.id == id; });
    return it == m_instances.end() ? nullptr : &*it;
}

TemplateInstance* GuideDocument::instance(InstanceId id)
{
    return const_cast<TemplateInstance*>(std::as_const(*this).instance(id));
}

const TemplateInstance* GuideDocument::instanceNamed(const std::string& n) const
{
    auto it = std::find_if(m_instances.begin(), m_instances.end(), [&](const TemplateInstance& i) { return i.name == n; });
    return it == m_instances.end() ? nullptr : &*it;
}

const TemplateInstance* GuideDocument::ownerOf(JointId joint) const
{
    for (const TemplateInstance& i : m_instances)
        if (i.joint(joint))
            return &i;
    return nullptr;
}

const GuideJoint* GuideDocument::joint(JointId id) const
{
    const TemplateInstance* owner = ownerOf(id);
    return owner ? owner->joint(id) : nullptr;
}

std::vector<InstanceId> GuideDocument::childInstances(InstanceId id) const
{
    std::vector<InstanceId> out;
    for (const TemplateInstance& i : m_instances)
        if (i.parent == id && id != kNoId)
            out.push_back(i.id);
    return out;
}

std::vector<InstanceId> GuideDocument::subtree(InstanceId id) const
{
    // One pass for every instance's children, not a scan per visited instance.
    std::unordered_map<InstanceId, std::vector<InstanceId>> children;
    for (const TemplateInstance& i : m_instances)
        if (i.parent != kNoId)
            children[i.parent].push_back(i.id);
    std::vector<InstanceId> out{id};
    for (std::size_t k = 0; k < out.size(); ++k)
        if (auto it = children.find(out[k]); it != children.end() && out[k] != kNoId)
            out.insert(out.end(), it->second.begin(), it->second.end());
    return out;
}

Mat4 GuideDocument::parentWorldMatrix(JointId id) const
{
    const TemplateInstance* owner = ownerOf(id);
    if (!owner)
        return Mat4(1.0);
    const GuideJoint* j = owner->joint(id);
    if (j->parent != kNoId)
        return jointWorldMatrix(j->parent);
    if (owner->parentJoint != kNoId && joint(owner->parentJoint))
        return jointWorldMatrix(owner->parentJoint);
    return Mat4(1.0);
}

Mat4 GuideDocument::jointWorldMatrix(JointId id) const
{
    // Iterative walk so a (rejected-at-load) cycle can never recurse forever.
    Mat4 world(1.0);
    JointId current = id;
    for (std::size_t guard = 0; current != kNoId && guard < 100000; ++guard) {
        const TemplateInstance* owner = ownerOf(current);
        if (!owner)
            break;
        const GuideJoint* j = owner->joint(current);
        world = j->local.matrix() * world;
        current = j->parent != kNoId ? j->parent : owner->parentJoint;
    }
    return world;
}

void GuideDocument::insertInstance(TemplateInstance instance, std::size_t index)
{
    index = std::min(index, m_instances.size());
    m_instances.insert(m_instances.begin() + static_cast<std::ptrdiff_t>(index), std::move(instance));
}

std::optional<std::size_t> GuideDocument::indexOf(InstanceId id) const
{
    for (std::size_t i = 0; i < m_instances.size(); ++i)
        if (m_instances[i].id == id)
            return i;
    return std::nullopt;
}

std::optional<TemplateInstance> GuideDocument::takeInstance(InstanceId id)
{
    const auto index = indexOf(id);
    if (!index)
        return std::nullopt;
    TemplateInstance out = std::move(m_instances[*index]);
    m_instances.erase(m_instances.begin() + static_cast<std::ptrdiff_t>(*index));
    return out;
}

InstanceId GuideDocument::nextInstanceId() const
{
    InstanceId next = 1;
    for (const TemplateInstance& i : m_instances)
        next = std::max(next, i.id + 1);
    return next;
}

JointId GuideDocument::nextJointId() const
{
    JointId next = 1;
    for (const TemplateInstance& i : m_instances)
        for (const GuideJoint& j : i.joints)
            next = std::max(next, j.id + 1);
    return next;
}

std::string GuideDocument::uniqueName(const std::string& base) const
{
    if (!instanceNamed(base))
        return base;
    for (int n = 1;; ++n)
        if (!instanceNamed(base + std::to_string(n)))
            return base + std::to_string(n);
}

} // namespace rs::model
