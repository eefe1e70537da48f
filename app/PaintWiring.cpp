// MainWindow's weight painting: Skin > Paint Weights (the viewport's paint
// mode, in Guide and Rig mode alike: the brush hits the meshes as drawn), the
// Paint dock, and the viewport's strokes and vertex picks turned into session
// edits. The painted joint is the dock's current one, kept by skin joint
// identity so a rebuild keeps it; the weight display shows it.
#include "MainWindow.h"

#include "ActionKit.h"

#include "LogPanel.h"
#include "ViewportWidget.h"
#include "WeightPaintPanel.h"

#include <QDockWidget>
#include <QMenu>
#include <QStatusBar>

namespace rs::app {

namespace {
const char* kStrokeVerbs[] = {"Add", "Subtract", "Replace", "Smooth"};
}

void MainWindow::createPaintActions(QMenu* skinMenu)
{
    QAction* paint = makeAction(this, "paintWeights", tr("&Paint Weights"), QKeySequence(tr("Ctrl+Shift+P")));
    paint->setCheckable(true);
    const QString tip = tr("Paint the chosen joint's weights on the character: drag adds, Ctrl+drag subtracts, Shift+drag smooths; "
                           "B+drag or [ ] resize the brush; Alt or the middle button moves the camera (Ctrl+Shift+P)");
    paint->setToolTip(tip);
    paint->setStatusTip(tip);
    connect(paint, &QAction::toggled, this, &MainWindow::setPaintMode);
    skinMenu->addSeparator();
    skinMenu->addAction(paint);
}

void MainWindow::createPaintDock()
{
    m_paintPanel = new widgets::WeightPaintPanel(this);
    m_paintPanel->setObjectName("paintPanel");
    QDockWidget* dock = addDock(m_paintPanel, tr("Paint"), "paintDock", Qt::RightDockWidgetArea);
    if (auto* channels = findChild<QDockWidget*>("channelBoxDock"))
        tabifyDockWidget(channels, dock); // the full height for the joint list; raised with the paint mode
    dock->hide(); // shown with the paint mode
}

bool MainWindow::isPainting() const { return m_viewport && m_viewport->isPaintMode(); }

int MainWindow::paintBone() const
{
    if (!m_paintJoint)
        return -1;
    const auto& bones = m_session.skinBones();
    for (std::size_t b = 0; b < bones.size(); ++b)
        if (bones[b].key == *m_paintJoint)
            return int(b);
    return -1;
}

QString MainWindow::skinBoneName(int bone) const
{
    const auto& bones = m_session.skinBones();
    if (bone < 0 || std::size_t(bone) >= bones.size())
        return {};
    const model::Rig* rig = m_session.rig();
    const skin::SkinBone& b = bones[std::size_t(bone)];
    if (rig && b.node < rig->nodes.size())
        return QString::fromStdString(rig->nodes[b.node].name);
    return QString::fromStdString(b.key.tag + (b.key.branch.empty() ? "" : " (" + b.key.branch + ")"));
}

void MainWindow::choosePaintJoint(int bone)
{
    const auto& bones = m_session.skinBones();
    if (bone >= 0 && std::size_t(bone) < bones.size())
        m_paintJoint = bones[std::size_t(bone)].key;
    else
        m_paintJoint.reset();
    m_paintPanel->setCurrentJoint(paintBone());
    showPaintedWeights();
    refreshScene();
}

// The rigger sees what the brush paints: the weight display on the painted joint.
void MainWindow::showPaintedWeights()
{
    if (m_display.weights == viewport::WeightDisplay::Off)
        if (QAction* selected = action("weights:selected"))
            selected->setChecked(true); // refreshes the scene
}

void MainWindow::setPaintMode(bool on)
{
    if (QAction* a = action("paintWeights"); a && a->isChecked() != on)
        a->setChecked(on); // comes back here
    if (isPainting() == on)
        return;
    m_viewport->setPaintMode(on);
    if (auto* dock = findChild<QDockWidget*>("paintDock")) {
        dock->setVisible(on);
        if (on)
            dock->raise();
    }
    if (on) {
        if (paintBone() < 0) { // start on the selection's joint, else the first
            const int selected = viewport::skinBoneFor(m_session, m_session.mode() == EditorMode::Rig);
            const auto& bones = m_session.skinBones();
            m_paintJoint = selected >= 0 ? std::optional(bones[std::size_t(selected)].key)
                                         : bones.empty() ? std::nullopt : std::optional(bones.front().key);
        }
        refreshPaintPanel();
        showPaintedWeights();
        statusBar()->showMessage(tr("Paint weights: drag paints, Ctrl+drag subtracts, Shift+drag smooths, B+drag or [ ] resize; "
                                    "Alt or the middle button moves the camera"));
        m_viewport->setFocus(Qt::OtherFocusReason);
    } else {
        statusBar()->clearMessage();
    }
    refreshScene();
}

void MainWindow::refreshPaintPanel()
{
    std::vector<widgets::WeightPaintPanel::JointRow> rows;
    const auto& bones = m_session.skinBones();
    for (std::size_t b = 0; b < bones.size(); ++b)
        rows.push_back({skinBoneName(int(b)), m_session.lockedJoints().count(bones[b].key) > 0});
    m_paintPanel->showJoints(rows, paintBone());
}

void MainWindow::connectPaint()
{
    using viewport::ViewportWidget;
    using widgets::WeightPaintPanel;
    connect(m_viewport, &ViewportWidget::paintStrokeStarted, this, [this](int stroke) {
        m_strokeOpen = false;
        const int bone = paintBone();
        if (bone < 0) {
            logStatus(Status::refused("choose the joint to paint in the Paint dock (Skin > Paint Weights)"));
            return;
        }
        skin::Brush brush = m_paintPanel->brush();
        brush.radius = m_viewport->brushRadius(); // the circle the rigger sees (the dock rounds to millimetres)
        if (stroke == int(viewport::PaintStroke::Subtract))
            brush.mode = skin::BrushMode::Subtract;
        else if (stroke == int(viewport::PaintStroke::Smooth))
            brush.mode = skin::BrushMode::Smooth;
        m_strokeBrush = brush;
        m_strokeOpen = true;
        m_strokeRefused = false;
        showPaintedWeights();
        m_session.beginWeightStroke(tr("%1 weights of %2").arg(kStrokeVerbs[int(brush.mode)], skinBoneName(bone)).toStdString());
    });
    connect(m_viewport, &ViewportWidget::paintDabbed, this, [this](quint64 mesh, const glm::dvec3& centre, quint32 vertex) {
        if (!m_strokeOpen || !m_paintJoint)
            return;
        skin::Brush brush = m_strokeBrush;
        brush.centre = centre;
        brush.vertex = vertex;
        const Status status = m_session.paintWeights(std::size_t(mesh), *m_paintJoint, brush);
        if (status.failed() && !m_strokeRefused) { // once per stroke, not once per dab
            m_strokeRefused = true;
            logStatus(status);
        }
    });
    connect(m_viewport, &ViewportWidget::paintStrokeFinished, this, [this] {
        if (!m_strokeOpen)
            return;
        m_strokeOpen = false;
        m_session.endWeightStroke();
    });
    connect(m_viewport, &ViewportWidget::verticesSelected, this, [this](const viewport::VertexSelection& picked, bool add) {
        if (picked.empty() && !add)
            m_session.clearVertexSelection();
        for (std::size_t i = 0; i < picked.size(); ++i)
            m_session.selectVertices(picked[i].first, picked[i].second, add || i > 0);
    });
    connect(m_viewport, &ViewportWidget::brushRadiusChanged, m_paintPanel, &WeightPaintPanel::setRadius);

    connect(m_paintPanel, &WeightPaintPanel::brushChanged, this, [this] { m_viewport->setBrushRadius(m_paintPanel->brush().radius); });
    connect(m_paintPanel, &WeightPaintPanel::toolChanged, this, [this](int tool) {
        m_viewport->setPaintTool(WeightPaintPanel::Tool(tool) == WeightPaintPanel::Tool::SelectVertices ? viewport::PaintTool::SelectVertices
                                                                                                       : viewport::PaintTool::Brush);
    });
    connect(m_paintPanel, &WeightPaintPanel::jointChosen, this, &MainWindow::choosePaintJoint);
    connect(m_paintPanel, &WeightPaintPanel::jointLockChanged, this, [this](int bone, bool locked) {
        const auto& bones = m_session.skinBones();
        if (bone >= 0 && std::size_t(bone) < bones.size())
            m_session.setJointLocked(bones[std::size_t(bone)].key, locked);
    });
    connect(m_paintPanel, &WeightPaintPanel::operationRequested, this, [this](int operation, double amount) {
        logStatus(m_session.applyWeightOperation(session::Session::WeightOperation(operation), amount));
    });
    connect(m_paintPanel, &WeightPaintPanel::mirrorRequested, this, [this](bool fromPositive) { logStatus(m_session.mirrorWeights(fromPositive)); });
    connect(m_paintPanel, &WeightPaintPanel::copyRequested, this, [this] {
        const Status copied = m_session.copyVertexWeights();
        logStatus(copied);
        if (copied.ok())
            statusBar()->showMessage(tr("Copied the vertex's weights"), 3000);
    });
    connect(m_paintPanel, &WeightPaintPanel::pasteRequested, this, [this] { logStatus(m_session.pasteVertexWeights()); });
    connect(m_paintPanel, &WeightPaintPanel::clearSelectionRequested, this, [this] { m_session.clearVertexSelection(); });
}

} // namespace rs::app
