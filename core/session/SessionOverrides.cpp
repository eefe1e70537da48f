// Override commands: each edits one node's override record through the
// history (edit/OverrideEdits.h), so it is one undo step with a typed change
// event; the live rebuild then applies it.
#include "session/Session.h"

#include "edit/BuildSettingsEdits.h"
#include "edit/OverrideEdits.h"

namespace rs::session {

namespace {

model::Override recordOf(const model::GuideDocument& document, const NodeKey& key)
{
    auto it = document.overrides.find(key);
    return it == document.overrides.end() ? model::Override{} : it->second;
}

} // namespace

Status Session::setOverride(const NodeKey& key, const model::Override& record, const std::string& what)
{
    return edit::setOverride(m_history, key, record, what);
}

Status Session::removeOverride(const NodeKey& key)
{
    return edit::removeOverride(m_history, key);
}

Status Session::setChannelAsDefault(int channel)
{
    if (!m_program || channel < 0 || std::size_t(channel) >= m_program->channels().size())
        return Status::refused("no such channel");
    const eval::Channel& c = m_program->channels()[channel];
    if (c.transform == eval::kRotateOrderChannel)
        return Status::refused("the rotate order has no default value to set");
    const model::RigNode& node = m_rig->nodes[c.node];
    model::Override record = recordOf(m_document, node.key);
    record.defaults[c.name] = m_pose[channel];
    record.pose.erase(c.name); // the value is now the default: the test pose keeps only differences
    return edit::setOverride(m_history, node.key, record, "Set default " + node.name + "." + c.name);
}

Status Session::resetChannelToDefault(int channel)
{
    if (!m_program || channel < 0 || std::size_t(channel) >= m_program->channels().size())
        return Status::refused("no such channel");
    const eval::Channel& c = m_program->channels()[channel];
    eval::Pose pose = m_pose;
    pose[channel] = c.defaultValue;
    return commitPose(pose, "Reset " + m_rig->nodes[c.node].name + "." + c.name);
}

Status Session::setChannelLocked(int channel, bool locked)
{
    if (!m_program || channel < 0 || std::size_t(channel) >= m_program->channels().size())
        return Status::refused("no such channel");
    const eval::Channel& c = m_program->channels()[channel];
    const model::RigNode& node = m_rig->nodes[c.node];
    model::Override record = recordOf(m_document, node.key);
    model::ChannelState& state = record.locks[c.name];
    state.locked = locked;
    state.keyable = c.keyable;
    return edit::setOverride(m_history, node.key, record, std::string(locked ? "Lock " : "Unlock ") + node.name + "." + c.name);
}

Status Session::setChannelLimit(int channel, std::optional<model::ChannelLimit> limit)
{
    if (!m_program || channel < 0 || std::size_t(channel) >= m_program->channels().size())
        return Status::refused("no such channel");
    const eval::Channel& c = m_program->channels()[channel];
    const model::RigNode& node = m_rig->nodes[c.node];
    model::Override record = recordOf(m_document, node.key);
    if (limit) record.limits[c.name] = *limit;
    else record.limits.erase(c.name);
    return edit::setOverride(m_history, node.key, record, (limit ? "Limit " : "Unlimit ") + node.name + "." + c.name);
}

Status Session::setRestore(const model::RestoreToggles& restore)
{
    model::BuildSettings settings = m_document.build;
    std::string what = "Restore on build";
    for (int k = 0; k < model::kOverrideKindCount; ++k) {
        const auto kind = model::OverrideKind(k);
        if (restore.restores(kind) != settings.restore.restores(kind))
            what = std::string(restore.restores(kind) ? "Restore " : "Do not restore ") + model::overrideKindName(kind) + " on build";
    }
    settings.restore = restore;
    return edit::setBuildSettings(m_history, settings, what);
}

Status Session::setCleanup(bool cleanup)
{
    model::BuildSettings settings = m_document.build;
    settings.cleanup = cleanup;
    return edit::setBuildSettings(m_history, settings, cleanup ? "Clean up on build" : "Do not clean up on build");
}

} // namespace rs::session

