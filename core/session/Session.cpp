#include "session/Session.h"

#include "edit/GuideEdits.h"
#include "rigging/BuildCache.h"
#include "rigging/RigBuilder.h"

#include <algorithm>
#include <chrono>
#include <utility>

namespace rs::session {

Session::Session(std::shared_ptr<const templates::TemplateRegistry> templates)
    : m_templates(std::move(templates)), m_buildCache(std::make_unique<rigging::BuildCache>())
{
    m_history.addListener([this](const Change& change) { onHistoryChange(change); });
}

Session::~Session() = default;

int Session::subscribe(Listener listener)
{
    m_listeners.emplace_back(m_nextListener, std::move(listener));
    return m_nextListener++;
}

void Session::unsubscribe(int handle)
{
    std::erase_if(m_listeners, [&](const auto& l) { return l.first == handle; });
}

void Session::emitChange(const Change& change)
{
    constexpr std::uint32_t kViewOnly = ChangeKind::History | ChangeKind::Selection | ChangeKind::Evaluation | ChangeKind::Mode | ChangeKind::Pose;
    if (change.kinds & ~kViewOnly) // what a re-fit (or another job) read may have changed
        ++m_revision;
    followCharacter(change);
    const auto listeners = m_listeners; // a listener may unsubscribe
    for (const auto& [handle, listener] : listeners)
        listener(change);
}

void Session::report(const Diagnostics& diagnostics)
{
    if (m_reporter && !diagnostics.empty())
        m_reporter(diagnostics);
}

// Follows an edit: drops a selection of what is gone, rebuilds a built rig
// when the guide changed (live) or evaluates the pose again, then tells
// subscribers everything that changed in one event.
void Session::onHistoryChange(Change change)
{
    if (m_batching) { // replacePreview: one rebuild and one event for the revert and the new preview
        m_batched.merge(change);
        return;
    }
    if (m_selection.instance != model::kNoId && !m_document.instance(m_selection.instance)) {
        m_selection = {};
        change.add(ChangeKind::Selection);
    }
    if (change.touchesGuide() && m_rig) {
        if (m_liveRebuild) {
            rebuild(!change.preview); // a drag's previews do not flood the log
            change.add(ChangeKind::Rig);
            change.add(ChangeKind::Evaluation);
        } else {
            m_rigStale = true;
        }
    } else if (change.has(ChangeKind::Pose) && m_program) {
        poseFromDocument();
        change.add(ChangeKind::Evaluation);
    }
    emitChange(change);
}

void Session::replacePreview(const std::function<void()>& apply)
{
    m_batching = true;
    m_batched = {};
    m_history.revert();
    apply();
    m_batching = false;
    if (!m_batched.empty())
        onHistoryChange(std::exchange(m_batched, Change{}));
}

void Session::setDocumentName(const std::string& name)
{
    if (m_document.name == name)
        return;
    m_document.name = name;
    emitChange(Change::of(ChangeKind::Names));
}

namespace {

// An option written under its other name (Mikan's `iks` for rig.spline's
// `controls`) is the option itself in the editor: the Options dock shows and
// edits it by its own name (the build reads either).
void adoptOtherOptionNames(model::GuideDocument& document, const templates::TemplateRegistry& templates)
{
    for (const model::TemplateInstance& i : document.instances()) {
        const templates::TemplateManifest* manifest = templates.find(i.templateId);
        if (!manifest)
            continue;
        model::TemplateInstance& instance = *document.instance(i.id);
        for (const templates::Parameter& p : manifest->opts) {
            const auto other = p.legacy.empty() ? instance.options.end() : instance.options.find(p.legacy);
            if (other == instance.options.end() || instance.options.count(p.name))
                continue;
            instance.options[p.name] = other->second;
            instance.options.erase(other);
            if (auto source = instance.optionSources.at.extract(p.legacy))
                instance.optionSources.at[p.name] = source.mapped();
        }
    }
}

} // namespace

void Session::replaceDocument(model::GuideDocument document)
{
    adoptOtherOptionNames(document, *m_templates);
    m_guideDrag.reset();
    m_shapeDrag.reset();
    m_cvDrag.reset();
    m_dragStart.reset();
    m_selection = {};
    m_rig.reset();
    m_buildCache->clear();
    m_rigStale = false;
    compileRig();
    m_rolledPaths.clear(); // another document: its wheels start unrolled
    m_mode = Mode::Guide;
    m_models.clear();                     // an opened guide reads its model files afresh (they may have changed)
    m_history.reset(std::move(document)); // emits Document: every view starts over
    refitChangedMeshes();                 // an undo step on the new document's history
}

void Session::setTemplates(std::shared_ptr<const templates::TemplateRegistry> templates)
{
    m_templates = std::move(templates);
    Change change = Change::of(ChangeKind::Templates);
    if (m_rig) {
        rebuild(true);
        change.add(ChangeKind::Rig);
        change.add(ChangeKind::Evaluation);
    }
    emitChange(change);
}

void Session::setLiveRebuild(bool on)
{
    m_liveRebuild = on;
    if (on && m_rigStale)
        build();
}

double Session::build()
{
    rebuild(true, true);
    Change change = Change::of(ChangeKind::Rig | ChangeKind::Evaluation | ChangeKind::Selection);
    emitChange(change);
    refitChangedMeshes();
    return m_lastBuildMs;
}

// Builds, compiles and poses; the selected controllers and CVs are kept by
// node key (indices may move).
void Session::rebuild(bool reportDiagnostics, bool explicitBuild)
{
    const auto start = std::chrono::steady_clock::now();
    std::vector<NodeKey> selected;
    std::vector<std::pair<NodeKey, model::CurveCv>> selectedCvs;
    if (m_rig) {
        for (auto n : m_selection.nodes)
            if (n < m_rig->nodes.size()) selected.push_back(m_rig->nodes[n].key);
        for (const auto& cv : m_selection.cvs)
            if (cv.node < m_rig->nodes.size()) selectedCvs.emplace_back(m_rig->nodes[cv.node].key, cv);
    }
    if (explicitBuild) // the rigger asked for a build: everything is generated again
        m_buildCache->clear();
    m_rig = rigging::buildRig(m_document, *m_templates, rigging::BuilderRegistry::builtin(),
                              explicitBuild ? m_progress : rigging::BuildProgress{}, // live rebuilds show no progress
                              m_buildCache.get(), m_document.build.restore);
    m_rigStale = false;
    compileRig(m_buildCache->takeProgram());
    restoreSelection(selected, selectedCvs);
    m_lastBuildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    // A live rebuild reports only messages that changed (an edit that fixes or
    // breaks something), an explicit build always.
    const std::string text = formatAll(m_rig->diagnostics);
    if (reportDiagnostics && (explicitBuild || text != m_reportedBuild))
        report(m_rig->diagnostics);
    if (reportDiagnostics)
        m_reportedBuild = text;
}

Session::BuildReuse Session::lastBuildReuse() const
{
    const auto& stats = m_buildCache->lastBuild();
    return {stats.replayed, stats.generated};
}

void Session::restoreSelection(const std::vector<NodeKey>& nodes, const std::vector<std::pair<NodeKey, model::CurveCv>>& cvs)
{
    m_selection.nodes.clear();
    m_selection.node = model::kNoNode;
    for (const auto& key : nodes)
        if (auto n = m_rig->find(key)) {
            m_selection.nodes.push_back(*n);
            m_selection.node = *n;
        }
    m_selection.cvs.clear();
    for (auto [key, cv] : cvs)
        if (auto n = m_rig->find(key); n && std::size_t(cv.curve) < m_rig->nodes[*n].curves.size() &&
                                       std::size_t(cv.cv) < m_rig->nodes[*n].curves[cv.curve].cvs.size()) {
            cv.node = *n;
            m_selection.cvs.push_back(cv);
        }
}

// A rebuild keeps how far the wheels have rolled (eval::RigProgram::carryPaths).
// The rolls are kept as values when the program goes, so a rig edit that fails
// to compile (or to build) does not lose them: the next good program takes them.
void Session::compileRig(std::optional<Result<eval::RigProgram>> program)
{
    m_posing.reset();
    if (m_program)
        m_rolledPaths = m_program->rolledPaths(m_evaluation);
    m_program.reset();
    if (!m_rig)
        return;
    auto compiled = program ? std::move(*program) : eval::RigProgram::compile(*m_rig);
    if (!compiled) {
        report(compiled.diagnostics());
        m_mode = Mode::Guide;
        return;
    }
    m_program = std::make_unique<eval::RigProgram>(compiled.take());
    m_posing = std::make_unique<eval::Posing>(*m_rig, *m_program);
    m_posing->follow(&m_evaluation); // tools evaluate from the displayed wheels' roll
    eval::EvalState state = m_program->makeState();
    m_program->carryPaths(m_rolledPaths, state);
    m_evaluation = std::move(state);
    poseFromDocument();
}

void Session::poseFromDocument()
{
    if (!m_program)
        return;
    m_pose = eval::poseFromValues(*m_rig, m_program->channels(), rigging::restoredPose(m_document, m_document.build.restore));
    m_program->evaluate(m_pose, m_evaluation);
}

void Session::select(const Selection& selection)
{
    m_selection = selection;
    emitChange(Change::of(ChangeKind::Selection));
}

void Session::selectSubject(const Subject& subject)
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

void Session::setMode(Mode mode)
{
    if (mode == Mode::Rig && !m_program)
        mode = Mode::Guide; // nothing to pose yet
    if (mode == m_mode)
        return;
    m_mode = mode;
    emitChange(Change::of(ChangeKind::Mode));
}

const templates::TemplateManifest* Session::manifestOf(model::InstanceId id) const
{
    const model::TemplateInstance* instance = m_document.instance(id);
    return instance ? m_templates->find(instance->templateId) : nullptr;
}

Status Session::addTemplate(const std::string& templateId, model::JointId hookJoint)
{
    auto instance = rigging::makeInstance(m_document, *m_templates, templateId, hookJoint);
    if (!instance)
        return Status::failure(instance.takeDiagnostics());
    const model::InstanceId id = instance->id;
    Diagnostics warnings = instance.takeDiagnostics();
    if (Status added = edit::addInstance(m_history, instance.take()); added.failed())
        return added;
    select(Selection::ofInstance(id));
    return Status::success(std::move(warnings));
}

Status Session::removeInstances(const std::vector<model::InstanceId>& ids) { return edit::removeInstances(m_history, ids); }

Status Session::renameInstance(model::InstanceId id, const std::string& name)
{
    return edit::renameInstance(m_history, id, name);
}

Status Session::setOption(model::InstanceId id, const std::string& name, const Value& value)
{
    const model::TemplateInstance* instance = m_document.instance(id);
    const templates::TemplateManifest* manifest = manifestOf(id);
    if (!manifest)
        return Status::refused("no template for this instance", Subject::ofInstance(id));
    const templates::Parameter* guide = manifest->findGuide(name);
    const templates::Parameter* option = guide ? guide : manifest->findOpt(name);
    if (!option)
        return Status::refused(manifest->id + " has no option '" + name + "'", Subject::ofInstance(id));
    if (!guide)
        return edit::setOption(m_history, id, name, value, option->value);
    auto options = instance->options;
    if (sameValue(value, option->value))
        options.erase(name);
    else
        options[name] = value;
    if (options == instance->options)
        return {};
    auto regenerated = rigging::regenerateGuide(m_document, *m_templates, id, options);
    if (!regenerated)
        return Status::failure(regenerated.takeDiagnostics());
    return edit::replaceInstance(m_history, regenerated.take(), "Set guide option " + name);
}

Status Session::resetOptions(model::InstanceId id)
{
    const model::TemplateInstance* instance = m_document.instance(id);
    const templates::TemplateManifest* manifest = manifestOf(id);
    if (!manifest)
        return Status::refused("no template for this instance", Subject::ofInstance(id));
    model::TemplateInstance reset = *instance;
    std::erase_if(reset.options, [&](const auto& entry) { return !manifest->findGuide(entry.first); });
    if (reset.options == instance->options)
        return {};
    return edit::replaceInstance(m_history, std::move(reset), "Reset options of " + instance->name);
}

Status Session::setNameOverride(model::InstanceId id, const std::string& token, const std::string& name)
{
    const templates::TemplateManifest* manifest = manifestOf(id);
    if (!manifest)
        return Status::refused("no template for this instance", Subject::ofInstance(id));
    return edit::setNameOverride(m_history, id, token, name, manifest->defaultName(token));
}

Status Session::duplicateInstances(const std::vector<model::InstanceId>& ids)
{
    std::vector<model::InstanceId> copies;
    if (Status duplicated = edit::duplicateInstances(m_history, ids, &copies); duplicated.failed())
        return duplicated;
    select(Selection::ofInstance(copies.back()));
    return {};
}

Status Session::reparentInstance(model::InstanceId id, model::JointId hookJoint)
{
    return edit::reparentInstance(m_history, id, hookJoint);
}


} // namespace rs::session
