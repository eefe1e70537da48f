#include "edit/GuideEdits.h"

#include "edit/GuideMove.h"

#include <algorithm>
#include <cmath>
#include <cctype>
#include <filesystem>
#include <map>

namespace rs::edit {

using model::GuideDocument;
using model::InstanceId;
using model::TemplateInstance;

namespace {

class AddInstance final : public Command {
public:
    explicit AddInstance(TemplateInstance instance) : m_instance(std::move(instance)) {}
    std::string text() const override { return "Add " + m_instance.templateId + " '" + m_instance.name + "'"; }
    void redo(GuideDocument& d) override { d.insertInstance(m_instance, d.instances().size()); }
    void undo(GuideDocument& d) override { m_instance = d.takeInstance(m_instance.id); }
    Change change() const override { return Change::of(ChangeKind::Instances, {m_instance.id}); }

private:
    TemplateInstance m_instance;
};

class RemoveInstances final : public Command {
public:
    RemoveInstances(std::vector<InstanceId> ids, std::string what) : m_ids(std::move(ids)), m_what(std::move(what)) {}
    std::string text() const override { return m_what; }
    void redo(GuideDocument& d) override
    {
        m_removed.clear();
        for (InstanceId top : m_ids) {
            if (!d.instance(top))
                continue; // already gone below another removed instance
            for (InstanceId id : d.subtree(top)) {
                const std::size_t index = *d.indexOf(id);
                m_removed.emplace_back(index, d.takeInstance(id));
            }
        }
    }
    void undo(GuideDocument& d) override
    {
        // Re-insert in reverse removal order so every index is the original one.
        for (auto it = m_removed.rbegin(); it != m_removed.rend(); ++it)
            d.insertInstance(it->second, it->first);
        m_removed.clear();
    }
    Change change() const override { return Change::of(ChangeKind::Instances, m_ids); }

private:
    std::vector<InstanceId> m_ids;
    std::string m_what;
    std::vector<std::pair<std::size_t, TemplateInstance>> m_removed;
};

class RenameInstance final : public Command {
public:
    RenameInstance(InstanceId id, std::string from, std::string to) : m_id(id), m_from(std::move(from)), m_to(std::move(to)) {}
    std::string text() const override { return "Rename '" + m_from + "' to '" + m_to + "'"; }
    void redo(GuideDocument& d) override { d.instance(m_id)->name = m_to; }
    void undo(GuideDocument& d) override { d.instance(m_id)->name = m_from; }
    Change change() const override { return Change::of(ChangeKind::Instances | ChangeKind::Names, {m_id}); }

private:
    InstanceId m_id;
    std::string m_from, m_to;
};

// One document-wide field (the test pose, the reference model) set to a new value.
template <class T>
class SetDocumentField final : public Command {
public:
    SetDocumentField(T GuideDocument::*field, ChangeKind kind, T from, T to, std::string what)
        : m_field(field), m_kind(kind), m_from(std::move(from)), m_to(std::move(to)), m_what(std::move(what)) {}
    std::string text() const override { return m_what; }
    void redo(GuideDocument& d) override { d.*m_field = m_to; }
    void undo(GuideDocument& d) override { d.*m_field = m_from; }
    Change change() const override { return Change::of(m_kind); }

private:
    T GuideDocument::*m_field;
    ChangeKind m_kind;
    T m_from, m_to;
    std::string m_what;
};

class SetJointTransform final : public Command {
public:
    SetJointTransform(InstanceId owner, model::JointId joint, Transform from, Transform to)
        : m_owner(owner), m_joint(joint), m_from(from), m_to(to) {}
    std::string text() const override { return "Move joint " + std::to_string(m_joint); }
    void redo(GuideDocument& d) override { d.instance(m_owner)->joint(m_joint)->local = m_to; }
    void undo(GuideDocument& d) override { d.instance(m_owner)->joint(m_joint)->local = m_from; }
    Change change() const override { return Change::of(ChangeKind::Joints, {m_owner}, {m_joint}); }

private:
    InstanceId m_owner;
    model::JointId m_joint;
    Transform m_from, m_to;
};

class SetOption final : public Command {
public:
    SetOption(InstanceId id, std::string option, std::optional<Value> from, std::optional<Value> to)
        : m_id(id), m_option(std::move(option)), m_from(std::move(from)), m_to(std::move(to)) {}
    std::string text() const override { return "Set option " + m_option; }
    void redo(GuideDocument& d) override { apply(d, m_to); }
    void undo(GuideDocument& d) override { apply(d, m_from); }
    Change change() const override { return Change::of(ChangeKind::Options, {m_id}); }

private:
    void apply(GuideDocument& d, const std::optional<Value>& v)
    {
        auto& options = d.instance(m_id)->options;
        if (v) options[m_option] = *v;
        else options.erase(m_option);
    }
    InstanceId m_id;
    std::string m_option;
    std::optional<Value> m_from, m_to;
};

// An instance replaced as a whole (its guide joints regenerated), in place.
class ReplaceInstance final : public Command {
public:
    ReplaceInstance(TemplateInstance from, TemplateInstance to, std::string what)
        : m_from(std::move(from)), m_to(std::move(to)), m_what(std::move(what))
    {
        // What differs, once: views hear "names of arm" rather than "the arm".
        m_change.instances = {m_to.id};
        if (m_from.joints != m_to.joints) m_change.add(ChangeKind::Joints);
        if (m_from.options != m_to.options) m_change.add(ChangeKind::Options);
        if (m_from.shapes != m_to.shapes) m_change.add(ChangeKind::Shapes);
        if (m_from.names != m_to.names) m_change.add(ChangeKind::Names);
        if (m_from.name != m_to.name || m_from.parent != m_to.parent || m_from.parentJoint != m_to.parentJoint ||
            m_from.structure != m_to.structure || m_from.templateId != m_to.templateId || m_change.empty())
            m_change.add(ChangeKind::Instances);
        for (const auto& joint : m_to.joints)
            m_change.joints.push_back(joint.id);
    }
    std::string text() const override { return m_what; }
    void redo(GuideDocument& d) override { *d.instance(m_to.id) = m_to; }
    void undo(GuideDocument& d) override { *d.instance(m_from.id) = m_from; }
    Change change() const override { return m_change; }

private:
    TemplateInstance m_from, m_to;
    std::string m_what;
    Change m_change;
};

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
            const std::size_t index = *d.indexOf(id);
            m_removed.emplace_back(index, d.takeInstance(id));
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

} // namespace

bool isValidInstanceName(const std::string& name)
{
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name.front())))
        return false;
    return std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

