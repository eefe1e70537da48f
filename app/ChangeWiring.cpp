// MainWindow's change wiring: what each view shows of a session change (the
// typed edit::Change), and the docks that edit options, names and history.
#include "MainWindow.h"

#include "ChannelBox.h"
#include "HistoryView.h"
#include "LogPanel.h"
#include "OptionsEditor.h"
#include "OutlinerView.h"
#include "TemplateLibrary.h"

#include <algorithm>

namespace rs::app {

namespace {

// The instances whose drawing a change can alter, when it names them and
// alters nothing else the viewport draws: each named instance, what hangs
// below it (hooked on its joints, sized by its guide) and above it (a builder
// may read its children's nodes). None (draw all again) for anything else: a
// selection, a mode, a posed rig (a pose reaches across instances), a new
// document or template library, instances added or removed.
std::optional<std::vector<model::InstanceId>> instancesDrawnAnew(const edit::Change& change,
                                                                 const model::GuideDocument& document, bool rigMode)
{
    using K = edit::ChangeKind;
    std::uint32_t local = K::Joints | K::Options | K::Shapes | K::Rig | K::History;
    if (!rigMode)
        local |= std::uint32_t(K::Evaluation);
    if (change.instances.empty() || (change.kinds & ~local) != 0)
        return std::nullopt;
    std::vector<model::InstanceId> out;
    for (model::InstanceId id : change.instances) {
        const std::vector<model::InstanceId> below = document.subtree(id);
        out.insert(out.end(), below.begin(), below.end());
        for (const model::TemplateInstance* i = document.instance(id); i && i->parent != model::kNoId;
             i = document.instance(i->parent))
            out.push_back(i->parent);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

} // namespace

void MainWindow::connectOptions()
{
    connect(m_historyView, &widgets::HistoryView::jumpRequested, this,
            [this](int index) { m_session.history().jumpTo(std::size_t(index)); });
    connect(m_library, &widgets::TemplateLibrary::templateActivated, this, [this](const QString& id) {
        logStatus(m_session.addTemplate(id.toStdString(), m_session.selection().joint));
    });
    m_historyView->refresh(m_session.history());
    m_library->refresh(m_session.templates());
    connect(m_options, &widgets::OptionsEditor::optionEdited, this,
            [this](model::InstanceId id, const std::string& name, const Value& value) {
                // The editor's own widget already shows the value: its page is
                // not rebuilt under the cursor (a spinner keeps turning).
                m_optionsEditing = true;
                const Status set = m_session.setOption(id, name, value);
                m_optionsEditing = false;
                const model::TemplateInstance* instance = m_session.document().instance(id);
                if (instance && !instance->options.count(name))
                    refreshOptions(); // back to the default (its reset button): the widget shows it
                else if (instance)
                    m_options->showChanged(*instance);
                logStatus(set);
                if (set.failed())
                    refreshOptions(); // show the stored value again
            });
    connect(m_options, &widgets::OptionsEditor::helpRequested, this,
            [this](const std::string& templateId) { showTemplateHelp(templateId); });
    connect(m_options, &widgets::OptionsEditor::nameEdited, this,
            [this](model::InstanceId id, const std::string& token, const QString& name) {
                logStatus(m_session.setNameOverride(id, token, name.toStdString()));
            });
}

void MainWindow::refreshOptions()
{
    // Queued: an edit rebuilds the editor's widgets, the one that emitted included.
    QMetaObject::invokeMethod(this, [this] {
        const model::TemplateInstance* instance = m_session.document().instance(m_session.selection().instance);
        m_options->setInstance(instance, instance ? m_session.templates().find(instance->templateId) : nullptr);
        m_optionsInstance = m_session.selection().instance;
    }, Qt::QueuedConnection);
}

// What each view shows of a change; previews (a drag in progress) touch only
// the viewport and what follows the rig.
void MainWindow::follow(const edit::Change& change)
{
    using K = edit::ChangeKind;
    const bool everything = change.hasAny(K::Document | K::Templates);
    if (change.has(K::Document))
        clearRoutes(); // another guide: its meshes' steps are its own
    if (everything || (!change.preview && change.hasAny(K::Instances | K::Names)))
        m_outliner->refresh(m_session.document(), m_session.templates());
    if (everything || change.hasAny(K::Selection | K::Instances))
        m_outliner->selectInstance(m_session.selection().instance);
    if (change.has(K::Templates))
        m_library->refresh(m_session.templates());
    if (change.hasAny(K::History | K::Document)) {
        m_historyView->refresh(m_session.history());
        updateUndoActions();
        updateTitle();
    }
    const bool optionsShown = m_optionsInstance == m_session.selection().instance;
    if (everything || !optionsShown ||
        (!change.preview && !m_optionsEditing && change.hasAny(K::Options | K::Names | K::Instances)))
        refreshOptions();
    // The Overrides dock: records and, after a build, which are orphans.
    if (everything || (!change.preview && change.hasAny(K::Overrides | K::Shapes | K::Pose | K::Instances | K::Names | K::Rig)))
        refreshOverridesPanel();
    if (everything || (!change.preview && change.hasAny(K::Mods | K::Instances)))
        refreshModsPanel(); // instances: an owner renamed, removed or back
    if (change.hasAny(K::Build | K::Document))
        syncBuildActions();
    if (change.has(K::Rig))
        m_channelBox->invalidate(); // a rebuilt rig has new channel indices
    if (change.has(K::Mode))
        followMode();
    m_characterWeights.follow(m_session, change);
    if (change.hasAny(K::Document | K::Rig | K::Templates))
        refreshPaintPanel(); // new skin joints
    if (change.hasAny(K::Document | K::Instances | K::Joints | K::Options | K::Shapes | K::Names |  K::Selection |
                      K::Rig | K::Evaluation | K::Mode | K::Templates | K::Models | K::Weights)) {
        m_sceneChanged = instancesDrawnAnew(change, m_session.document(), m_session.mode() == EditorMode::Rig);
        refreshScene();
    }
    if (change.hasAny(K::Document | K::Instances | K::Joints | K::Options | K::Selection | K::Mode))
        refreshTransformPanel();
}

} // namespace rs::app
