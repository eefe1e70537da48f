#include "edit/OverrideEdits.h"

#include <cmath>
#include <map>

namespace rs::edit {

using model::GuideDocument;
using model::Override;
using model::OverrideKind;

namespace {

// Some records replaced (nullopt: removed), as one undo step.
class SetOverrides final : public Command {
public:
    using Records = std::map<NodeKey, std::optional<Override>>;
    SetOverrides(Records from, Records to, std::string what)
        : m_from(std::move(from)), m_to(std::move(to)), m_what(std::move(what))
    {
        for (const auto& [key, after] : m_to) {
            const std::optional<Override>& before = m_from.at(key);
            const Override none;
            const Override& a = before ? *before : none;
            const Override& b = after ? *after : none;
            if (a.shape != b.shape) m_change.add(ChangeKind::Shapes);
            if (a.pose != b.pose) m_change.add(ChangeKind::Pose);
            if (a.defaults != b.defaults || a.limits != b.limits || a.locks != b.locks || a.post != b.post ||
                a.displayName != b.displayName)
                m_change.add(ChangeKind::Overrides);
            if (key.instance != model::kNoId &&
                std::find(m_change.instances.begin(), m_change.instances.end(), key.instance) == m_change.instances.end())
                m_change.instances.push_back(key.instance);
        }
    }
    std::string text() const override { return m_what; }
    void redo(GuideDocument& d) override { apply(d, m_to); }
    void undo(GuideDocument& d) override { apply(d, m_from); }
    Change change() const override { return m_change; }

private:
    static void apply(GuideDocument& d, const Records& records)
    {
        for (const auto& [key, record] : records) {
            if (record) d.overrides[key] = *record;
            else d.overrides.erase(key);
        }
    }
    Records m_from, m_to;
    std::string m_what;
    Change m_change;
};

std::optional<Override> current(const GuideDocument& d, const NodeKey& key)
{
    auto it = d.overrides.find(key);
    return it == d.overrides.end() ? std::nullopt : std::optional<Override>(it->second);
}

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const Transform& t) { return finite(t.translate) && finite(t.rotateDegrees) && finite(t.scale); }

// Why a record cannot be stored, or empty.
std::string problemOf(const NodeKey& key, const Override& o)
{
    if (key.tag.empty())
        return "an override needs a node tag";
    if (o.shape) {
        const model::ShapeOverride& s = *o.shape;
        if (!finite(s.edit.transform)) return "the shape transform is not finite";
        for (const auto& [at, offset] : s.edit.cvs)
            if (at.first < 0 || at.second < 0 || !finite(offset)) return "a CV offset needs indices from 0 and a finite offset";
        if (s.color && (!finite(*s.color) || glm::any(glm::lessThan(*s.color, Vec3(0.0))) || glm::any(glm::greaterThan(*s.color, Vec3(1.0)))))
            return "a colour needs three numbers from 0 to 1";
        if (s.lineWidth && !(*s.lineWidth > 0.0 && std::isfinite(*s.lineWidth))) return "a line width must be more than 0";
    }
    for (const auto* channels : {&o.defaults, &o.pose})
        for (const auto& [channel, value] : *channels)
            if (channel.empty() || !std::isfinite(value)) return "channel '" + channel + "' needs a name and a finite value";
    for (const auto& [channel, limit] : o.limits)
        if (channel.empty() || !std::isfinite(limit.min) || !std::isfinite(limit.max) || limit.min > limit.max)
            return "the limits of '" + channel + "' need finite min <= max";
    for (const auto& [channel, state] : o.locks)
        if (channel.empty()) return "a lock needs a channel name";
    if (o.post && !(key == model::rigRootKey())) return "a post transform belongs to the rig root";
    if (o.post && (!finite(*o.post) || o.post->scale.x == 0.0 || o.post->scale.y == 0.0 || o.post->scale.z == 0.0))
        return "a post transform needs finite values and a scale other than 0";
    if (o.displayName && o.displayName->empty()) return "a display name cannot be empty";
    return {};
}

Status push(History& history, const NodeKey& key, const Override& record, const std::string& what)
{
    if (const std::string problem = problemOf(key, record); !problem.empty())
        return Status::refused(problem, key.isRoot() ? Subject{} : Subject::ofNode(key));
    std::optional<Override> from = current(history.document(), key);
    std::optional<Override> to = record.isEmpty() ? std::nullopt : std::optional<Override>(record);
    if (from == to)
        return {};
    history.push(std::make_unique<SetOverrides>(SetOverrides::Records{{key, std::move(from)}},
                                                SetOverrides::Records{{key, std::move(to)}}, what));
    return {};
}

} // namespace

