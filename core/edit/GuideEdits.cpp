// The guide edits on one instance or the document (duplicate and re-hang are
// in InstanceTreeEdits.cpp).
#include "edit/GuideEdits.h"

#include <algorithm>
#include <cmath>
#include <cctype>
#include <optional>

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
    void undo(GuideDocument& d) override
    {
        if (auto taken = d.takeInstance(m_instance.id))
            m_instance = std::move(*taken);
    }
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
                const auto index = d.indexOf(id);
                if (auto taken = index ? d.takeInstance(id) : std::nullopt)
                    m_removed.emplace_back(*index, std::move(*taken));
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

// Renames an instance, and the `virtual_parent` options that name it (the
// one option whose value is an instance's name), so they still find it.
class RenameInstance final : public Command {
public:
    RenameInstance(InstanceId id, std::string from, std::string to, std::vector<InstanceId> referring)
        : m_id(id), m_from(std::move(from)), m_to(std::move(to)), m_referring(std::move(referring)) {}
    std::string text() const override { return "Rename '" + m_from + "' to '" + m_to + "'"; }
    void redo(GuideDocument& d) override { set(d, m_to); }
    void undo(GuideDocument& d) override { set(d, m_from); }
    Change change() const override
    {
        std::vector<InstanceId> ids{m_id};
        ids.insert(ids.end(), m_referring.begin(), m_referring.end());
        return Change::of(ChangeKind::Instances | ChangeKind::Names | (m_referring.empty() ? ChangeKind{} : ChangeKind::Options), ids);
    }

private:
    void set(GuideDocument& d, const std::string& name)
    {
        d.instance(m_id)->name = name;
        for (InstanceId id : m_referring)
            d.instance(id)->options["virtual_parent"] = name;
    }

    InstanceId m_id;
    std::string m_from, m_to;
    std::vector<InstanceId> m_referring;
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
        d.instance(m_id)->optionSources.at.erase(m_option); // no longer the file's value
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

} // namespace

bool isValidInstanceName(const std::string& name)
{
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name.front())))
        return false;
    return std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

namespace {

Status refusedFor(InstanceId id, std::string message) { return Status::refused(std::move(message), Subject::ofInstance(id)); }
Status noInstance(InstanceId id) { return refusedFor(id, "no instance with id " + std::to_string(id)); }
Status invalidName(InstanceId id, const std::string& name)
{
    return refusedFor(id, "'" + name + "' is not a valid name (letters, digits and _, not starting with a digit)");
}

} // namespace

Status addInstance(History& history, TemplateInstance instance)
{
    const GuideDocument& d = history.document();
    if (instance.id == model::kNoId || d.instance(instance.id))
        return refusedFor(instance.id, "instance id " + std::to_string(instance.id) + " is not free");
    if (!isValidInstanceName(instance.name))
        return invalidName(instance.id, instance.name);
    if (const TemplateInstance* taken = d.instanceNamed(instance.name))
        return refusedFor(taken->id, "an instance named '" + instance.name + "' already exists");
    if (instance.joints.empty())
        return refusedFor(instance.id, "an instance needs at least one guide joint");
    if (instance.parent != model::kNoId) {
        const TemplateInstance* parent = d.instance(instance.parent);
        if (!parent || !parent->joint(instance.parentJoint))
            return Status::refused("the hook joint does not belong to the parent instance",
                                   Subject::ofJoint(instance.parent, instance.parentJoint));
    }
    for (const auto& joint : instance.joints)
        if (const TemplateInstance* owner = d.ownerOf(joint.id))
            return Status::refused("joint id " + std::to_string(joint.id) + " is not free", Subject::ofJoint(owner->id, joint.id));
    history.push(std::make_unique<AddInstance>(std::move(instance)));
    return {};
}

Status removeInstance(History& history, InstanceId id) { return removeInstances(history, {id}); }

Status removeInstances(History& history, const std::vector<InstanceId>& ids)
{
    if (ids.empty())
        return Status::refused("no instance to remove");
    for (InstanceId id : ids)
        if (!history.document().instance(id))
            return noInstance(id);
    const std::string what = ids.size() == 1 ? "Remove '" + history.document().instance(ids.front())->name + "'"
                                             : "Remove " + std::to_string(ids.size()) + " templates";
    history.push(std::make_unique<RemoveInstances>(ids, what));
    return {};
}

