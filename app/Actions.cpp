// MainWindow's actions, menus and toolbar: one topic file so the window class
// stays a thin composition root.
#include "MainWindow.h"

#include "ActionKit.h"

#include "ExportDialog.h"
#include "Settings.h"

#include "LogPanel.h"
#include "ViewportWidget.h"
#include "base/Paths.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QFileDialog>
#include <QMenuBar>
#include <QToolBar>

namespace rs::app {

QAction* makeAction(QObject* owner, const QString& objectName, const QString& text, const QKeySequence& shortcut,
                    const QString& icon)
{
    auto* a = new QAction(text, owner);
    a->setObjectName(objectName);
    if (!shortcut.isEmpty())
        a->setShortcut(shortcut);
    if (!icon.isEmpty())
        a->setIcon(QIcon(QString::fromStdString(iconsDirectory()) + "/" + icon + ".svg"));
    return a;
}

QAction* MainWindow::action(const QString& objectName) const
{
    return findChild<QAction*>(objectName);
}

void MainWindow::createActions()
{
    QAction* open = makeAction(this, "open", tr("&Open..."), QKeySequence::Open);
    QAction* save = makeAction(this, "save", tr("&Save"), QKeySequence::Save);
    QAction* saveAs = makeAction(this, "saveAs", tr("Save &As..."), QKeySequence::SaveAs);
    QAction* exportRigAction = makeAction(this, "exportRig", tr("&Export..."), QKeySequence(tr("Ctrl+E")), "export");
    QAction* quit = makeAction(this, "quit", tr("&Quit"), QKeySequence::Quit);
    QAction* undo = makeAction(this, "undo", tr("&Undo"), QKeySequence::Undo);
    QAction* redo = makeAction(this, "redo", tr("&Redo"), QKeySequence::Redo);
    QAction* build = makeAction(this, "build", tr("&Build"), QKeySequence(tr("Ctrl+B")), "build");
    QAction* reload = makeAction(this, "reloadTemplates", tr("&Reload Templates"), QKeySequence(Qt::Key_F5));
    reload->setToolTip(tr("Rescan the template folders and shapes (F5)"));

    const QString filter = tr("Rigsmith guides (*.yml *.yaml)");
    connect(open, &QAction::triggered, this, [this, filter] {
        if (!maySwitchDocument(tr("Save the guide before opening another?")))
            return;
        const QString path = QFileDialog::getOpenFileName(this, tr("Open guide"), QString::fromStdString(samplesDirectory()), filter);
        if (!path.isEmpty())
            openFile(path);
    });
    connect(saveAs, &QAction::triggered, this, [this, filter] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save guide"), m_session.filePath(), filter);
        if (!path.isEmpty())
            saveFile(path);
    });
    connect(save, &QAction::triggered, this, [this, saveAs] {
        if (m_session.filePath().isEmpty())
            saveAs->trigger();
        else
            saveFile(m_session.filePath());
    });
    connect(exportRigAction, &QAction::triggered, this, [this] {
        exportDialog()->show();
        exportDialog()->raise();
    });
    connect(quit, &QAction::triggered, this, &QWidget::close);
    connect(undo, &QAction::triggered, this, [this] { m_session.history().undo(); });
    connect(redo, &QAction::triggered, this, [this] { m_session.history().redo(); });
    connect(build, &QAction::triggered, this, &MainWindow::buildRig);
    connect(reload, &QAction::triggered, this, &MainWindow::reloadTemplates);
    updateUndoActions();

    QMenu* file = menuBar()->addMenu(tr("&File"));
    // File > New: an empty guide or a copy of a bundled sample (biped, quadruped, prop, face, vehicle, robot, claw, cart, strider).
    QMenu* newMenu = file->addMenu(tr("&New"));
    newMenu->setObjectName("newMenu");
    QAction* empty = makeAction(this, "new:empty", tr("&Empty guide"), QKeySequence::New);
    connect(empty, &QAction::triggered, this, [this] {
        if (maySwitchDocument(tr("Save the guide before starting a new one?")))
            newFromSample(QString());
    });
    newMenu->addAction(empty);
    newMenu->addSeparator();
    const QDir samples(QString::fromStdString(samplesDirectory()));
    for (const QFileInfo& sample : samples.entryInfoList({"*.yml"}, QDir::Files, QDir::Name)) {
        QAction* a = makeAction(this, "new:" + sample.completeBaseName(), sample.completeBaseName(), {});
        a->setToolTip(tr("A new guide starting from the %1 sample").arg(sample.completeBaseName()));
        const QString path = sample.absoluteFilePath();
        connect(a, &QAction::triggered, this, [this, path] {
            if (maySwitchDocument(tr("Save the guide before starting a new one?")))
                newFromSample(path);
        });
        newMenu->addAction(a);
    }
    file->addAction(open);
    QMenu* recent = file->addMenu(tr("Open &Recent"));
    recent->setObjectName("recentMenu");
    connect(recent, &QMenu::aboutToShow, this, [this, recent] {
        recent->clear();
        const QStringList files = settings::recentFiles();
        for (const QString& path : files)
            recent->addAction(path, this, [this, path] {
                if (maySwitchDocument(tr("Save the guide before opening another?")))
                    openFile(path);
            });
        if (files.isEmpty())
            recent->addAction(tr("No recent guides"))->setEnabled(false);
    });
    file->addActions({save, saveAs});
    file->addSeparator();
    file->addAction(exportRigAction);
    file->addSeparator();
    QAction* close = makeAction(this, "closeGuide", tr("&Close"), QKeySequence::Close);
    close->setToolTip(tr("Close the guide (an empty untitled guide takes its place)"));
    connect(close, &QAction::triggered, this, &MainWindow::closeDocument);
    file->addAction(close);
    file->addAction(quit);
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->setObjectName("editMenu");
    edit->addActions({undo, redo});
    QMenu* rig = menuBar()->addMenu(tr("&Rig"));
    rig->addAction(build);
    createRestoreActions(rig);
    rig->addSeparator();
    rig->addAction(reload);

