// Session's Rig mode: controller selection, pickwalk, gizmo drags on
// controllers, the channel box and pose tools. The test pose is part of the
// guide, so a pose drag is a history transaction like a guide drag: each
// preview sets the pose (evaluated at once), the end commits one undo step.
#include "session/Session.h"

#include "edit/GuideEdits.h"

#include <algorithm>

namespace rs::session {

void Session::previewPose(eval::Pose pose)
{
    m_pose = std::move(pose);
    m_program->evaluate(m_pose, m_evaluation);
    emitChange(Change::of(ChangeKind::Evaluation));
}

Status Session::commitPose(const eval::Pose& pose, const std::string& what)
{
    const model::PoseValues stored = model::testPose(m_document.overrides);
    auto values = eval::valuesFromPose(*m_rig, m_program->channels(), pose, stored);
    if (values == stored) {
        poseFromDocument(); // a drag that ended where it began: show the stored pose
        emitChange(Change::of(ChangeKind::Evaluation));
        return {};
    }
    return edit::setPose(m_history, std::move(values), what);
}

void Session::selectControllers(const std::vector<model::RigNodeIndex>& nodes, bool add)
{
    Selection s = add ? m_selection : Selection{};
    for (auto node : nodes) {
        auto it = std::find(s.nodes.begin(), s.nodes.end(), node);
        if (add && it != s.nodes.end())
            s.nodes.erase(it);
        else if (it == s.nodes.end())
            s.nodes.push_back(node);
    }
    s.node = s.nodes.empty() ? model::kNoNode : s.nodes.back();
    s.joint = model::kNoId;
    s.instance = m_rig && s.node != model::kNoNode ? m_rig->nodes[s.node].owner : model::kNoId;
    select(s);
}

void Session::pickwalk(eval::WalkDirection direction, bool instances)
{
    if (!instances && m_mode == Mode::Rig && m_rig && m_selection.node != model::kNoNode) {
        const auto* shown = m_program ? &m_evaluation.visible : nullptr; // skip what the pose hides
        selectControllers({eval::pickwalk(*m_rig, m_selection.node, direction, shown)}, false);
        return;
    }
    if (m_selection.instance != model::kNoId)
        select(Selection::ofInstance(eval::pickwalk(m_document, m_selection.instance, direction)));
}

void Session::beginDrag(model::RigNodeIndex)
{
    if (m_program)
        m_dragStart = m_pose;
}

// The preview evaluates the dragged pose only (the document's pose changes
// once, when the drag ends): a pose drag never rebuilds anything.
void Session::dragTo(model::RigNodeIndex node, const Mat4& world)
{
    if (m_dragStart && m_posing)
        previewPose(m_posing->placeAt(*m_dragStart, node, world));
}

void Session::endDrag(model::RigNodeIndex, const std::string& what)
{
    if (!m_dragStart)
        return;
    m_dragStart.reset();
    commitPose(m_pose, what);
}

Status Session::setChannel(int channel, double value, bool matchSpace)
{
    if (!m_program || channel < 0 || std::size_t(channel) >= m_program->channels().size())
        return Status::refused("no such channel");
    const eval::Channel& c = m_program->channels()[channel];
    const std::string name = m_rig->nodes[c.node].name + "." + c.name;
    if (c.locked)
        return Status::refused(name + " is locked", Subject::ofNode(m_rig->nodes[c.node].key));
    eval::Pose pose = c.isEnum() ? m_posing->switchSpace(m_pose, channel, value, matchSpace) : m_pose;
    if (!c.isEnum())
        pose[channel] = m_program->channels().clamp(channel, value);
    return commitPose(pose, "Set " + name);
}

Status Session::applyPoseTool(PoseTool tool)
{
    if (!m_posing)
        return Status::refused("build the rig first");
    const auto& selected = m_selection.nodes;
    const auto all = m_rig->sets.count("controllers") ? m_rig->sets.at("controllers") : std::vector<model::RigNodeIndex>{};
    if (tool == PoseTool::ResetSelected && selected.empty())
        return Status::refused("select the controls to reset");
    switch (tool) {
    case PoseTool::ResetSelected: return commitPose(m_posing->reset(m_pose, selected), "Reset selected");
    case PoseTool::ResetAll: return commitPose(m_posing->reset(m_pose, {}), "Reset all");
    case PoseTool::Mirror: return commitPose(m_posing->mirror(m_pose, selected.empty() ? all : selected), "Mirror pose");
    case PoseTool::Flip: return commitPose(m_posing->flip(m_pose, selected.empty() ? all : selected), "Flip pose");
    case PoseTool::IkToFk:
    case PoseTool::FkToIk: break;
    }
    if (m_selection.node == model::kNoNode)
        return Status::refused("select a control of the limb to match");
    auto matched = tool == PoseTool::IkToFk ? m_posing->ikToFk(m_pose, m_selection.node)
                                            : m_posing->fkToIk(m_pose, m_selection.node);
    if (!matched)
        return Status::failure(matched.takeDiagnostics());
    return commitPose(*matched, tool == PoseTool::IkToFk ? "Match FK to IK" : "Match IK to FK");
}

} // namespace rs::session
