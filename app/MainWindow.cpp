#include "MainWindow.h"

#include "ChannelBox.h"
#include "ExportDialog.h"
#include "OptionsEditor.h"
#include "HistoryView.h"
#include "Settings.h"
#include "TemplateLibrary.h"
#include "TransformPanel.h"
#include "LogPanel.h"
#include "OutlinerView.h"
#include "ViewportWidget.h"

#include <QCloseEvent>
#include <QFile>
#include <QTimer>
#include <QCoreApplication>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QProgressBar>
#include <QMessageBox>
#include <QStatusBar>

namespace rs::app {

namespace {

// The first `count` errors (warnings when there are none): what a message box has room for.
Diagnostics errorsOf(const Diagnostics& diagnostics, std::size_t count)
{
    Diagnostics out;
    for (Severity severity : {Severity::Error, Severity::Warning}) {
        for (const Diagnostic& d : diagnostics)
            if (d.severity == severity && out.size() < count)
                out.push_back(d);
        if (!out.empty())
            break;
    }
    return out;
}

} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent)
{
    createActions();
    createDocks();
    connectDocument();
    createRouteOverlay();
    // Changed meshes are re-fitted on a worker thread: opening a guide never blocks the window.
    m_session.setRefitRunner([this](session::RefitJob job) { startRefit(std::move(job)); });
    settings::restoreWindow(*this);

    auto* autosave = new QTimer(this);
    autosave->setObjectName("autosaveTimer");
    connect(autosave, &QTimer::timeout, this, [this] {
        Diagnostics diagnostics;
        if (m_session.autosave(diagnostics))
            statusBar()->showMessage(tr("Autosaved to %1").arg(m_session.autosavePath()), 3000);
        else if (hasErrors(diagnostics))
            report(tr("Autosave failed"), diagnostics);
    });
    autosave->start(kAutosaveMilliseconds);
    m_errorPrompt = [this](const QString& title, const QString& text) {
        if (isVisible() && !property("skipUnsavedPrompt").toBool()) // tests drive the editor without modal boxes
            QMessageBox::warning(this, title, text);
    };
    m_recoveryPrompt = [this](const QString& file, const QString& autosavePath) {
        return QMessageBox::question(this, tr("Recover unsaved changes?"),
                                     tr("%1 has unsaved changes from %2 that were not saved (the editor did not close "
                                        "normally). Recover them?")
                                         .arg(file.isEmpty() ? tr("An untitled guide") : file,
                                              QFileInfo(autosavePath).lastModified().toString()),
                                     QMessageBox::Yes | QMessageBox::No) == QMessageBox::Yes;
    };
}

MainWindow::~MainWindow()
{
    // The session goes before the child widgets: a field still being typed in
    // commits its value when it is hidden, and that edit must not reach it.
    for (QObject* view : findChildren<QWidget*>())
        disconnect(view, nullptr, this, nullptr);
}

void MainWindow::offerUntitledRecovery()
{
    if (EditorSession::recoveryState({}) == EditorSession::Recovery::NothingNewer)
        QFile::remove(EditorSession::autosavePathFor({}));
    if (!EditorSession::hasRecovery({}))
        return;
    Diagnostics diagnostics;
    if (m_recoveryPrompt({}, EditorSession::autosavePathFor({})) && m_session.recover({}, diagnostics))
        report(tr("Recovered an untitled guide"), diagnostics);
    else
        QFile::remove(EditorSession::autosavePathFor({}));
    updateTitle();
}

QDockWidget* MainWindow::addDock(QWidget* widget, const QString& title, const QString& objectName, Qt::DockWidgetArea area)
{
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(objectName);
    dock->setWidget(widget);
    addDockWidget(area, dock);
    return dock;
}

