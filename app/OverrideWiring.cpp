// Overrides in the editor (issue 23): the channel box's override actions on
// the selected channels of the selected controllers, Rig > Restore on Build
// (one checkable action per override kind, kept by the session, rebuilding on
// change), and the Overrides dock (every record by instance, orphans with their
// reason, delete / re-target / delete all orphans, a click selects the node).
// Every edit is one session command, so one undo step.
#include "ActionKit.h"
#include "MainWindow.h"
#include "ChannelBox.h"
#include "OverridesPanel.h"

#include <QDockWidget>
#include <QMenu>
#include <QSignalBlocker>

namespace rs::app {

namespace {

// The rig node a record's key points at: its own node, else (a shape record of
// an authored side, branch "") the first copy of the same tag.
std::optional<model::RigNodeIndex> nodeOf(const model::Rig& rig, const NodeKey& key)
{
    if (const auto node = rig.find(key))
        return node;
    for (model::RigNodeIndex i = 0; i < rig.nodes.size(); ++i)
        if (rig.nodes[i].key.instance == key.instance && rig.nodes[i].key.tag == key.tag)
            return i;
    return std::nullopt;
}

// "arm.L": an instance's name with the branch of the copy a key names.
QString copyName(const model::GuideDocument& d, const NodeKey& key)
{
    if (key.isRoot())
        return QObject::tr("rig");
    const model::TemplateInstance* instance = d.instance(key.instance);
    QString name = instance ? QString::fromStdString(instance->name) : QObject::tr("#%1 (deleted)").arg(key.instance);
    return key.branch.empty() ? name : name + "." + QString::fromStdString(key.branch);
}

} // namespace

void MainWindow::createRestoreActions(QMenu* rigMenu)
{
    QMenu* restore = rigMenu->addMenu(tr("Restore on &Build"));
    restore->setObjectName("restoreMenu");
    restore->setToolTip(tr("Which of your overrides a build applies; the records stay in the guide either way"));
    const QString texts[model::kOverrideKindCount] = {tr("&Shapes"), tr("&Default Values"), tr("&Limits"), tr("Loc&ks"),
                                                      tr("&Post Transform"), tr("&Names"), tr("Test P&ose")};
    for (int k = 0; k < model::kOverrideKindCount; ++k) {
        const auto kind = model::OverrideKind(k);
        QAction* a = makeAction(this, QString("restore:") + model::overrideKindName(kind), texts[k], {});
        a->setCheckable(true);
        a->setChecked(m_session.restore().restores(kind));
        connect(a, &QAction::toggled, this, [this, kind](bool on) {
            model::RestoreToggles toggles = m_session.restore();
            toggles.set(kind, on);
            logStatus(m_session.setRestore(toggles)); // one undo step; rebuilds a built rig
            syncBuildActions();
            refreshOverridesPanel();
        });
        restore->addAction(a);
    }
    QAction* cleanup = makeAction(this, "rig:cleanup", tr("&Clean Up on Build"), {});
    cleanup->setCheckable(true);
    cleanup->setChecked(m_session.cleanup());
    cleanup->setToolTip(tr("Build the animators' rig: hide setup groups and skin joints, lock and hide every channel "
                           "the templates do not make animatable, record the controllers' default values (exported)"));
    connect(cleanup, &QAction::toggled, this, [this](bool on) {
        logStatus(m_session.setCleanup(on)); // saved in the guide, one undo step; rebuilds a built rig
        syncBuildActions();
    });
    rigMenu->addAction(cleanup);
}

void MainWindow::syncBuildActions()
{
    const model::BuildSettings& settings = m_session.document().build;
    auto check = [this](const QString& name, bool on) {
        if (QAction* a = findChild<QAction*>(name); a && a->isChecked() != on) {
            const QSignalBlocker quiet(a); // showing the settings is no edit
            a->setChecked(on);
        }
    };
    for (int k = 0; k < model::kOverrideKindCount; ++k)
        check(QString("restore:") + model::overrideKindName(model::OverrideKind(k)), settings.restore.restores(model::OverrideKind(k)));
    check("rig:cleanup", settings.cleanup);
}

void MainWindow::createOverridesDock(QDockWidget* tabWith)
{
    m_overridesPanel = new widgets::OverridesPanel(this);
    m_overridesPanel->setObjectName("overridesPanel");
    QDockWidget* dock = addDock(m_overridesPanel, tr("Overrides"), "overridesDock", Qt::BottomDockWidgetArea);
    tabifyDockWidget(tabWith, dock);
    connect(m_overridesPanel, &widgets::OverridesPanel::nodeActivated, this, [this](const NodeKey& key) {
        const model::Rig* rig = m_session.rig();
        if (const auto node = rig ? nodeOf(*rig, key) : std::nullopt)
            m_session.selectSubject(Subject::ofNode(rig->nodes[*node].key));
    });
    connect(m_overridesPanel, &widgets::OverridesPanel::recordsEditRequested, this,
            [this](const std::map<NodeKey, model::Override>& records, const QString& what) {
                logStatus(m_session.setOverrides(records, what.toStdString()));
            });
    connect(m_overridesPanel, &widgets::OverridesPanel::retargetRequested, this,
            [this](const NodeKey& from, const NodeKey& to) { logStatus(m_session.retargetOverride(from, to)); });
}

void MainWindow::refreshOverridesPanel()
{
    const model::GuideDocument& d = m_session.document();
    const model::Rig* rig = m_session.rig();
    std::vector<widgets::OverridesPanel::Entry> entries;
    for (const auto& [key, record] : d.overrides) {
        widgets::OverridesPanel::Entry e;
        e.key = key;
        e.record = record;
        e.instance = copyName(d, key);
        const auto node = rig ? nodeOf(*rig, key) : std::nullopt;
        e.node = node && rig->nodes[*node].key == key ? QString::fromStdString(rig->nodes[*node].name) : QString::fromStdString(key.tag);
        if (const auto reason = m_session.orphanReason(key))
            e.orphanReason = QString::fromStdString(*reason);
        entries.push_back(std::move(e));
    }
    std::vector<widgets::OverridesPanel::Target> targets;
    if (rig)
        for (const model::RigNode& n : rig->nodes) {
            if (n.key.tag.empty()) continue;
            targets.push_back({n.key, copyName(d, n.key) + " / " + QString::fromStdString(n.name)});
        }
    m_overridesPanel->refresh(std::move(entries), std::move(targets));
}

void MainWindow::connectChannelOverrides()
{
    using A = widgets::ChannelBox::ChannelAction;
    using E = session::Session::ChannelEdit;
    connect(m_channelBox, &widgets::ChannelBox::channelActionRequested, this, [this](A action, const QStringList& names) {
        const std::vector<int> channels = selectedChannels(names);
        switch (action) {
        case A::SetDefault: logStatus(m_session.editChannels(channels, E::SetDefault)); break;
        case A::ResetDefault: logStatus(m_session.resetChannelsToDefault(channels)); break;
        case A::Lock: logStatus(m_session.editChannels(channels, E::Lock)); break;
        case A::Unlock: logStatus(m_session.editChannels(channels, E::Unlock)); break;
        case A::Keyable: logStatus(m_session.editChannels(channels, E::Keyable)); break;
        case A::NonKeyable: logStatus(m_session.editChannels(channels, E::NonKeyable)); break;
        case A::RemoveLimit: logStatus(m_session.editChannels(channels, E::Limit, std::nullopt)); break;
        }
    });
    connect(m_channelBox, &widgets::ChannelBox::limitRequested, this, [this](const QStringList& names, double min, double max) {
        logStatus(m_session.editChannels(selectedChannels(names), E::Limit, model::ChannelLimit{min, max}));
    });
}

std::vector<int> MainWindow::selectedChannels(const QStringList& names) const
{
    std::vector<int> channels;
    const eval::RigProgram* program = m_session.program();
    if (!program || m_session.mode() != EditorMode::Rig)
        return channels;
    for (model::RigNodeIndex node : m_session.selection().nodes)
        for (const QString& name : names)
            if (const auto channel = program->channels().find(node, name.toStdString()))
                channels.push_back(*channel);
    return channels;
}

const model::Override* MainWindow::channelBoxRecord(model::RigNodeIndex node) const
{
    const model::Rig* rig = m_session.rig();
    if (!rig || node >= rig->nodes.size() || !m_session.restore().restores(model::OverrideKind::Defaults))
        return nullptr;
    auto it = m_session.document().overrides.find(rig->nodes[node].key);
    return it == m_session.document().overrides.end() ? nullptr : &it->second;
}

} // namespace rs::app
