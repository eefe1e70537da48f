// MainWindow's skin chunks: Skin > Skin Chunks (the dock), export of the
// dock's scope (the selected joints: those built from the selected guide
// joints, or the selected instance's), import and preview on a worker thread with progress and
// Cancel (as Skin > Bind), and the chunk file inspector. The session does the
// work (session/SkinChunkJob.h): an import is one undo step; a preview
// selects the vertices of the route the dock names, so the viewport's
// vertex-selection display shows which vertices each step would take.
#include "MainWindow.h"

#include "ActionKit.h"

#include "LogPanel.h"
#include "SkinChunkPanel.h"
#include "SkinInfluenceBox.h"
#include "io/InfluenceNameMap.h"
#include "io/SkinChunkInfo.h"
#include "io/SkinChunks.h"

#include <QCoreApplication>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QProgressDialog>
#include <QStatusBar>
#include <QThread>
#include <QTimer>

#include <algorithm>
#include <atomic>
#include <chrono>

namespace rs::app {

// An import in flight: the session's job (owning what it reads), its
// progress and cancel flag (shared with the worker) and whether it only previews.
struct MainWindow::ChunkImportJob {
    session::SkinImportJob job;
    bool preview = false;
    std::atomic<bool> cancel{false};
    std::atomic<double> fraction{0.0};
    Status result;
    QThread* thread = nullptr;
    QProgressDialog* dialog = nullptr;
    ~ChunkImportJob()
    {
        cancel = true;
        if (thread) {
            thread->wait();
            delete thread;
        }
    }
};

void MainWindow::createSkinChunkActions(QMenu* skinMenu)
{
    QAction* chunks = makeAction(this, "skinChunks", tr("Skin &Chunks..."), {});
    chunks->setCheckable(true);
    chunks->setToolTip(tr("The Skin Chunks dock: export and import weights as skin chunk files, preview an import, inspect a file"));
    connect(chunks, &QAction::toggled, this, [this](bool on) {
        if (auto* dock = findChild<QDockWidget*>("skinChunkDock")) {
            dock->setVisible(on);
            if (on)
                dock->raise();
        }
    });
    skinMenu->addSeparator();
    skinMenu->addAction(chunks);
}

void MainWindow::createSkinChunkDock()
{
    m_chunkPanel = new widgets::SkinChunkPanel(this);
    m_chunkPanel->setObjectName("skinChunkPanel");
    QDockWidget* dock = addDock(m_chunkPanel, tr("Skin Chunks"), "skinChunkDock", Qt::RightDockWidgetArea);
    dock->hide();
    connect(dock, &QDockWidget::visibilityChanged, this, [this, dock] {
        if (QAction* a = action("skinChunks"))
            a->setChecked(!dock->isHidden()); // closed with its title bar's button: the menu item follows
    });
    connect(m_chunkPanel, &widgets::SkinChunkPanel::exportRequested, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export skin chunks"), QFileInfo(m_session.filePath()).absolutePath(),
                                                          tr("Skin chunks (*.rschunks)"));
        if (!path.isEmpty())
            exportSkinChunks(path.endsWith(".rschunks") ? path : path + ".rschunks");
    });
    connect(m_chunkPanel, &widgets::SkinChunkPanel::importRequested, this,
            [this](bool preview) { importSkinChunks(m_chunkPanel->importFiles(), preview); });
    connect(m_chunkPanel, &widgets::SkinChunkPanel::inspectRequested, this, &MainWindow::inspectSkinChunks);
}

namespace {

// The skin joints of the selection: those built from the selected guide
// joints, or, when none is selected, every skin joint of the selected instance.
std::vector<NodeKey> selectedSkinJoints(const session::Session& s)
{
    std::vector<NodeKey> keys;
    const session::Selection& selection = s.selection();
    if (!s.rig())
        return keys;
    for (const skin::SkinBone& bone : s.skinBones()) {
        const model::RigNode& node = s.rig()->nodes[bone.node];
        const bool picked = selection.joints.empty()
                                ? selection.instance != model::kNoId && node.owner == selection.instance
                                : std::find(selection.joints.begin(), selection.joints.end(), node.guide) != selection.joints.end();
        if (picked)
            keys.push_back(bone.key);
    }
    return keys;
}

session::SkinScope exportScopeOf(widgets::SkinChunkPanel::ExportScope scope, const session::Session& s)
{
    switch (scope) {
    case widgets::SkinChunkPanel::ExportScope::Character:
        return session::SkinScope::all();
    case widgets::SkinChunkPanel::ExportScope::SelectedMeshes: {
        std::vector<std::size_t> meshes;
        for (const auto& [mesh, vertices] : s.selectedVertices())
            if (!vertices.empty())
                meshes.push_back(mesh);
        return session::SkinScope::ofMeshes(std::move(meshes));
    }
    case widgets::SkinChunkPanel::ExportScope::SelectedJoints:
        return session::SkinScope::ofJoints(selectedSkinJoints(s));
    case widgets::SkinChunkPanel::ExportScope::SelectedVertices:
        break;
    }
    return session::SkinScope::selectedVertices();
}

std::int64_t nowMicroseconds()
{
    return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
}

} // namespace

