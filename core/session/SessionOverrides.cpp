// Override commands: each edits one node's override record through the
// history (edit/OverrideEdits.h), so it is one undo step with a typed change
// event; the live rebuild then applies it.
#include "session/Session.h"

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

void Session::setRestore(const model::RestoreToggles& restore)
{
    if (restore == m_restore)
        return;
    m_restore = restore;
    if (m_rig)
        build();
}

} // namespace rs::session