Status setOverride(History& history, const NodeKey& key, const Override& record, const std::string& what)
{
    return push(history, key, record, what.empty() ? "Override " + key.tag : what);
}

Status setOverrideKind(History& history, const NodeKey& key, OverrideKind kind, const Override& from, const std::string& what)
{
    Override record = current(history.document(), key).value_or(Override{});
    record.clear(kind);
    switch (kind) {
    case OverrideKind::Shapes: record.shape = from.shape; break;
    case OverrideKind::Defaults: record.defaults = from.defaults; break;
    case OverrideKind::Limits: record.limits = from.limits; break;
    case OverrideKind::Locks: record.locks = from.locks; break;
    case OverrideKind::Post: record.post = from.post; break;
    case OverrideKind::Names: record.displayName = from.displayName; break;
    case OverrideKind::Pose: record.pose = from.pose; break;
    }
    return push(history, key, record,
                what.empty() ? std::string("Override ") + model::overrideKindName(kind) + " of " + key.tag : what);
}

Status removeOverride(History& history, const NodeKey& key, const std::string& what)
{
    return push(history, key, Override{}, what.empty() ? "Remove overrides of " + key.tag : what);
}

Status setOverrides(History& history, const std::map<NodeKey, Override>& records, const std::string& what)
{
    SetOverrides::Records from, to;
    for (const auto& [key, record] : records) {
        if (const std::string problem = problemOf(key, record); !problem.empty())
            return Status::refused(problem, key.isRoot() ? Subject{} : Subject::ofNode(key));
        std::optional<Override> before = current(history.document(), key);
        std::optional<Override> after = record.isEmpty() ? std::nullopt : std::optional<Override>(record);
        if (before != after) { from[key] = std::move(before); to[key] = std::move(after); }
    }
    if (to.empty())
        return Status::refused("nothing to change");
    history.push(std::make_unique<SetOverrides>(std::move(from), std::move(to), what));
    return {};
}

Status setShapeEdit(History& history, model::InstanceId id, const std::string& tag, const model::ShapeEdit& edit,
                    const std::string& what)
{
    if (!history.document().instance(id))
        return Status::refused("no instance with id " + std::to_string(id), Subject::ofInstance(id));
    if (tag.empty())
        return Status::refused("a shape edit needs the controller's tag", Subject::ofInstance(id));
    const NodeKey key{id, {}, tag};
    for (const auto& [at, offset] : edit.cvs)
        if (at.first < 0 || at.second < 0 || !finite(offset))
            return Status::refused("a CV offset needs indices from 0 and a finite offset", Subject::ofShape(key));
    Override record = current(history.document(), key).value_or(Override{});
    model::ShapeOverride shape = record.shape.value_or(model::ShapeOverride{});
    shape.edit = edit;
    record.shape = shape.isEmpty() ? std::nullopt : std::optional<model::ShapeOverride>(shape);
    const model::TemplateInstance* instance = history.document().instance(id);
    return push(history, key, record,
                (what.empty() ? "Edit shape " + tag : what) + (instance ? " of " + instance->name : std::string()));
}

Status setPose(History& history, const model::PoseValues& pose, const std::string& what)
{
    const GuideDocument& d = history.document();
    if (pose == model::testPose(d.overrides))
        return Status::refused("the pose did not change");
    model::Overrides after = d.overrides;
    model::setTestPose(after, pose);
    SetOverrides::Records from, to;
    auto note = [&](const NodeKey& key) {
        std::optional<Override> before = current(d, key);
        auto it = after.find(key);
        std::optional<Override> now = it == after.end() ? std::nullopt : std::optional<Override>(it->second);
        if (before != now) { from[key] = std::move(before); to[key] = std::move(now); }
    };
    for (const auto& [key, record] : d.overrides) note(key);
    for (const auto& [key, record] : after) if (!d.overrides.count(key)) note(key);
    history.push(std::make_unique<SetOverrides>(std::move(from), std::move(to), what));
    return {};
}

} // namespace rs::edit
