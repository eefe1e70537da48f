// The character: Guide > Add / Remove Model, the Skin menu (Bind on a worker
// thread with progress and Cancel, the bind method and influence limit), and
// the model files watched so a changed file is offered for reloading.
#include "MainWindow.h"

#include "ActionKit.h"

#include "LogPanel.h"
#include "skin/BindModels.h"

#include <QActionGroup>
#include <QFileDialog>
#include <QFileInfo>
#include <QFileSystemWatcher>
#include <QGuiApplication>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressDialog>
#include <QStatusBar>
#include <QThread>
#include <QTimer>

#include <atomic>
#include <optional>

namespace rs::app {

// A bind in flight: what it binds (shared, immutable models; a copy of the
// bones), its progress and cancel flag (shared with the worker), its result.
struct MainWindow::BindJob {
    std::vector<skin::ModelToBind> models;
    std::vector<skin::SkinBone> bones;
    skin::BindOptions options;
    std::atomic<bool> cancel{false};
    std::atomic<double> fraction{0.0};
    std::optional<Result<std::vector<model::MeshBinding>>> result;
    std::vector<skin::MeshBindReport> reports;
    QThread* thread = nullptr;
    QProgressDialog* dialog = nullptr;
    QTimer* poll = nullptr;
    QElapsedTimer clock;
    ~BindJob()
    {
        cancel = true;
        if (thread) {
            thread->wait();
            delete thread;
        }
    }
};

void MainWindow::createSkinActions()
{
    QMenu* guide = findChild<QMenu*>("guideMenu");
    QAction* add = makeAction(this, "addModel", tr("Add &Model..."), QKeySequence(tr("Ctrl+Shift+I")));
    add->setToolTip(tr("Add a character model (FBX, OBJ, glTF, Collada...) to bind to the rig"));
    connect(add, &QAction::triggered, this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Add model"), QFileInfo(m_session.filePath()).absolutePath(),
            tr("Models (*.fbx *.obj *.gltf *.glb *.dae *.zae *.blend *.ply *.stl *.x *.3ds);;All files (*)"));
        if (!path.isEmpty())
            addModel(path);
    });
    QMenu* remove = new QMenu(tr("Re&move Model"), this);
    remove->setObjectName("removeModelMenu");
    connect(remove, &QMenu::aboutToShow, this, [this, remove] {
        remove->clear();
        for (const std::string& path : m_session.document().models)
            remove->addAction(QString::fromStdString(path), this, [this, path] { logStatus(m_session.removeModel(path)); });
        if (m_session.document().models.empty())
            remove->addAction(tr("The guide has no model"))->setEnabled(false);
    });
    if (guide) {
        guide->addSeparator();
        guide->addAction(add);
        guide->addMenu(remove);
    }

    QMenu* skinMenu = menuBar()->addMenu(tr("&Skin"));
    skinMenu->setObjectName("skinMenu");
    QAction* bind = makeAction(this, "bindSkin", tr("&Bind"), QKeySequence(tr("Ctrl+Shift+B")));
    bind->setToolTip(tr("Bind the guide's models to the rig's skin joints with automatic weights (the rig is built first)"));
    connect(bind, &QAction::triggered, this, &MainWindow::bindSkin);
    skinMenu->addAction(bind);
    skinMenu->addSeparator();
    QMenu* method = skinMenu->addMenu(tr("Bind &Method"));
    auto* methods = new QActionGroup(this);
    const std::pair<const char*, QString> methodNames[] = {
        {"heat", tr("&Heat (surface diffusion, default)")}, {"envelope", tr("&Envelope (nearest bones)")}, {"closest", tr("&Closest bone")}};
    for (const auto& [name, text] : methodNames) {
        QAction* a = makeAction(this, QString("bindMethod:") + name, text, {});
        a->setCheckable(true);
        a->setChecked(std::string(name) == "heat");
        methods->addAction(a);
        method->addAction(a);
    }
    QMenu* limit = skinMenu->addMenu(tr("Max &Influences"));
    auto* limits = new QActionGroup(this);
    for (int n = 1; n <= 8; ++n) {
        QAction* a = makeAction(this, QString("maxInfluences:%1").arg(n), QString::number(n), {});
        a->setCheckable(true);
        a->setChecked(n == 4);
        limits->addAction(a);
        limit->addAction(a);
    }
    skinMenu->addSeparator();
    QAction* reload = makeAction(this, "reloadModels", tr("&Reload Models"), {});
    reload->setToolTip(tr("Read the guide's model files again (after changing them in another program)"));
    connect(reload, &QAction::triggered, this, [this] {
        for (const std::string& path : m_session.document().models) {
            const Status reloaded = m_session.reloadModel(path);
            report(reloaded.ok() ? tr("Reloaded %1").arg(QString::fromStdString(path))
                                 : tr("Could not reload %1; the model as it was stays").arg(QString::fromStdString(path)),
                   reloaded.diagnostics());
        }
    });
    skinMenu->addAction(reload);
    createPaintActions(skinMenu);
    createSkinChunkActions(skinMenu);

    m_modelWatcher = new QFileSystemWatcher(this);
    connect(m_modelWatcher, &QFileSystemWatcher::fileChanged, this, [this](const QString& path) {
        // Editors save by writing a new file and renaming it over the old one:
        // wait until it settles, then watch the new file.
        QTimer::singleShot(300, this, [this, path] { modelFileChanged(path); });
    });
    connect(&m_session, &EditorSession::changed, this, [this](const edit::Change& change) {
        if (change.hasAny(edit::ChangeKind::Models | edit::ChangeKind::Document))
            watchModels();
    });
    watchModels();
}

