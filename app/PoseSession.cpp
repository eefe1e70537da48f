// EditorSession's Rig mode: the compiled rig, the pose from the document, the
// controller selection, pickwalk, gizmo drags and pose tools. A topic file of
// the session so EditorSession.cpp stays about documents and builds.
#include "EditorSession.h"

#include "edit/GuideEdits.h"

#include <algorithm>

namespace rs::app {

void EditorSession::setMode(EditorMode mode)
{
    if (mode == EditorMode::Rig && !m_program)
        mode = EditorMode::Guide; // nothing to pose yet
    if (mode == m_mode)
        return;
    m_mode = mode;
    emit modeChanged();
}

void EditorSession::compileRig()
{
    m_posing.reset();
    m_program.reset();
    if (!m_rig)
        return;
    auto compiled = eval::RigProgram::compile(*m_rig);
    if (!compiled) {
        emit diagnosticsReported(compiled.diagnostics());
        setMode(EditorMode::Guide);
        return;
    }
    m_program = std::make_unique<eval::RigProgram>(compiled.take());
    m_posing = std::make_unique<eval::Posing>(*m_rig, *m_program);
    m_evaluation = m_program->makeState();
    poseFromDocument();
}

void EditorSession::poseFromDocument()
{
    if (!m_program)
        return;
    m_pose = eval::poseFromValues(*m_rig, m_program->channels(), m_document.pose);
    m_program->evaluate(m_pose, m_evaluation);
    emit poseChanged();
}

void EditorSession::previewPose(eval::Pose pose)
{
    m_pose = std::move(pose);
    m_program->evaluate(m_pose, m_evaluation);
    emit poseChanged();
}

QString EditorSession::commitPose(const eval::Pose& pose, const QString& what)
{
    auto values = eval::valuesFromPose(*m_rig, m_program->channels(), pose, m_document.pose);
    if (values == m_document.pose) {
        poseFromDocument(); // a drag that ended where it began: show the stored pose
        return {};
    }
    return messageOf(edit::setPose(m_history, std::move(values), what.toStdString()));
}

void EditorSession::selectControllers(const std::vector<model::RigNodeIndex>& nodes, bool add)
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

void EditorSession::pickwalk(eval::WalkDirection direction, bool instances)
{
    if (!instances && m_mode == EditorMode::Rig && m_rig && m_selection.node != model::kNoNode) {
        selectControllers({eval::pickwalk(*m_rig, m_selection.node, direction)}, false);
        return;
    }
    if (m_selection.instance != model::kNoId)
        select(Selection::ofInstance(eval::pickwalk(m_document, m_selection.instance, direction)));
}

void EditorSession::beginDrag(model::RigNodeIndex)
{
    if (m_program)
        m_dragStart = m_pose;
}

void EditorSession::dragTo(model::RigNodeIndex node, const Mat4& world)
{
    if (m_dragStart && m_posing)
        previewPose(m_posing->placeAt(*m_dragStart, node, world));
}

void EditorSession::endDrag(model::RigNodeIndex, const QString& what)
{
    if (!m_dragStart)
        return;
    m_dragStart.reset();
    commitPose(m_pose, what);
}

QString EditorSession::setChannel(int channel, double value, bool matchSpace)
{
    if (!m_program || channel < 0 || std::size_t(channel) >= m_program->channels().size())
        return tr("no such channel");
    const eval::Channel& c = m_program->channels()[channel];
    const QString name = QString::fromStdString(m_rig->nodes[c.node].name + "." + c.name);
    if (c.locked)
        return tr("%1 is locked").arg(name);
    eval::Pose pose = c.isEnum() ? m_posing->switchSpace(m_pose, channel, value, matchSpace) : m_pose;
    if (!c.isEnum())
        pose[channel] = m_program->channels().clamp(channel, value);
    return commitPose(pose, tr("Set %1").arg(name));
}

QString EditorSession::applyPoseTool(PoseTool tool)
{
    if (!m_posing)
        return tr("build the rig first");
    const auto& selected = m_selection.nodes;
    const auto all = m_rig->sets.count("controllers") ? m_rig->sets.at("controllers") : std::vector<model::RigNodeIndex>{};
    std::string error;
    std::optional<eval::Pose> pose;
    QString what;
    switch (tool) {
    case PoseTool::ResetSelected: pose = m_posing->reset(m_pose, selected); what = tr("Reset selected"); break;
    case PoseTool::ResetAll: pose = m_posing->reset(m_pose, {}); what = tr("Reset all"); break;
    case PoseTool::Mirror: pose = m_posing->mirror(m_pose, selected.empty() ? all : selected); what = tr("Mirror pose"); break;
    case PoseTool::Flip: pose = m_posing->flip(m_pose, selected.empty() ? all : selected); what = tr("Flip pose"); break;
    case PoseTool::IkToFk:
    case PoseTool::FkToIk:
        if (m_selection.node == model::kNoNode)
            return tr("select a control of the limb to match");
        pose = tool == PoseTool::IkToFk ? m_posing->ikToFk(m_pose, m_selection.node, error)
                                        : m_posing->fkToIk(m_pose, m_selection.node, error);
        what = tool == PoseTool::IkToFk ? tr("Match FK to IK") : tr("Match IK to FK");
        break;
    }
    if (tool == PoseTool::ResetSelected && selected.empty())
        return tr("select the controls to reset");
    if (!pose)
        return QString::fromStdString(error);
    return commitPose(*pose, what);
}

} // namespace rs::app