Error addInstance(History& history, TemplateInstance instance)
{
    const GuideDocument& d = history.document();
    if (instance.id == model::kNoId || d.instance(instance.id))
        return "instance id " + std::to_string(instance.id) + " is not free";
    if (!isValidInstanceName(instance.name))
        return "'" + instance.name + "' is not a valid name (letters, digits and _, not starting with a digit)";
    if (d.instanceNamed(instance.name))
        return "an instance named '" + instance.name + "' already exists";
    if (instance.joints.empty())
        return "an instance needs at least one guide joint";
    if (instance.parent != model::kNoId) {
        const TemplateInstance* parent = d.instance(instance.parent);
        if (!parent || !parent->joint(instance.parentJoint))
            return "the hook joint does not belong to the parent instance";
    }
    for (const auto& joint : instance.joints)
        if (d.joint(joint.id))
            return "joint id " + std::to_string(joint.id) + " is not free";
    history.push(std::make_unique<AddInstance>(std::move(instance)));
    return std::nullopt;
}

Error removeInstance(History& history, InstanceId id) { return removeInstances(history, {id}); }

Error removeInstances(History& history, const std::vector<InstanceId>& ids)
{
    if (ids.empty())
        return "no instance to remove";
    for (InstanceId id : ids)
        if (!history.document().instance(id))
            return "no instance with id " + std::to_string(id);
    const std::string what = ids.size() == 1 ? "Remove '" + history.document().instance(ids.front())->name + "'"
                                             : "Remove " + std::to_string(ids.size()) + " templates";
    history.push(std::make_unique<RemoveInstances>(ids, what));
    return std::nullopt;
}

Error renameInstance(History& history, InstanceId id, const std::string& newName)
{
    const TemplateInstance* instance = history.document().instance(id);
    if (!instance)
        return "no instance with id " + std::to_string(id);
    if (instance->name == newName)
        return std::nullopt;
    if (!isValidInstanceName(newName))
        return "'" + newName + "' is not a valid name (letters, digits and _, not starting with a digit)";
    if (history.document().instanceNamed(newName))
        return "an instance named '" + newName + "' already exists";
    history.push(std::make_unique<RenameInstance>(id, instance->name, newName));
    return std::nullopt;
}

Error setJointTransform(History& history, model::JointId joint, const Transform& local)
{
    const TemplateInstance* owner = history.document().ownerOf(joint);
    if (!owner)
        return "no joint with id " + std::to_string(joint);
    const Transform before = owner->joint(joint)->local;
    if (before == local)
        return std::nullopt;
    history.push(std::make_unique<SetJointTransform>(owner->id, joint, before, local));
    return std::nullopt;
}

Error setOption(History& history, InstanceId id, const std::string& option, const Value& value, const Value& defaultValue)
{
    const TemplateInstance* instance = history.document().instance(id);
    if (!instance)
        return "no instance with id " + std::to_string(id);
    if (typeOf(value) != typeOf(defaultValue))
        return "option '" + option + "' takes a " + typeName(typeOf(defaultValue)) + ", not a " + typeName(typeOf(value));
    std::optional<Value> before;
    if (auto it = instance->options.find(option); it != instance->options.end())
        before = it->second;
    std::optional<Value> after;
    if (value != defaultValue)
        after = value;
    if (before == after)
        return std::nullopt;
    history.push(std::make_unique<SetOption>(id, option, before, after));
    return std::nullopt;
}