void MainWindow::createDocks()
{
    m_viewport = new viewport::ViewportWidget(this);
    m_viewport->setObjectName("viewport");
    setCentralWidget(m_viewport);

    m_outliner = new widgets::OutlinerView(this);
    QDockWidget* outlinerDock = addDock(m_outliner, tr("Outliner"), "outlinerDock", Qt::LeftDockWidgetArea);
    m_library = new widgets::TemplateLibrary(this);
    addDock(m_library, tr("Templates"), "libraryDock", Qt::LeftDockWidgetArea);

    m_log = new widgets::LogPanel(this);
    QDockWidget* logDock = addDock(m_log, tr("Build log"), "logDock", Qt::BottomDockWidgetArea);
    m_historyView = new widgets::HistoryView(this);
    tabifyDockWidget(logDock, addDock(m_historyView, tr("History"), "historyDock", Qt::BottomDockWidgetArea));
    createOverridesDock(logDock);
    createModsDock(logDock);
    logDock->raise();

    m_channelBox = new widgets::ChannelBox(this);
    m_channelBox->setObjectName("channelBox");
    QDockWidget* channelDock = addDock(m_channelBox, tr("Channel box"), "channelBoxDock", Qt::RightDockWidgetArea);
    // Right-click in the channel box: match the selected limb's FK and IK (the Pose menu's actions).
    for (const char* name : {"ikToFk", "fkToIk"})
        if (auto* match = findChild<QAction*>(name))
            m_channelBox->addAction(match);
    m_channelBox->setContextMenuPolicy(Qt::ActionsContextMenu);
    m_transformPanel = new widgets::TransformPanel(this);
    tabifyDockWidget(channelDock, addDock(m_transformPanel, tr("Transform"), "transformDock", Qt::RightDockWidgetArea));
    m_options = new widgets::OptionsEditor(this);
    createPaintDock();
    createSkinChunkDock();
    resizeDocks({addDock(m_options, tr("Options"), "optionsDock", Qt::RightDockWidgetArea), outlinerDock}, {340, 250},
                Qt::Horizontal);

    m_status = new QLabel(this);
    statusBar()->addPermanentWidget(m_status);
    m_buildProgress = new QProgressBar(this);
    m_buildProgress->setObjectName("buildProgress");
    m_buildProgress->setRange(0, 1000);
    m_buildProgress->setMaximumWidth(200);
    m_buildProgress->setTextVisible(false);
    m_buildProgress->hide();
    statusBar()->addPermanentWidget(m_buildProgress);
    connect(&m_session, &EditorSession::buildProgressed, this, &MainWindow::showBuildProgress);
    resize(1400, 900);
    createDisplayActions(); // the menus that drive the viewport and list the docks
    createHelpActions();
}

void MainWindow::connectDocument()
{
    // One typed event per change: each view refreshes only what it names.
    connect(&m_session, &EditorSession::changed, this, &MainWindow::follow);
    connect(&m_session, &EditorSession::diagnosticsReported, m_log, &widgets::LogPanel::addDiagnostics);

    connect(m_outliner, &widgets::OutlinerView::instanceSelected, this,
            [this](quint32 id) { m_session.select(Selection::ofInstance(id)); });
    connect(m_outliner, &widgets::OutlinerView::addTemplateRequested, this, [this](const QString& id, quint32 joint) {
        logStatus(m_session.addTemplate(id.toStdString(), joint));
    });
    connect(m_outliner, &widgets::OutlinerView::removeRequested, this, [this](const QList<quint32>& ids) {
        logStatus(m_session.removeInstances({ids.begin(), ids.end()}));
    });
    connect(m_outliner, &widgets::OutlinerView::renameRequested, this, [this](quint32 id, const QString& name) {
        if (const Status renamed = m_session.renameInstance(id, name.toStdString()); renamed.failed()) {
            logStatus(renamed);
            refreshViews(); // put the old name back in the tree
        }
    });
    connect(m_outliner, &widgets::OutlinerView::branchesRequested, this, [this](quint32 id, const QString& branches) {
        logStatus(m_session.setOption(id, "branches", Value(branches.toStdString())));
    });
    connect(m_outliner, &widgets::OutlinerView::duplicateRequested, this, [this](const QList<quint32>& ids) {
        logStatus(m_session.duplicateInstances(std::vector<model::InstanceId>(ids.begin(), ids.end())));
    });
    connect(m_outliner, &widgets::OutlinerView::reparentRequested, this, [this](quint32 id, quint32 joint) {
        logStatus(m_session.reparentInstance(id, joint));
    });
    connect(m_outliner, &widgets::OutlinerView::hookSelected, this,
            [this](quint32 id, quint32 joint) { m_session.select(Selection::ofInstance(id, joint)); });
    connect(m_outliner, &widgets::OutlinerView::resetOptionsRequested, this, [this](quint32 id) {
        logStatus(m_session.resetOptions(id));
    });
    connect(m_log, &widgets::LogPanel::subjectActivated, this,
            [this](const rs::Subject& subject) { m_session.selectSubject(subject); });
    connect(m_outliner, &widgets::OutlinerView::walkRequested, this,
            [this](int direction) { m_session.pickwalk(eval::WalkDirection(direction), true); });
    connectViewport();
    connectRigMode();
    connectOptions();
    connectTransformPanel();
    connectPaint();

    m_log->addDiagnostics(m_session.templateDiagnostics());
    refreshViews();
    updateTitle();
}

void MainWindow::setAutosaveEnabled(bool on)
{
    if (auto* timer = findChild<QTimer*>("autosaveTimer"))
        on ? timer->start(kAutosaveMilliseconds) : timer->stop();
}

void MainWindow::logStatus(const Status& status)
{
    m_log->addDiagnostics(status.diagnostics());
}

void MainWindow::refreshViews()
{
    m_outliner->refresh(m_session.document(), m_session.templates());
    m_outliner->selectInstance(m_session.selection().instance);
    refreshScene();
}

void MainWindow::updateTitle()
{
    const QString name = m_session.filePath().isEmpty() ? tr("untitled") : QFileInfo(m_session.filePath()).fileName();
    setWindowTitle(QString("%1%2 - Rigsmith").arg(name, m_session.history().isClean() ? "" : "*"));
}

