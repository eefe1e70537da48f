#include "EditorSession.h"

#include "rigging/RigBuilder.h"
#include "edit/GuideEdits.h"
#include "io/ExportRequest.h"
#include "io/GuideFile.h"

#include <chrono>

namespace rs::app {

namespace {

// The guide without its test pose: what a build depends on.
bool sameGuide(const model::GuideDocument& a, const model::GuideDocument& b)
{
    return a.name == b.name && a.naming == b.naming && a.instances() == b.instances();
}

// Only shape edits differ: a rebuild cannot fail or move anything else.
bool differsOnlyInShapes(const model::GuideDocument& a, const model::GuideDocument& b)
{
    if (!(a.name == b.name && a.naming == b.naming && a.instances().size() == b.instances().size()))
        return false;
    for (std::size_t i = 0; i < a.instances().size(); ++i) {
        model::TemplateInstance x = a.instances()[i], y = b.instances()[i];
        x.shapes.clear();
        y.shapes.clear();
        if (!(x == y))
            return false;
    }
    return true;
}

} // namespace

EditorSession::EditorSession(QObject* parent) : QObject(parent)
{
    qRegisterMetaType<rs::Diagnostics>();
    m_templates = templates::TemplateRegistry::loadDefault(m_templateDiagnostics);
    m_history.addListener([this] {
        m_rigStale = m_rig.has_value() && !sameGuide(m_document, m_builtFrom); // posing does not age the rig
        if (m_selection.instance != model::kNoId && !m_document.instance(m_selection.instance))
            m_selection = {};
        if (m_rigStale && differsOnlyInShapes(m_document, m_builtFrom))
            build(); // a shape edit (or its undo) shows at once, on both sides of mirrored branches
        syncReference();
        emit documentChanged();
        poseFromDocument();
    });
}

EditorSession::~EditorSession() = default;

bool EditorSession::open(const QString& path, Diagnostics& diagnostics)
{
    auto loaded = io::readGuideFile(path.toStdString());
    diagnostics = loaded.takeDiagnostics();
    if (!loaded)
        return false;
    replaceDocument(loaded.take(), path);
    return true;
}

void EditorSession::replaceDocument(model::GuideDocument document, const QString& path)
{
    m_ownsAutosave = false; // the previous guide's autosave stays to be offered when it is opened again
    m_filePath = path;
    m_selection = {};
    m_rig.reset();
    m_rigStale = false;
    compileRig();
    setMode(EditorMode::Guide);
    m_history.reset(std::move(document));
    m_history.setClean();
    emit rigChanged();
    emit selectionChanged();
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
    replaceDocument(std::move(document), QString());
    return true;
}

bool EditorSession::save(const QString& path, Diagnostics& diagnostics)
{
    diagnostics = io::saveGuideFile(m_document, path.toStdString());
    if (hasErrors(diagnostics))
        return false;
    discardAutosave(); // the previous path's (or the untitled one's)
    m_filePath = path;
    m_history.setClean();
    m_ownsAutosave = false;
    return true;
}

double EditorSession::build()
{
    const auto start = std::chrono::steady_clock::now();
    // Rebuilding keeps the selected controllers and CVs (by id: indices may move).
    std::vector<NodeKey> selectedIds;
    std::vector<std::pair<NodeKey, model::CurveCv>> selectedCvs;
    if (m_rig) {
        for (auto n : m_selection.nodes)
            selectedIds.push_back(m_rig->nodes[n].key);
        for (const auto& cv : m_selection.cvs)
            selectedCvs.emplace_back(m_rig->nodes[cv.node].key, cv);
    }
    m_rig = rigging::buildRig(m_document, *m_templates, rigging::BuilderRegistry::builtin(),
                            [this](double fraction, const std::string& stage) {
                                emit buildProgressed(fraction, QString::fromStdString(stage));
                            });
    compileRig();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    m_rigStale = false;
    m_builtFrom = m_document;
    m_selection.nodes.clear();
    m_selection.node = model::kNoNode;
    for (const auto& id : selectedIds)
        if (auto n = m_rig->find(id)) {
            m_selection.nodes.push_back(*n);
            m_selection.node = *n;
        }
    m_selection.cvs.clear();
    for (auto [id, cv] : selectedCvs)
        if (auto n = m_rig->find(id); n && std::size_t(cv.curve) < m_rig->nodes[*n].curves.size() &&
                                      std::size_t(cv.cv) < m_rig->nodes[*n].curves[cv.curve].cvs.size()) {
            cv.node = *n;
            m_selection.cvs.push_back(cv);
        }
    emit rigChanged();
    emit diagnosticsReported(m_rig->diagnostics);
    return ms;
}

Diagnostics EditorSession::reloadTemplates()
{
    m_templates = templates::TemplateRegistry::loadDefault(m_templateDiagnostics);
    emit templatesReloaded();
    if (m_rig)
        build();
    return m_templateDiagnostics;
}

Diagnostics EditorSession::exportRig(const io::ExportRequest& request, std::function<bool(double)> progress) const
{
    if (!m_rig)
        return {makeError({request.path, 0, 0}, "build the rig before exporting it")};
    return io::runExport(*m_rig, m_document.pose, request, std::move(progress));
}

QString EditorSession::addTemplate(const QString& templateId, model::JointId hookJoint)
{
    auto instance = rigging::makeInstance(m_document, *m_templates, templateId.toStdString(), hookJoint);
    if (!instance)
        return QString::fromStdString(instance.diagnostics().front().message);
    const model::InstanceId id = instance->id;
    if (auto error = edit::addInstance(m_history, instance.take()))
        return QString::fromStdString(*error);
    select(Selection::ofInstance(id));
    return {};
}

QString EditorSession::removeInstances(const std::vector<model::InstanceId>& ids)
{
    return messageOf(edit::removeInstances(m_history, ids));
}

QString EditorSession::renameInstance(model::InstanceId id, const QString& name)
{
    return messageOf(edit::renameInstance(m_history, id, name.toStdString()));
}

const templates::TemplateManifest* EditorSession::manifestOf(model::InstanceId id) const
{
    const model::TemplateInstance* instance = m_document.instance(id);
    return instance ? m_templates->find(instance->templateId) : nullptr;
}

QString EditorSession::setOption(model::InstanceId id, const std::string& name, const Value& value)
{
    const model::TemplateInstance* instance = m_document.instance(id);
    const templates::TemplateManifest* manifest = manifestOf(id);
    if (!manifest)
        return tr("no template for this instance");
    const templates::Parameter* guide = manifest->findGuide(name);
    const templates::Parameter* option = guide ? guide : manifest->findOpt(name);
    if (!option)
        return tr("%1 has no option '%2'").arg(QString::fromStdString(manifest->id), QString::fromStdString(name));
    if (!guide) {
        return messageOf(edit::setOption(m_history, id, name, value, option->value));
    }
    auto options = instance->options;
    if (value == option->value)
        options.erase(name);
    else
        options[name] = value;
    if (options == instance->options)
        return {};
    auto regenerated = rigging::regenerateGuide(m_document, *m_templates, id, options);
    if (!regenerated)
        return QString::fromStdString(formatAll(regenerated.diagnostics()));
    return messageOf(edit::replaceInstance(m_history, regenerated.take(), "Set guide option " + name));
}

QString EditorSession::resetOptions(model::InstanceId id)
{
    const model::TemplateInstance* instance = m_document.instance(id);
    const templates::TemplateManifest* manifest = manifestOf(id);
    if (!manifest)
        return tr("no template for this instance");
    model::TemplateInstance reset = *instance;
    std::erase_if(reset.options, [&](const auto& entry) { return !manifest->findGuide(entry.first); });
    if (reset.options == instance->options)
        return {};
    return messageOf(edit::replaceInstance(m_history, std::move(reset), "Reset options of " + instance->name));
}

QString EditorSession::setNameOverride(model::InstanceId id, const std::string& token, const QString& name)
{
    const templates::TemplateManifest* manifest = manifestOf(id);
    if (!manifest)
        return tr("no template for this instance");
    return messageOf(edit::setNameOverride(m_history, id, token, name.toStdString(), manifest->defaultName(token)));
}

void EditorSession::select(const Selection& selection)
{
    m_selection = selection;
    emit selectionChanged();
}

void EditorSession::selectSubject(const Subject& subject)
{
    const model::TemplateInstance* instance = m_document.instance(subject.instance());
    if (!instance)
        return;
    Selection s = Selection::ofInstance(instance->id);
    if (subject.kind == Subject::Kind::GuideJoint && instance->joint(subject.joint)) {
        s.joint = subject.joint;
        s.joints = {subject.joint};
    }
    if ((subject.kind == Subject::Kind::Node || subject.kind == Subject::Kind::Shape) && m_rig)
        if (const auto node = m_rig->find(subject.node)) {
            s.node = *node;
            s.nodes = {*node};
        }
    select(s);
}

model::InstanceId EditorSession::instanceNamed(const QString& name) const
{
    const auto* instance = m_document.instanceNamed(name.toStdString());
    return instance ? instance->id : model::kNoId;
}

} // namespace rs::app