Status renameInstance(History& history, InstanceId id, const std::string& newName)
{
    const TemplateInstance* instance = history.document().instance(id);
    if (!instance)
        return noInstance(id);
    if (instance->name == newName)
        return {};
    if (!isValidInstanceName(newName))
        return invalidName(id, newName);
    if (history.document().instanceNamed(newName))
        return refusedFor(id, "an instance named '" + newName + "' already exists");
    std::vector<InstanceId> referring;
    for (const TemplateInstance& other : history.document().instances())
        if (auto it = other.options.find("virtual_parent"); it != other.options.end())
            if (const auto* name = std::get_if<std::string>(&it->second); name && *name == instance->name)
                referring.push_back(other.id);
    history.push(std::make_unique<RenameInstance>(id, instance->name, newName, std::move(referring)));
    return {};
}

Status setJointTransform(History& history, model::JointId joint, const Transform& local)
{
    const TemplateInstance* owner = history.document().ownerOf(joint);
    if (!owner)
        return Status::refused("no joint with id " + std::to_string(joint), Subject::ofJoint(model::kNoId, joint));
    const Transform before = owner->joint(joint)->local;
    if (before == local)
        return {};
    history.push(std::make_unique<SetJointTransform>(owner->id, joint, before, local));
    return {};
}

Status setOption(History& history, InstanceId id, const std::string& option, const Value& value, const Value& defaultValue)
{
    const TemplateInstance* instance = history.document().instance(id);
    if (!instance)
        return noInstance(id);
    const bool intForFloat = typeOf(value) == ValueType::Int && typeOf(defaultValue) == ValueType::Float;
    if (typeOf(value) != typeOf(defaultValue) && !intForFloat)
        return refusedFor(id, "option '" + option + "' takes a " + typeName(typeOf(defaultValue)) + ", not a " +
                                  typeName(typeOf(value)));
    std::optional<Value> before;
    if (auto it = instance->options.find(option); it != instance->options.end())
        before = it->second;
    std::optional<Value> after;
    if (!sameValue(value, defaultValue))
        after = intForFloat ? Value(double(std::get<long long>(value))) : value;
    if (before == after || (before && after && sameValue(*before, *after)))
        return {};
    history.push(std::make_unique<SetOption>(id, option, before, after));
    return {};
}

namespace {

// Sets (or, with nullopt, removes) one entry of a keyed per-instance section
// (`names`) as one undo step; no step when nothing changes.
template <class Map>
Status setInstanceEntry(History& history, InstanceId id, Map TemplateInstance::*section, const std::string& key,
                        std::optional<typename Map::mapped_type> value, const std::string& what)
{
    const TemplateInstance* instance = history.document().instance(id);
    if (!instance)
        return noInstance(id);
    TemplateInstance changed = *instance;
    if (value)
        (changed.*section)[key] = *value;
    else
        (changed.*section).erase(key);
    if (changed.*section == instance->*section)
        return {};
    history.push(std::make_unique<ReplaceInstance>(*instance, std::move(changed), what + " of " + instance->name));
    return {};
}

} // namespace

Status setNameOverride(History& history, InstanceId id, const std::string& token, const std::string& name,
                       const std::string& defaultName)
{
    if (!name.empty() && !std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; }))
        return refusedFor(id, "'" + name + "' is not a valid name (letters, digits and _)");
    const bool fallback = name.empty() || name == defaultName;
    return setInstanceEntry(history, id, &TemplateInstance::names, token,
                            fallback ? std::nullopt : std::optional<std::string>(name), "Name " + token);
}

Status replaceInstance(History& history, TemplateInstance instance, const std::string& what)
{
    const GuideDocument& d = history.document();
    const TemplateInstance* current = d.instance(instance.id);
    if (!current)
        return noInstance(instance.id);
    if (instance.joints.empty())
        return refusedFor(instance.id, "an instance needs at least one guide joint");
    for (const auto& joint : instance.joints)
        if (const TemplateInstance* owner = d.ownerOf(joint.id); owner && owner->id != instance.id)
            return Status::refused("joint id " + std::to_string(joint.id) + " belongs to '" + owner->name + "'",
                                   Subject::ofJoint(owner->id, joint.id));
    for (const auto& other : d.instances())
        if (other.parent == instance.id && !instance.joint(other.parentJoint))
            return refusedFor(other.id, "'" + other.name + "' hangs under a guide joint of '" + current->name + "' that would go away");
    history.push(std::make_unique<ReplaceInstance>(*current, std::move(instance), what));
    return {};
}

} // namespace rs::edit