bool MainWindow::exportSkinChunks(const QString& path)
{
    const session::SkinScope scope = exportScopeOf(m_chunkPanel->exportScope(), m_session);
    if (scope.kind == session::SkinScope::Kind::Meshes && scope.meshes.empty()) {
        logStatus(Status::refused(tr("no mesh has selected vertices: select some, or export the whole character").toStdString()));
        return false;
    }
    if (!m_session.rig() || m_session.isRigStale())
        buildRig();
    skin::ChunkExportOptions stamp;
    stamp.tool = "rigsmith " + QCoreApplication::applicationVersion().toStdString();
    stamp.user = qEnvironmentVariable("USER").toStdString();
    stamp.exportedAtMicroseconds = nowMicroseconds();
    auto chunks = m_session.exportSkinChunks(scope, stamp);
    if (!chunks) {
        report(tr("Nothing exported to %1").arg(path), chunks.diagnostics());
        return false;
    }
    const Status saved = io::saveSkinChunkFile(path.toStdString(), *chunks);
    std::size_t vertices = 0;
    for (const skin::SkinChunk& c : *chunks)
        vertices += c.vertexCount();
    report(saved.ok() ? tr("Exported %1 skin chunks (%2 vertices) to %3").arg(chunks->size()).arg(vertices).arg(path)
                      : tr("Could not write %1").arg(path),
           saved.diagnostics());
    return saved.ok();
}

void MainWindow::inspectSkinChunks(const QString& file)
{
    auto chunks = io::loadSkinChunkFile(file.toStdString());
    if (!chunks) {
        m_chunkPanel->showInspection(QString::fromStdString(formatAll(chunks.diagnostics())));
        return;
    }
    m_chunkPanel->showInspection(QString::fromStdString(io::describeSkinChunks(file.toStdString(), *chunks, std::size_t(m_chunkPanel->inspectFrom()),
                                                                               std::size_t(m_chunkPanel->inspectLimit()))),
                                 file);
}

void MainWindow::importSkinChunks(const QStringList& files, bool preview)
{
    if (m_chunkImport || m_bind)
        return; // one at a time
    std::vector<skin::SkinChunk> all;
    for (const QString& file : files) {
        auto chunks = io::loadSkinChunkFile(file.toStdString());
        if (!chunks) {
            report(tr("Could not read %1; nothing imported").arg(file), chunks.diagnostics());
            return;
        }
        for (skin::SkinChunk& c : *chunks)
            all.push_back(std::move(c));
    }
    widgets::SkinInfluenceBox* box = m_chunkPanel->influences();
    box->clearResults();
    skin::InfluenceMapOptions influences;
    influences.missing = box->missing();
    if (!box->nameMapFile().isEmpty()) {
        auto names = io::readInfluenceNameMap(box->nameMapFile().toStdString());
        if (!names) {
            report(tr("Could not read the name map %1; nothing imported").arg(box->nameMapFile()), names.diagnostics());
            return;
        }
        influences.names = names.take();
    }
    if (!m_session.rig() || m_session.isRigStale())
        buildRig(); // the chunks' influences land on the rig's skin joints
    const auto missing = influences.missing == skin::MissingInfluences::Create ? std::vector<skin::InfluenceMatch>{}
                                                                               : m_session.missingInfluences(all, influences);
    const bool onSelection = m_chunkPanel->importOntoSelection();
    auto prepared = m_session.prepareSkinImport(std::move(all), m_chunkPanel->options(),
                                                onSelection ? session::SkinScope::selectedVertices() : session::SkinScope::all(), influences);
    if (!prepared) {
        box->showMissing(missing);
        report(missing.empty() ? tr("Nothing imported")
                               : tr("Nothing imported: %1 influences are no skin joint of the rig (listed in the Skin Chunks dock)").arg(missing.size()),
               prepared.diagnostics());
        return;
    }
    box->showMoved(prepared->influences.matches);
    auto job = std::make_shared<ChunkImportJob>();
    job->job = prepared.take();
    job->job.append = m_chunkPanel->appendImport();
    job->preview = preview;
    ChunkImportJob* raw = job.get();
    job->job.options.progress = [raw](double fraction) {
        raw->fraction = fraction;
        return !raw->cancel.load();
    };
    m_chunkImport = job;
    job->dialog = new QProgressDialog(preview ? tr("Previewing the import...") : tr("Importing skin weights..."), tr("Cancel"), 0, 1000, this);
    job->dialog->setObjectName("chunkImportProgress");
    job->dialog->setWindowTitle(tr("Import skin chunks"));
    job->dialog->setWindowModality(Qt::WindowModal);
    job->dialog->setMinimumDuration(300);
    job->dialog->setAutoClose(false);
    job->dialog->setAutoReset(false);
    connect(job->dialog, &QProgressDialog::canceled, this, &MainWindow::cancelChunkImport);
    auto* poll = new QTimer(job->dialog);
    connect(poll, &QTimer::timeout, this, [this] {
        if (m_chunkImport && m_chunkImport->dialog)
            m_chunkImport->dialog->setValue(int(m_chunkImport->fraction.load() * 1000.0));
    });
    poll->start(50);
    job->thread = QThread::create([raw] { raw->result = raw->job.run(); });
    job->thread->setObjectName("rigsmith-chunk-import");
    connect(job->thread, &QThread::finished, this, &MainWindow::finishChunkImport, Qt::QueuedConnection);
    job->thread->start(QThread::LowPriority);
}

