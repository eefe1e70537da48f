// MainWindow's viewport wiring: picks and box selection, gizmo drags (guide
// joints, shapes or CVs in Guide mode, controllers in Rig mode), pickwalk and
// the channel box, and what the viewport draws.
#include "MainWindow.h"

#include "ChannelBox.h"
#include "LogPanel.h"
#include "SceneCharacter.h"
#include "ViewportWidget.h"

#include <QAction>
#include <QLabel>

namespace rs::app {

namespace {
const char* kDragVerbs[] = {"Move", "Rotate", "Scale"};
}

void MainWindow::connectViewport()
{
    using viewport::ViewportWidget;
    connect(m_viewport, &ViewportWidget::guideJointPicked, this,
            [this](quint32 joint, quint32, bool add) { m_session.selectGuideJoints({joint}, add); });
    connect(m_viewport, &ViewportWidget::guideJointsBoxSelected, this, [this](const QList<quint32>& joints, bool add) {
        m_session.selectGuideJoints(std::vector<model::JointId>(joints.begin(), joints.end()), add);
    });
    connect(m_viewport, &ViewportWidget::controllerPicked, this,
            [this](quint32 node, bool add) { m_session.selectControllers({node}, add); });
    connect(m_viewport, &ViewportWidget::controllersBoxSelected, this, [this](const QList<quint32>& nodes, bool add) {
        m_session.selectControllers(std::vector<model::RigNodeIndex>(nodes.begin(), nodes.end()), add);
    });
    connect(m_viewport, &ViewportWidget::cvsSelected, this,
            [this](const std::vector<model::CurveCv>& cvs, bool add) { m_session.selectCvs(cvs, add); });
    connect(m_viewport, &ViewportWidget::nothingPicked, this, [this] {
        if (m_session.isCvMode() && !m_session.selection().cvs.empty())
            m_session.selectCvs({}, false); // CV mode: a click on nothing drops the CVs, keeps the controller
        else
            m_session.select({});
    });

    // Guide mode: the gizmo is on a guide joint, on the selected controller's
    // shape, or (CV mode) on the selected CVs.
    auto guideMode = [this] { return m_session.mode() == EditorMode::Guide; };
    auto cvMode = [this, guideMode] { return guideMode() && m_session.isCvMode(); };
    auto shapeMode = [this, guideMode] { return guideMode() && m_session.selection().node != model::kNoNode; };
    connect(m_viewport, &ViewportWidget::gizmoDragStarted, this, [this, guideMode, shapeMode, cvMode](quint32 target) {
        if (cvMode()) m_session.beginCvDrag();
        else if (shapeMode()) m_session.beginShapeDrag(target);
        else if (guideMode()) m_session.beginGuideDrag(target);
        else m_session.beginDrag(target);
    });
    connect(m_viewport, &ViewportWidget::gizmoDragged, this,
            [this, guideMode, shapeMode, cvMode](quint32 target, const glm::dmat4& world) {
                if (cvMode()) m_session.dragCvsTo(world);
                else if (shapeMode()) m_session.dragShapeTo(world);
                else if (guideMode()) m_session.dragGuideTo(world);
                else m_session.dragTo(target, world);
            });
    connect(m_viewport, &ViewportWidget::gizmoDragFinished, this, [this, guideMode, shapeMode, cvMode](quint32 target) {
        const QString verb = kDragVerbs[int(m_viewport->gizmoMode())];
        if (cvMode()) {
            logStatus(m_session.endCvDrag(verb.toStdString()));
            return;
        }
        if (shapeMode()) {
            logStatus(m_session.endShapeDrag());
            return;
        }
        if (guideMode()) {
            const model::TemplateInstance* owner = m_session.document().ownerOf(target);
            const QString name = owner ? QString::fromStdString(owner->name) : QString();
            const std::size_t count = std::max<std::size_t>(1, m_session.selection().joints.size());
            logStatus(m_session.endGuideDrag((count > 1 ? tr("%1 %2 guide joints").arg(verb).arg(count)
                                                       : tr("%1 guide joint of %2").arg(verb, name)).toStdString()));
            return;
        }
        const auto* rig = m_session.rig();
        const QString name = rig && target < rig->nodes.size() ? QString::fromStdString(rig->nodes[target].name) : QString();
        m_session.endDrag(target, QString("%1 %2").arg(verb, name).toStdString());
    });
    connect(m_viewport, &ViewportWidget::renderWarning, this,
            [this](const QString& message) { m_log->addMessage(message, Severity::Warning); });
    connect(m_viewport, &ViewportWidget::viewChanged, this, [this](int view) {
        const char* names[] = {"viewPerspective", "viewFront", "viewSide", "viewTop"};
        if (QAction* a = action(names[view])) a->setChecked(true);
    });
}

void MainWindow::connectRigMode()
{
    connect(m_viewport, &viewport::ViewportWidget::pickwalkRequested, this,
            [this](int direction) { m_session.pickwalk(eval::WalkDirection(direction)); });
    connect(m_channelBox, &widgets::ChannelBox::channelEdited, this, [this](int channel, double value, bool match) {
        logStatus(m_session.setChannel(channel, value, match));
    });
    // After a value is entered the keyboard goes back to the viewport: hotkeys and arrow pickwalk work again.
    connect(m_channelBox, &widgets::ChannelBox::editingDone, this, [this] { m_viewport->setFocus(Qt::OtherFocusReason); });
    connectChannelOverrides();
}

void MainWindow::refreshScene()
{
    const Selection& s = m_session.selection();
    const bool rigMode = m_session.mode() == EditorMode::Rig;
    const eval::EvalState* pose = rigMode ? m_session.evaluation() : nullptr;
    const bool cvMode = !rigMode && m_session.isCvMode();
    // The mirrored branches' guides are drawn with the guides only (not in Rig mode).
    const std::vector<session::MirroredGuideJoint> mirrored =
        pose ? std::vector<session::MirroredGuideJoint>{} : m_session.mirroredGuideJoints();
    // A rig that no longer matches the guide is not drawn over it (Build brings it back).
    const model::Rig* drawnRig = rigMode || !m_session.isRigStale() ? m_session.rig() : nullptr;
    viewport::Scene scene = viewport::makeScene(m_session.document(), drawnRig,
                                                {s.instance, s.joint, s.joints, s.node, s.nodes, cvMode, s.cvs}, pose,
                                                mirrored);
    viewport::addCharacter(scene, m_session, m_characterWeights, rigMode);
    if (m_display.weights == viewport::WeightDisplay::SelectedJoint)
        scene.weightBone = isPainting() ? paintBone() : viewport::skinBoneFor(m_session, rigMode);
    viewport::applyDisplay(scene, m_display, rigMode);
    if (m_showRoutes && !isPainting())
        applyRouteColours(scene);
    m_viewport->setScene(std::move(scene), std::exchange(m_sceneChanged, std::nullopt));
    const auto* rig = m_session.rig();
    const bool hasNode = rig && pose && s.node != model::kNoNode && s.node < rig->nodes.size();
    if (rigMode) {
        m_viewport->setGizmoTarget(hasNode ? s.node : model::kNoNode, hasNode ? pose->worldMatrix(s.node) : glm::dmat4(1.0));
    } else if (cvMode) {
        const auto frame = m_session.cvFrame(); // no gizmo until CVs are picked
        m_viewport->setGizmoTarget(frame ? s.node : model::kNoNode, frame.value_or(glm::dmat4(1.0)));
    } else if (const auto frame = s.node != model::kNoNode ? m_session.shapeFrame(s.node) : std::nullopt) {
        m_viewport->setGizmoTarget(s.node, *frame); // the selected controller's shape
    } else {
        const model::JointId joint = m_session.gizmoJoint();
        m_viewport->setGizmoTarget(joint != model::kNoId ? joint : model::kNoNode,
                                   joint != model::kNoId ? m_session.document().jointWorldMatrix(joint) : glm::dmat4(1.0));
    }
    // Driven channels (driven keys, a mod's connection) show the value their driver gives them.
    const eval::EvalState* evaluated = m_session.evaluation();
    const eval::Pose* shown = evaluated && evaluated->channels.size() == m_session.pose().size() ? &evaluated->channels : &m_session.pose();
    m_channelBox->showNode(rigMode && m_session.program() ? &m_session.program()->channels() : nullptr,
                           hasNode ? s.node : model::kNoNode, hasNode ? QString::fromStdString(rig->nodes[s.node].name) : QString(),
                           shown, hasNode ? channelBoxRecord(s.node) : nullptr);
    if (!rig)
        m_status->setText(tr("Guide: %1 templates").arg(m_session.document().instances().size()));
    else
        m_status->setText(tr("Rig%1: %2 controllers, %3 skin joints")
                              .arg(m_session.isRigStale() ? tr(" (out of date, press Build)") : QString())
                              .arg(rig->count(model::RigNodeKind::Controller))
                              .arg(rig->skinJointCount()));
}

} // namespace rs::app