bool MainWindow::addModel(const QString& path)
{
    QGuiApplication::setOverrideCursor(Qt::WaitCursor);
    const Status added = m_session.addModel(path.toStdString());
    QGuiApplication::restoreOverrideCursor();
    std::size_t vertices = 0, meshes = 0;
    if (added.ok() && !m_session.models().empty())
        if (const auto& model = m_session.models().back().model) {
            meshes = model->meshes.size();
            for (const auto& mesh : model->meshes)
                vertices += mesh.vertexCount();
        }
    report(added.ok() ? tr("Added model %1: %2 meshes, %3 vertices; Skin > Bind binds it to the rig").arg(path).arg(meshes).arg(vertices)
                      : tr("Could not add the model %1").arg(path),
           added.diagnostics());
    return added.ok();
}

void MainWindow::bindSkin()
{
    if (m_bind)
        return; // one bind at a time
    if (m_session.document().models.empty()) {
        logStatus(Status::refused(tr("the guide has no model to bind: Guide > Add Model first").toStdString()));
        return;
    }
    if (!m_session.rig() || m_session.isRigStale())
        buildRig();
    if (m_session.skinBones().empty()) {
        logStatus(Status::refused(tr("the rig has no skin joints to bind to").toStdString()));
        return;
    }
    auto job = std::make_shared<BindJob>();
    for (const session::LoadedModel& m : m_session.models())
        if (m.model)
            job->models.push_back({m.path, m.model});
    job->bones = m_session.skinBones();
    for (const char* name : {"heat", "envelope", "closest"})
        if (QAction* a = action(QString("bindMethod:") + name); a && a->isChecked())
            job->options.method = *skin::parseBindMethod(name);
    for (int n = 1; n <= 8; ++n)
        if (QAction* a = action(QString("maxInfluences:%1").arg(n)); a && a->isChecked())
            job->options.maxInfluences = n;
    BindJob* raw = job.get();
    job->options.progress = [raw](double fraction) {
        raw->fraction = fraction;
        return !raw->cancel.load();
    };
    m_bind = job;
    if (QAction* a = action("bindSkin"))
        a->setEnabled(false);

    job->dialog = new QProgressDialog(tr("Binding the character to %1 skin joints...").arg(job->bones.size()), tr("Cancel"), 0, 1000, this);
    job->dialog->setObjectName("bindProgress");
    job->dialog->setWindowTitle(tr("Bind"));
    job->dialog->setWindowModality(Qt::WindowModal); // the window repaints and Cancel answers; edits wait for the bind
    job->dialog->setMinimumDuration(300);
    job->dialog->setAutoClose(false);
    job->dialog->setAutoReset(false);
    job->dialog->setValue(0);
    connect(job->dialog, &QProgressDialog::canceled, this, &MainWindow::cancelBind);
    job->poll = new QTimer(job->dialog);
    connect(job->poll, &QTimer::timeout, this, [this] {
        if (m_bind && m_bind->dialog)
            m_bind->dialog->setValue(int(m_bind->fraction.load() * 1000.0));
    });
    job->poll->start(50);
    job->clock.start();
    statusBar()->showMessage(tr("Binding... (Skin > Bind; Cancel keeps the previous weights)"));

    job->thread = QThread::create([raw] {
        std::vector<skin::MeshBindReport> reports;
        auto result = skin::bindModels(raw->models, raw->bones, raw->options, &reports);
        raw->reports = std::move(reports);
        raw->result.emplace(std::move(result));
    });
    job->thread->setObjectName("rigsmith-bind");
    connect(job->thread, &QThread::finished, this, &MainWindow::finishBind, Qt::QueuedConnection);
    job->thread->start(QThread::LowPriority);
}