void MainWindow::cancelChunkImport()
{
    if (m_chunkImport)
        m_chunkImport->cancel = true;
}

void MainWindow::finishChunkImport()
{
    if (!m_chunkImport)
        return;
    std::shared_ptr<ChunkImportJob> job = std::move(m_chunkImport);
    job->thread->wait();
    if (job->dialog) {
        job->dialog->hide();
        job->dialog->deleteLater();
    }
    if (job->cancel || job->result.failed()) {
        report(job->cancel ? tr("Import cancelled; nothing changed") : tr("Import failed; nothing changed"),
               job->cancel ? Diagnostics{} : job->result.diagnostics());
        return;
    }
    std::vector<std::pair<std::size_t, std::vector<session::VertexRoute>>> routes; // the steps each vertex took
    for (std::size_t t = 0; t < job->job.targets.size(); ++t)
        if (job->job.targets[t].vertices.empty()) // a whole mesh (onto selected vertices, the others keep theirs)
            routes.emplace_back(job->job.targets[t].characterMesh, job->job.routes(t));
    if (job->preview) {
        for (auto& [mesh, steps] : routes)
            setRoutes(mesh, std::move(steps));
        refreshScene();
        const bool oneToOne = m_chunkPanel->previewSelects() == widgets::SkinChunkPanel::PreviewSelects::OneToOne;
        m_session.clearVertexSelection();
        std::size_t selected = 0;
        for (std::size_t t = 0; t < job->job.targets.size(); ++t) {
            const auto routes = job->job.routes(t);
            const auto& only = job->job.targets[t].vertices; // an import onto selected vertices previews within them
            std::vector<std::uint32_t> vertices;
            for (std::uint32_t v = 0; v < routes.size(); ++v)
                if ((routes[v] == session::VertexRoute::OneToOne) == oneToOne &&
                    (only.empty() || std::binary_search(only.begin(), only.end(), v)))
                    vertices.push_back(v);
            selected += vertices.size();
            if (!vertices.empty())
                m_session.selectVertices(job->job.targets[t].characterMesh, std::move(vertices), true);
        }
        m_chunkPanel->showReports(job->job.reports, true);
        report(tr("Import preview: %1 vertices %2 selected; nothing changed%3")
                   .arg(selected)
                   .arg(oneToOne ? tr("loaded 1:1") : tr("not loaded 1:1 (transferred or single influence)"))
                   .arg(isPainting() ? QString() : tr(" (Skin > Paint Weights shows the selected vertices)")),
               job->job.notes);
        return;
    }
    auto applied = m_session.applySkinImport(std::move(job->job), tr("Import skin weights").toStdString());
    if (!applied) {
        report(tr("The import could not be applied; nothing changed"), applied.diagnostics());
        return;
    }
    for (auto& [mesh, steps] : routes)
        setRoutes(mesh, std::move(steps));
    refreshScene();
    m_chunkPanel->showReports(*applied, false);
    report(tr("Imported skin weights onto %1 meshes (Edit > Undo takes them back)").arg(applied->size()), applied.diagnostics());
}

} // namespace rs::app