    QToolBar* bar = addToolBar(tr("Main"));
    bar->setObjectName("mainToolBar");
    bar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    bar->addActions({build, exportRigAction});
    bar->addSeparator();
    bar->addActions({undo, redo});
    createEditActions();
    createPoseActions();
    createViewActions();
    createSkinActions();
}

void MainWindow::createPoseActions()
{
    QAction* guideMode = makeAction(this, "modeGuide", tr("&Guide mode"), QKeySequence(Qt::Key_F3));
    QAction* rigMode = makeAction(this, "modeRig", tr("&Rig mode"), QKeySequence(Qt::Key_F4));
    guideMode->setToolTip(tr("Author guides (F3)"));
    rigMode->setToolTip(tr("Pose the built rig as an animator would (F4); Build switches to it"));
    auto* modes = new QActionGroup(this);
    for (QAction* a : {guideMode, rigMode}) {
        a->setCheckable(true);
        modes->addAction(a);
    }
    guideMode->setChecked(true);
    connect(guideMode, &QAction::triggered, this, [this] { m_session.setMode(EditorMode::Guide); });
    connect(rigMode, &QAction::triggered, this, [this] {
        if (!m_session.rig() || m_session.isRigStale())
            buildRig();
        m_session.setMode(EditorMode::Rig);
    });

    const std::tuple<const char*, QString, QKeySequence, PoseTool> tools[] = {
        {"resetSelected", tr("Reset &Selected"), QKeySequence(tr("Ctrl+Shift+R")), PoseTool::ResetSelected},
        {"resetAll", tr("Reset &All"), QKeySequence(), PoseTool::ResetAll},
        {"mirrorPose", tr("&Mirror Pose"), QKeySequence(tr("Ctrl+Shift+M")), PoseTool::Mirror},
        {"flipPose", tr("&Flip Pose"), QKeySequence(tr("Ctrl+Shift+F")), PoseTool::Flip},
        {"ikToFk", tr("Match &FK to IK (switch to FK)"), QKeySequence(), PoseTool::IkToFk},
        {"fkToIk", tr("Match &IK to FK (switch to IK)"), QKeySequence(), PoseTool::FkToIk}};
    QMenu* pose = menuBar()->addMenu(tr("&Pose"));
    pose->addActions({guideMode, rigMode});
    pose->addSeparator();
    for (const auto& [name, text, shortcut, tool] : tools) {
        QAction* a = makeAction(this, name, text, shortcut);
        const PoseTool t = tool;
        connect(a, &QAction::triggered, this, [this, t] {
            logStatus(m_session.applyPoseTool(t));
        });
        pose->addAction(a);
        if (t == PoseTool::ResetAll || t == PoseTool::Flip)
            pose->addSeparator();
    }
    QAction* worldGizmo = makeAction(this, "gizmoWorld", tr("Gizmo in &World Space"), QKeySequence(tr("Ctrl+Shift+W")));
    worldGizmo->setCheckable(true);
    worldGizmo->setToolTip(tr("Translate and rotate along world axes instead of the control's own"));
    connect(worldGizmo, &QAction::toggled, this, [this](bool on) { m_viewport->setGizmoWorldSpace(on); });
    pose->addSeparator();
    pose->addAction(worldGizmo);

    QToolBar* bar = findChild<QToolBar*>("mainToolBar");
    bar->addSeparator();
    bar->addActions({guideMode, rigMode});
}

void MainWindow::updateUndoActions()
{
    QAction* undo = action("undo");
    QAction* redo = action("redo");
    if (!undo || !redo)
        return;
    const auto& h = m_session.history();
    undo->setEnabled(h.canUndo());
    redo->setEnabled(h.canRedo());
    undo->setText(h.canUndo() ? tr("&Undo %1").arg(QString::fromStdString(h.undoText())) : tr("&Undo"));
    redo->setText(h.canRedo() ? tr("&Redo %1").arg(QString::fromStdString(h.redoText())) : tr("&Redo"));
    undo->setIconText(tr("Undo")); // the toolbar keeps a short label; the menu and tooltip name the step
    redo->setIconText(tr("Redo"));
    undo->setToolTip(undo->text().remove('&'));
    redo->setToolTip(redo->text().remove('&'));
}

void MainWindow::followMode()
{
    const bool rigMode = m_session.mode() == EditorMode::Rig;
    if (QAction* a = action(rigMode ? "modeRig" : "modeGuide"))
        a->setChecked(true);
    m_viewport->setRigMode(rigMode);
    // The dock for the mode: the transform panel in Guide mode, the channel box in Rig mode (the Paint dock while painting).
    if (auto* dock = findChild<QDockWidget*>(isPainting() ? "paintDock" : rigMode ? "channelBoxDock" : "transformDock"))
        dock->raise();
}

} // namespace rs::app
