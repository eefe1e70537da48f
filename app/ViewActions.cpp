// MainWindow's View and Guide menus: camera views and framing (the viewport
// handles the same keys when it has focus), symmetric editing, grid snapping,
// CV mode and duplicating.
#include "MainWindow.h"

#include "ActionKit.h"
#include "LogPanel.h"
#include "OutlinerView.h"
#include "ViewportWidget.h"

#include <QActionGroup>
#include <QFileDialog>
#include <QMenuBar>
#include <QToolBar>

namespace rs::app {

void MainWindow::createViewActions()
{
    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->setObjectName("viewMenu");
    auto* views = new QActionGroup(this); // in CameraView order: ViewportWiring checks the current one
    const std::tuple<const char*, QString, viewport::CameraView> cameraViews[] = {
        {"viewPerspective", tr("&Perspective\t5"), viewport::CameraView::Perspective},
        {"viewFront", tr("&Front\t1"), viewport::CameraView::Front},
        {"viewSide", tr("&Side\t3"), viewport::CameraView::Side},
        {"viewTop", tr("&Top\t7"), viewport::CameraView::Top}};
    for (const auto& [name, text, cameraView] : cameraViews) {
        QAction* a = makeAction(this, name, text, {});
        a->setCheckable(true);
        a->setChecked(cameraView == viewport::CameraView::Perspective);
        views->addAction(a);
        view->addAction(a);
        const auto v = cameraView;
        connect(a, &QAction::triggered, this, [this, v] { m_viewport->setView(v); });
    }
    view->addSeparator();
    QAction* frameSelected = makeAction(this, "frameSelected", tr("Frame &Selected\tF"), {});
    QAction* frameAll = makeAction(this, "frameAll", tr("Frame &All\tA"), {});
    connect(frameSelected, &QAction::triggered, this, [this] { m_viewport->frameSelection(); });
    connect(frameAll, &QAction::triggered, this, [this] { m_viewport->frameAll(); });
    view->addActions({frameSelected, frameAll});

    QMenu* guide = menuBar()->addMenu(tr("&Guide"));
    guide->setObjectName("guideMenu");
    QAction* symmetry = makeAction(this, "symmetry", tr("S&ymmetric Editing"), QKeySequence(tr("Ctrl+Shift+Y")), "mirror");
    symmetry->setToolTip(tr("Moving a guide of a side instance (arm_L) moves its twin (arm_R) mirrored; "
                            "mirrored branches (L/R) follow always"));
    QAction* snap = makeAction(this, "snapGrid", tr("Snap to &Grid (5 cm)"), QKeySequence(tr("Ctrl+Shift+G")));
    snap->setToolTip(tr("Translating a guide joint snaps its world position to a 5 cm grid"));
    for (QAction* a : {symmetry, snap}) {
        a->setCheckable(true);
        connect(a, &QAction::toggled, this, [this, symmetry, snap] {
            m_session.setGuideDragOptions({symmetry->isChecked(), snap->isChecked() ? 0.05 : 0.0});
        });
    }
    QAction* cvMode = makeAction(this, "cvMode", tr("&CV Mode"), QKeySequence(Qt::Key_F8), "cvs");
    cvMode->setCheckable(true);
    cvMode->setToolTip(tr("Edit the control points of the selected controllers' shapes (F8, as Maya's component mode): "
                          "click or box-select CVs, then W/E/R"));
    connect(cvMode, &QAction::toggled, this, [this](bool on) { m_session.setCvMode(on); });
    QAction* duplicate = makeAction(this, "duplicate", tr("&Duplicate"), QKeySequence(tr("Ctrl+D")));
    connect(duplicate, &QAction::triggered, this, [this] {
        std::vector<model::InstanceId> ids = m_outliner->topSelectedInstances();
        if (ids.empty() && m_session.selection().instance != model::kNoId)
            ids.push_back(m_session.selection().instance);
        logStatus(ids.empty() ? Status::refused(tr("select the templates to duplicate").toStdString())
                             : m_session.duplicateInstances(ids));
    });
    guide->addActions({symmetry, snap, cvMode});
    guide->addSeparator();
    guide->addAction(duplicate);
    findChild<QToolBar*>("mainToolBar")->addActions({symmetry, cvMode});
}

} // namespace rs::app