void MainWindow::cancelBind()
{
    if (m_bind)
        m_bind->cancel = true;
}

void MainWindow::finishBind()
{
    if (!m_bind)
        return;
    std::shared_ptr<BindJob> job = std::move(m_bind);
    job->thread->wait();
    const double seconds = job->clock.elapsed() / 1000.0;
    if (job->dialog) {
        job->poll->stop();
        job->dialog->hide();
        job->dialog->deleteLater();
    }
    if (QAction* a = action("bindSkin"))
        a->setEnabled(true);
    auto& result = *job->result;
    if (!result || job->cancel) {
        const bool cancelled = job->cancel;
        report(cancelled ? tr("Bind cancelled; the previous weights are kept") : tr("Bind failed; the previous weights are kept"),
               cancelled ? Diagnostics{} : result.diagnostics());
        statusBar()->showMessage(cancelled ? tr("Bind cancelled") : tr("Bind failed (details in the build log)"), 8000);
        return;
    }
    Diagnostics notes = result.takeDiagnostics();
    std::size_t vertices = 0, fallback = 0;
    for (const skin::MeshBindReport& r : job->reports) {
        vertices += r.stats.vertices;
        fallback += r.stats.verticesByClosestBone;
        Diagnostic d = makeWarning({r.model, 0, 0}, "");
        d.severity = Severity::Note;
        d.subject = Subject::ofMesh(r.mesh);
        d.message = "mesh '" + r.mesh + "': " + std::to_string(r.stats.vertices) + " vertices (" + std::to_string(r.stats.surfaceVertices) +
                    " welded, " + std::to_string(r.stats.parts) + (r.stats.parts == 1 ? " part" : " parts") + ") bound in " +
                    std::to_string(int(r.milliseconds)) + " ms; " + std::to_string(r.stats.verticesByClosestBone) +
                    " vertices by their closest bone";
        notes.push_back(std::move(d));
    }
    const Status set = m_session.setBindings(result.take(), tr("Bind skin").toStdString());
    notes.insert(notes.end(), set.diagnostics().begin(), set.diagnostics().end());
    report(set.ok() ? tr("Bound %1 vertices to %2 skin joints by %3 in %4 s")
                          .arg(vertices)
                          .arg(job->bones.size())
                          .arg(skin::bindMethodName(job->options.method))
                          .arg(seconds, 0, 'f', 2)
                    : tr("The bind could not be applied; the previous weights are kept"),
           notes);
    statusBar()->showMessage(set.ok() ? tr("Bound in %1 s (%2 vertices by their closest bone)").arg(seconds, 0, 'f', 2).arg(fallback)
                                      : tr("Bind not applied (details in the build log)"),
                             8000);
}

void MainWindow::watchModels()
{
    if (!m_modelWatcher)
        return;
    if (!m_modelWatcher->files().isEmpty())
        m_modelWatcher->removePaths(m_modelWatcher->files());
    QStringList paths;
    for (const std::string& path : m_session.document().models)
        if (QFileInfo::exists(QString::fromStdString(path)))
            paths.push_back(QString::fromStdString(path));
    if (!paths.isEmpty())
        m_modelWatcher->addPaths(paths);
}

void MainWindow::modelFileChanged(const QString& path)
{
    const auto& models = m_session.document().models;
    if (std::find(models.begin(), models.end(), path.toStdString()) == models.end())
        return;
    if (QFileInfo::exists(path) && !m_modelWatcher->files().contains(path))
        m_modelWatcher->addPath(path); // replaced by a rename: watch the new file
    if (!QFileInfo::exists(path)) {
        report(tr("The model file %1 is gone; the guide keeps it and its weights").arg(path), {});
        return;
    }
    if (m_modelsAsked.contains(path))
        return; // a question about it is open
    m_modelsAsked.push_back(path);
    bool reload = false;
    if (m_reloadPrompt)
        reload = m_reloadPrompt(path);
    else if (isVisible())
        reload = QMessageBox::question(this, tr("Model changed"),
                                       tr("%1 changed on disk. Read it again?\n\nWeights bound to a mesh whose vertices changed are re-fitted "
                                          "from the mesh as it was bound (one undo step).")
                                           .arg(QFileInfo(path).fileName())) == QMessageBox::Yes;
    m_modelsAsked.removeAll(path);
    if (!reload) {
        report(tr("%1 changed on disk; Skin > Reload Models reads it again").arg(path), {});
        return;
    }
    const Status reloaded = m_session.reloadModel(path.toStdString());
    report(reloaded.ok() ? tr("Reloaded %1").arg(path) : tr("Could not reload %1; the model as it was stays").arg(path), reloaded.diagnostics());
}

} // namespace rs::app