namespace {

// Sets (or, with nullopt, removes) one entry of a keyed per-instance section
// (`names`, `shapes`) as one undo step; no step when nothing changes.
template <class Map>
Error setInstanceEntry(History& history, InstanceId id, Map TemplateInstance::*section, const std::string& key,
                       std::optional<typename Map::mapped_type> value, const std::string& what)
{
    const TemplateInstance* instance = history.document().instance(id);
    if (!instance)
        return "no instance with id " + std::to_string(id);
    TemplateInstance changed = *instance;
    if (value)
        (changed.*section)[key] = *value;
    else
        (changed.*section).erase(key);
    if (changed.*section == instance->*section)
        return std::nullopt;
    history.push(std::make_unique<ReplaceInstance>(*instance, std::move(changed), what + " of " + instance->name));
    return std::nullopt;
}

} // namespace

Error setNameOverride(History& history, InstanceId id, const std::string& token, const std::string& name,
                      const std::string& defaultName)
{
    if (!name.empty() && !std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; }))
        return "'" + name + "' is not a valid name (letters, digits and _)";
    const bool fallback = name.empty() || name == defaultName;
    return setInstanceEntry(history, id, &TemplateInstance::names, token,
                            fallback ? std::nullopt : std::optional<std::string>(name), "Name " + token);
}

Error setShapeEdit(History& history, InstanceId id, const std::string& tag, const model::ShapeEdit& edit,
                   const std::string& what)
{
    if (tag.empty())
        return "a shape edit needs the controller's tag";
    for (const auto& [at, offset] : edit.cvs)
        if (at.first < 0 || at.second < 0 || !std::isfinite(offset.x) || !std::isfinite(offset.y) || !std::isfinite(offset.z))
            return "a CV offset needs indices from 0 and a finite offset";
    return setInstanceEntry(history, id, &TemplateInstance::shapes, tag,
                            edit.isIdentity() ? std::nullopt : std::optional<model::ShapeEdit>(edit),
                            what.empty() ? "Edit shape " + tag : what);
}

Error replaceInstance(History& history, TemplateInstance instance, const std::string& what)
{
    const GuideDocument& d = history.document();
    const TemplateInstance* current = d.instance(instance.id);
    if (!current)
        return "no instance with id " + std::to_string(instance.id);
    if (instance.joints.empty())
        return "an instance needs at least one guide joint";
    for (const auto& joint : instance.joints)
        if (const TemplateInstance* owner = d.ownerOf(joint.id); owner && owner->id != instance.id)
            return "joint id " + std::to_string(joint.id) + " belongs to '" + owner->name + "'";
    for (const auto& other : d.instances())
        if (other.parent == instance.id && !instance.joint(other.parentJoint))
            return "'" + other.name + "' hangs under a guide joint of '" + current->name + "' that would go away";
    history.push(std::make_unique<ReplaceInstance>(*current, std::move(instance), what));
    return std::nullopt;
}

Error setPose(History& history, model::PoseValues pose, const std::string& what)
{
    if (pose == history.document().pose)
        return "the pose did not change";
    history.push(std::make_unique<SetDocumentField<model::PoseValues>>(&GuideDocument::pose, ChangeKind::Pose, history.document().pose,
                                                                       std::move(pose), what));
    return std::nullopt;
}

Error setReferenceModel(History& history, const std::string& path)
{
    const std::string& current = history.document().referenceModel;
    if (path == current)
        return std::nullopt;
    const std::string what = path.empty() ? "Clear reference model"
                                          : "Reference model " + std::filesystem::path(path).filename().string();
    history.push(std::make_unique<SetDocumentField<std::string>>(&GuideDocument::referenceModel, ChangeKind::Reference, current, path, what));
    return std::nullopt;
}

Error duplicateInstances(History& history, const std::vector<InstanceId>& ids, std::vector<InstanceId>* copies)
{
    GuideDocument scratch = history.document(); // names and ids are taken from it as copies land
    std::vector<TemplateInstance> added;
    std::string what;
    for (InstanceId top : ids) {
        const TemplateInstance* original = scratch.instance(top);
        if (!original)
            return "no instance with id " + std::to_string(top);
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
        return "nothing to duplicate";
    history.push(std::make_unique<ReplaceInstances>(std::vector<InstanceId>{}, std::move(added), "Duplicate " + what));
    return std::nullopt;
}

Error reparentInstance(History& history, InstanceId id, model::JointId hookJoint)
{
    const GuideDocument& d = history.document();
    const TemplateInstance* instance = d.instance(id);
    if (!instance)
        return "no instance with id " + std::to_string(id);
    const TemplateInstance* newParent = hookJoint == model::kNoId ? nullptr : d.ownerOf(hookJoint);
    if (hookJoint != model::kNoId && !newParent)
        return "no guide joint with id " + std::to_string(hookJoint);
    const std::vector<InstanceId> subtree = d.subtree(id);
    if (newParent && std::find(subtree.begin(), subtree.end(), newParent->id) != subtree.end())
        return "'" + instance->name + "' cannot hang under itself or an instance below it";
    if (hookJoint == instance->parentJoint)
        return "'" + instance->name + "' already hangs there";
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
    return std::nullopt;
}

} // namespace rs::edit
