#include "EditorSession.h"

#include "io/ExportRequest.h"
#include "io/GuideFile.h"
#include "io/ModelImport.h"
#include "io/WeightsFile.h"
#include "io/TemplateFolders.h"
#include "templates/GuideTemplates.h"

#include <filesystem>

namespace rs::app {

namespace {

std::shared_ptr<const templates::TemplateRegistry> loadTemplates(Diagnostics& diagnostics)
{
    return io::loadDefaultTemplates(diagnostics);
}

} // namespace

EditorSession::EditorSession(QObject* parent) : QObject(parent), session::Session(nullptr)
{
    qRegisterMetaType<rs::Diagnostics>();
    qRegisterMetaType<rs::edit::Change>();
    setTemplates(loadTemplates(m_templateDiagnostics));
    setReporter([this](const Diagnostics& diagnostics) { emit diagnosticsReported(diagnostics); });
    setModelLoader([](const std::string& path) { return io::importModel(path); });
    setBuildProgress([this](double fraction, const std::string& stage) {
        emit buildProgressed(fraction, QString::fromStdString(stage));
    });
    subscribe([this](const session::Change& change) {
        if (change.has(session::ChangeKind::History) && history().isClean())
            discardAutosave(); // undone back to the saved state: the autosave would bring the undone edits back
        emit changed(change);
    });
}

EditorSession::~EditorSession() = default;

bool EditorSession::open(const QString& path, Diagnostics& diagnostics)
{
    auto loaded = io::readGuideFile(path.toStdString());
    diagnostics = loaded.takeDiagnostics();
    if (!loaded)
        return false;
    model::GuideDocument guide = loaded.take();
    // A damaged weights file is reported and left alone (a save writes weights only once some are bound).
    const Status weights = io::loadGuideWeights(path.toStdString(), guide);
    diagnostics.insert(diagnostics.end(), weights.diagnostics().begin(), weights.diagnostics().end());
    loadSavedChunks(path, diagnostics);
    replaceWith(std::move(guide), path);
    const Diagnostics unknown = templates::checkGuideTemplates(document(), templates(), path.toStdString());
    diagnostics.insert(diagnostics.end(), unknown.begin(), unknown.end());
    return true;
}

void EditorSession::replaceWith(model::GuideDocument document, const QString& path)
{
    if (history().isClean())
        discardAutosave(); // the guide as saved: its autosave holds nothing newer
    m_ownsAutosave = false; // the previous guide's unsaved autosave stays to be offered when it is opened again
    m_filePath = path;
    m_baseHash = contentHash(path);
    replaceDocument(std::move(document)); // re-fits changed meshes as an undo step
    const bool refitted = history().size() > 0;
    history().setClean();
    if (refitted)
        history().setModified(); // re-fitted weights are not on disk yet
}

void EditorSession::loadSavedChunks(const QString& guidePath, Diagnostics& diagnostics)
{
    if (guidePath.isEmpty()) {
        setSavedChunks({});
        return;
    }
    // A damaged chunk file is reported; a changed mesh is then kept, not re-fitted.
    auto chunks = io::loadGuideChunks(guidePath.toStdString());
    diagnostics.insert(diagnostics.end(), chunks.diagnostics().begin(), chunks.diagnostics().end());
    setSavedChunks(chunks ? chunks.take() : std::vector<skin::SkinChunk>{});
}

bool EditorSession::newDocument(const QString& templatePath, Diagnostics& diagnostics)
{
    model::GuideDocument document;
    document.name = "untitled";
    if (!templatePath.isEmpty()) {
        auto loaded = io::readGuideFile(templatePath.toStdString());
        diagnostics = loaded.takeDiagnostics();
        if (!loaded)
            return false;
        document = loaded.take();
    }
    setSavedChunks({});
    replaceWith(std::move(document), QString());
    const Diagnostics unknown = templates::checkGuideTemplates(this->document(), templates(), templatePath.toStdString());
    diagnostics.insert(diagnostics.end(), unknown.begin(), unknown.end());
    return true;
}

bool EditorSession::save(const QString& path, Diagnostics& diagnostics)
{
    const Status saved = io::saveGuideFile(document(), path.toStdString());
    diagnostics = saved.diagnostics();
    if (saved.failed())
        return false;
    const Status weights = io::saveGuideWeights(document(), path.toStdString());
    diagnostics.insert(diagnostics.end(), weights.diagnostics().begin(), weights.diagnostics().end());
    if (weights.failed())
        return false; // the guide is saved, its weights are not: the document stays unsaved
    // The bound meshes as they are, to re-fit from when a model changes later.
    const Status chunks = io::saveGuideChunks(bindingChunks(), path.toStdString());
    diagnostics.insert(diagnostics.end(), chunks.diagnostics().begin(), chunks.diagnostics().end());
    if (chunks.failed())
        return false;
    discardAutosave(); // the previous path's (or the untitled one's)
    m_filePath = path;
    m_baseHash = contentHash(path);
    history().setClean();
    m_ownsAutosave = false;
    return true;
}

Diagnostics EditorSession::reloadTemplates()
{
    setTemplates(loadTemplates(m_templateDiagnostics));
    return m_templateDiagnostics;
}

Diagnostics EditorSession::exportRig(const io::ExportRequest& request, std::function<bool(double)> progress) const
{
    if (!rig())
        return {makeError({request.path, 0, 0}, "build the rig before exporting it")};
    io::ExportCharacter character{document().bindings, {}}; // the guide's models' meshes, bound
    for (const session::LoadedModel& m : models())
        character.models.push_back({m.path, m.model.get()});
    return io::runExport(document(), *rig(), model::testPose(document().overrides), request, std::move(progress), character.models.empty() ? nullptr : &character);
}

model::InstanceId EditorSession::instanceNamed(const QString& name) const
{
    const auto* instance = document().instanceNamed(name.toStdString());
    return instance ? instance->id : model::kNoId;
}

} // namespace rs::app