void MainWindow::report(const QString& what, const Diagnostics& diagnostics)
{
    if (!what.isEmpty())
        m_log->addMessage(what, hasErrors(diagnostics) ? Severity::Error : Severity::Note);
    m_log->addDiagnostics(diagnostics);
}

void MainWindow::showWriteFailure(const QString& what, const Diagnostics& diagnostics)
{
    statusBar()->showMessage(what + " " + tr("(details in the build log)"), 15000);
    showError(tr("Write failed"), what + "\n\n" + QString::fromStdString(formatAll(diagnostics)));
}

void MainWindow::showError(const QString& title, const QString& text)
{
    if (m_errorPrompt)
        m_errorPrompt(title, text);
}

void MainWindow::reloadTemplates()
{
    const Diagnostics diagnostics = m_session.reloadTemplates();
    const auto& t = m_session.templates();
    report(tr("Reloaded %1 templates and %2 shapes").arg(t.all().size()).arg(t.shapes().size()), diagnostics);
}

bool MainWindow::openFile(const QString& path)
{
    Diagnostics diagnostics, notes;
    const QString autosave = EditorSession::autosavePathFor(path);
    const auto recovery = EditorSession::recoveryState(path);
    if (recovery == EditorSession::Recovery::NothingNewer)
        QFile::remove(autosave); // the file has all it holds
    if (recovery == EditorSession::Recovery::OtherVersion)
        notes.push_back(makeWarning({autosave.toStdString(), 0, 0},
                                    "an autosave made from another version of this file is kept here, not offered "
                                    "(the file was saved since it was made)"));
    if (recovery == EditorSession::Recovery::Offer && m_recoveryPrompt(path, autosave)) {
        const bool recovered = m_session.recover(path, diagnostics);
        report(recovered ? tr("Recovered unsaved changes of %1").arg(path) : tr("Could not recover %1").arg(path),
               diagnostics);
        if (recovered) {
            settings::addRecentFile(path);
            updateTitle();
            m_viewport->frameAll();
            return true;
        }
    }
    const bool ok = m_session.open(path, diagnostics);
    diagnostics.insert(diagnostics.begin(), notes.begin(), notes.end());
    report(ok ? tr("Opened %1").arg(path) : tr("Could not open %1; the open guide is unchanged").arg(path), diagnostics);
    if (!ok) // the first errors, file:line:column, where the rigger looks (the log keeps them all)
        showError(tr("Could not open the guide"),
                  tr("Could not open %1; the open guide is unchanged.\n\n%2")
                      .arg(path, QString::fromStdString(formatAll(errorsOf(diagnostics, 8)))));
    if (ok) {
        settings::addRecentFile(path);
        updateTitle();
        m_viewport->frameAll();
    }
    return ok;
}

bool MainWindow::newFromSample(const QString& samplePath)
{
    Diagnostics diagnostics;
    const bool ok = m_session.newDocument(samplePath, diagnostics);
    const QString what = samplePath.isEmpty() ? tr("an empty guide") : tr("the %1 sample").arg(QFileInfo(samplePath).completeBaseName());
    report(ok ? tr("New guide from %1").arg(what) : tr("Could not start from %1; the open guide is unchanged").arg(what), diagnostics);
    if (ok) {
        updateTitle();
        m_viewport->frameAll();
    }
    return ok;
}

bool MainWindow::closeDocument()
{
    if (!maySwitchDocument(tr("Save the guide before closing it?")))
        return false;
    return newFromSample(QString());
}

bool MainWindow::saveFile(const QString& path)
{
    Diagnostics diagnostics;
    // The guide's name follows its file while it is untitled or named after its old file.
    const std::string& name = m_session.document().name;
    if (name.empty() || name == "untitled" || name == QFileInfo(m_session.filePath()).completeBaseName().toStdString())
        m_session.setDocumentName(QFileInfo(path).completeBaseName().toStdString());
    const bool ok = m_session.save(path, diagnostics);
    if (ok)
        settings::addRecentFile(path);
    report(ok ? tr("Saved %1").arg(path) : tr("Could not save %1").arg(path), diagnostics);
    if (!ok)
        showWriteFailure(tr("Could not save %1; the file on disk is unchanged.").arg(path), diagnostics);
    updateTitle();
    return ok;
}

bool MainWindow::maySwitchDocument(const QString& question)
{
    if (m_session.history().isClean() || !isVisible() || property("skipUnsavedPrompt").toBool())
        return true;
    const auto answer = QMessageBox::question(this, tr("Unsaved changes"), question,
                                              QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Cancel)
        return false;
    if (answer == QMessageBox::Save)
        action("save")->trigger();
    return answer == QMessageBox::Discard || m_session.history().isClean();
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!maySwitchDocument(tr("Save the guide before closing?"))) {
        event->ignore();
        return;
    }
    settings::saveWindow(*this);
    m_session.discardAutosave(); // a clean close: saved, or the changes were discarded
    event->accept();
}

} // namespace rs::app