namespace rs::session {

namespace {

// "Lock c_arm.rx" for one channel, "Lock 6 channels" for more.
std::string stepName(const std::string& verb, const std::vector<std::string>& labels)
{
    return labels.size() == 1 ? verb + " " + labels.front() : verb + " " + std::to_string(labels.size()) + " channels";
}

void merge(model::Override& into, const model::Override& from)
{
    if (from.shape) into.shape = from.shape;
    for (const auto& [c, v] : from.defaults) into.defaults[c] = v;
    for (const auto& [c, v] : from.limits) into.limits[c] = v;
    for (const auto& [c, v] : from.locks) into.locks[c] = v;
    if (from.post) into.post = from.post;
    if (from.displayName) into.displayName = from.displayName;
    for (const auto& [c, v] : from.pose) into.pose[c] = v;
}

} // namespace

Status Session::editChannels(const std::vector<int>& channels, ChannelEdit edit, std::optional<model::ChannelLimit> limit)
{
    if (!m_program)
        return Status::refused("build the rig first");
    std::map<NodeKey, model::Override> records;
    std::vector<std::string> labels;
    for (int channel : channels) {
        if (channel < 0 || std::size_t(channel) >= m_program->channels().size())
            return Status::refused("no such channel");
        const eval::Channel& c = m_program->channels()[channel];
        if (edit == ChannelEdit::SetDefault && c.transform == eval::kRotateOrderChannel)
            continue;
        if (edit == ChannelEdit::Limit && c.isEnum())
            continue;
        const model::RigNode& node = m_rig->nodes[c.node];
        auto [it, fresh] = records.try_emplace(node.key, recordOf(m_document, node.key));
        model::Override& record = it->second;
        switch (edit) {
        case ChannelEdit::SetDefault:
            record.defaults[c.name] = m_pose[channel];
            record.pose.erase(c.name); // the value is now the default: the test pose keeps only differences
            break;
        case ChannelEdit::Lock:
        case ChannelEdit::Unlock:
            record.locks[c.name] = {edit == ChannelEdit::Lock, c.keyable};
            break;
        case ChannelEdit::Keyable:
        case ChannelEdit::NonKeyable:
            record.locks[c.name] = {c.locked, edit == ChannelEdit::Keyable};
            break;
        case ChannelEdit::Limit:
            if (limit) record.limits[c.name] = *limit;
            else record.limits.erase(c.name);
            break;
        }
        labels.push_back(node.name + "." + c.name);
    }
    if (labels.empty())
        return Status::refused(edit == ChannelEdit::SetDefault ? "the rotate order has no default value to set"
                               : edit == ChannelEdit::Limit  ? "a switch (enum) channel takes no limits"
                                                             : "no channel selected");
    const char* verb = "";
    switch (edit) {
    case ChannelEdit::SetDefault: verb = "Set default"; break;
    case ChannelEdit::Lock: verb = "Lock"; break;
    case ChannelEdit::Unlock: verb = "Unlock"; break;
    case ChannelEdit::Keyable: verb = "Make keyable"; break;
    case ChannelEdit::NonKeyable: verb = "Make non-keyable"; break;
    case ChannelEdit::Limit: verb = limit ? "Limit" : "Unlimit"; break;
    }
    return edit::setOverrides(m_history, records, stepName(verb, labels));
}

Status Session::resetChannelsToDefault(const std::vector<int>& channels)
{
    if (!m_program)
        return Status::refused("build the rig first");
    eval::Pose pose = m_pose;
    std::vector<std::string> labels;
    for (int channel : channels) {
        if (channel < 0 || std::size_t(channel) >= m_program->channels().size())
            return Status::refused("no such channel");
        const eval::Channel& c = m_program->channels()[channel];
        pose[channel] = c.defaultValue;
        labels.push_back(m_rig->nodes[c.node].name + "." + c.name);
    }
    if (labels.empty())
        return Status::refused("no channel selected");
    return commitPose(pose, stepName("Reset", labels));
}

Status Session::setOverrides(const std::map<NodeKey, model::Override>& records, const std::string& what)
{
    return edit::setOverrides(m_history, records, what);
}

Status Session::retargetOverride(const NodeKey& from, const NodeKey& to)
{
    auto it = m_document.overrides.find(from);
    if (it == m_document.overrides.end())
        return Status::refused("no override to re-target", from.isRoot() ? Subject{} : Subject::ofNode(from));
    if (from == to)
        return Status::refused("the override is already on that node", Subject::ofNode(to));
    const auto node = m_rig ? m_rig->find(to) : std::nullopt;
    if (!node)
        return Status::refused("the rig has no node '" + to.tag + "' to re-target to", Subject::ofNode(to));
    if (it->second.post && !to.isRoot())
        return Status::refused("a post transform stays on the rig root", Subject::ofNode(from));
    model::Override moved = recordOf(m_document, to);
    merge(moved, it->second);
    std::map<NodeKey, model::Override> records{{from, {}}, {to, moved}};
    return edit::setOverrides(m_history, records, "Re-target overrides to " + m_rig->nodes[*node].name);
}

std::optional<std::string> Session::orphanReason(const NodeKey& key) const
{
    if (!m_rig || m_rig->find(key))
        return std::nullopt;
    auto it = m_document.overrides.find(key);
    bool sameInstance = false, sameBranch = false;
    for (const model::RigNode& node : m_rig->nodes) {
        if (node.key.instance != key.instance)
            continue;
        sameInstance = true;
        sameBranch = sameBranch || node.key.branch == key.branch;
        // A shape record of the authored side applies to its branch copies.
        if (key.branch.empty() && node.key.tag == key.tag && it != m_document.overrides.end() && it->second.shape)
            return std::nullopt;
    }
    const model::TemplateInstance* instance = m_document.instance(key.instance);
    if (!key.isRoot() && !instance)
        return "instance #" + std::to_string(key.instance) + " no longer exists";
    const std::string name = instance ? "'" + instance->name + "'" : std::string("the rig");
    if (!sameInstance)
        return "instance " + name + " makes no rig nodes";
    if (!sameBranch)
        return "instance " + name + " has no branch '" + key.branch + "'";
    return "instance " + name + " makes no node '" + key.tag + "' (an option removed it?)";
}

} // namespace rs::session
