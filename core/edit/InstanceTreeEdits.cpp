// The guide edits that take instances out of the tree and put them back
// elsewhere (duplicate, re-hang): one ReplaceInstances step each.
#include "edit/GuideEdits.h"

#include "edit/GuideMove.h"

#include <algorithm>
#include <map>

namespace rs::edit {

using model::GuideDocument;
using model::InstanceId;
using model::TemplateInstance;

namespace {

// Instances taken out (each at its index then) and others appended, in one
// step: duplicating appends copies; re-hanging takes a subtree and appends its
// new version, so parents stay before children.
class ReplaceInstances final : public Command {
public:
    ReplaceInstances(std::vector<InstanceId> removed, std::vector<TemplateInstance> added, std::string what)
        : m_removedIds(std::move(removed)), m_added(std::move(added)), m_what(std::move(what)) {}
    std::string text() const override { return m_what; }
    void redo(GuideDocument& d) override
    {
        m_removed.clear();
        for (InstanceId id : m_removedIds) {
            const auto index = d.indexOf(id);
            if (auto taken = index ? d.takeInstance(id) : std::nullopt)
                m_removed.emplace_back(*index, std::move(*taken));
        }
        for (const TemplateInstance& instance : m_added)
            d.insertInstance(instance, d.instances().size());
    }
    void undo(GuideDocument& d) override
    {
        for (auto it = m_added.rbegin(); it != m_added.rend(); ++it)
            d.takeInstance(it->id);
        for (auto it = m_removed.rbegin(); it != m_removed.rend(); ++it)
            d.insertInstance(it->second, it->first);
        m_removed.clear();
    }
    Change change() const override
    {
        Change out = Change::of(ChangeKind::Instances, m_removedIds);
        for (const TemplateInstance& instance : m_added)
            if (std::find(out.instances.begin(), out.instances.end(), instance.id) == out.instances.end())
                out.instances.push_back(instance.id);
        return out;
    }

private:
    std::vector<InstanceId> m_removedIds;
    std::vector<TemplateInstance> m_added;
    std::string m_what;
    std::vector<std::pair<std::size_t, TemplateInstance>> m_removed;
};

Status noInstance(InstanceId id)
{
    return Status::refused("no instance with id " + std::to_string(id), Subject::ofInstance(id));
}

} // namespace

Status duplicateInstances(History& history, const std::vector<InstanceId>& ids, std::vector<InstanceId>* copies)
{
    GuideDocument scratch = history.document(); // names and ids are taken from it as copies land
    std::vector<TemplateInstance> added;
    std::string what;
    for (InstanceId top : ids) {
        const TemplateInstance* original = scratch.instance(top);
        if (!original)
            return noInstance(top);
        what += (what.empty() ? "'" : ", '") + original->name + "'";
        std::map<InstanceId, InstanceId> instanceIds;
        std::map<model::JointId, model::JointId> jointIds;
        for (InstanceId id : scratch.subtree(top)) {
            TemplateInstance copy = *scratch.instance(id);
            copy.id = instanceIds[id] = scratch.nextInstanceId();
            copy.name = scratch.uniqueName(copy.name);
            model::JointId next = scratch.nextJointId();
            for (auto& joint : copy.joints) jointIds[joint.id] = next++;
            for (auto& joint : copy.joints) {
                joint.id = jointIds[joint.id];
                if (joint.parent != model::kNoId) joint.parent = jointIds[joint.parent];
            }
            if (id != top) {
                copy.parent = instanceIds[copy.parent];
                copy.parentJoint = jointIds[copy.parentJoint];
            }
            if (id == top && copies) copies->push_back(copy.id);
            scratch.insertInstance(copy, scratch.instances().size());
            added.push_back(std::move(copy));
        }
    }
    if (added.empty())
        return Status::refused("nothing to duplicate");
    history.push(std::make_unique<ReplaceInstances>(std::vector<InstanceId>{}, std::move(added), "Duplicate " + what));
    return {};
}

Status reparentInstance(History& history, InstanceId id, model::JointId hookJoint)
{
    const GuideDocument& d = history.document();
    const TemplateInstance* instance = d.instance(id);
    if (!instance)
        return noInstance(id);
    const TemplateInstance* newParent = hookJoint == model::kNoId ? nullptr : d.ownerOf(hookJoint);
    if (hookJoint != model::kNoId && !newParent)
        return Status::refused("no guide joint with id " + std::to_string(hookJoint), Subject::ofJoint(model::kNoId, hookJoint));
    const std::vector<InstanceId> subtree = d.subtree(id);
    if (newParent && std::find(subtree.begin(), subtree.end(), newParent->id) != subtree.end())
        return Status::refused("'" + instance->name + "' cannot hang under itself or an instance below it", Subject::ofInstance(id));
    if (hookJoint == instance->parentJoint)
        return Status::refused("'" + instance->name + "' already hangs there", Subject::ofInstance(id));
    std::vector<TemplateInstance> moved;
    for (InstanceId sub : subtree)
        moved.push_back(*d.instance(sub));
    TemplateInstance& root = moved.front();
    const Mat4 world = d.jointWorldMatrix(root.joints.front().id);
    const Mat4 hookWorld = newParent ? d.jointWorldMatrix(hookJoint) : Mat4(1.0);
    root.parent = newParent ? newParent->id : model::kNoId;
    root.parentJoint = hookJoint;
    root.joints.front().local = localTransformOf(glm::inverse(hookWorld) * world);
    const std::string where = newParent ? "'" + newParent->name + "'" : "the top level";
    history.push(std::make_unique<ReplaceInstances>(subtree, std::move(moved), "Re-hang '" + instance->name + "' under " + where));
    return {};
}

} // namespace rs::edit
