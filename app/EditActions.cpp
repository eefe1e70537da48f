// MainWindow's Edit menu beyond undo / redo: Delete, Select All and Select
// Hierarchy, over guide joints in Guide mode and controllers in Rig mode.
#include "MainWindow.h"

#include "ActionKit.h"
#include "OutlinerView.h"

#include <QMenu>

#include <algorithm>

namespace rs::app {

namespace {

std::vector<model::JointId> jointsOf(const model::GuideDocument& document, const std::vector<model::InstanceId>& ids)
{
    std::vector<model::JointId> joints;
    for (model::InstanceId id : ids)
        if (const auto* instance = document.instance(id))
            for (const auto& joint : instance->joints)
                joints.push_back(joint.id);
    return joints;
}

// Controllers of the rig owned by one of `owners` (every controller when `owners` is null).
std::vector<model::RigNodeIndex> controllersOf(const model::Rig& rig, const std::vector<model::InstanceId>* owners)
{
    std::vector<model::RigNodeIndex> nodes;
    for (model::RigNodeIndex i = 0; i < rig.nodes.size(); ++i)
        if (rig.nodes[i].kind == model::RigNodeKind::Controller &&
            (!owners || std::find(owners->begin(), owners->end(), rig.nodes[i].owner) != owners->end()))
            nodes.push_back(i);
    return nodes;
}

} // namespace

void MainWindow::createEditActions()
{
    QAction* remove = makeAction(this, "delete", tr("&Delete"), QKeySequence::Delete);
    remove->setToolTip(tr("Delete the selected template instances with what hangs below them"));
    QAction* selectAll = makeAction(this, "selectAll", tr("Select &All"), QKeySequence::SelectAll);
    selectAll->setToolTip(tr("Every guide joint (Guide mode) or controller (Rig mode)"));
    QAction* hierarchy = makeAction(this, "selectHierarchy", tr("Select &Hierarchy"), QKeySequence(tr("Ctrl+Shift+H")));
    hierarchy->setToolTip(tr("The selected template instance and every instance below it"));
    for (QAction* a : {remove, selectAll, hierarchy})
        a->setShortcutContext(Qt::WindowShortcut);

    connect(remove, &QAction::triggered, this, [this] {
        std::vector<model::InstanceId> ids = m_outliner->topSelectedInstances();
        if (ids.empty() && m_session.selection().instance != model::kNoId)
            ids.push_back(m_session.selection().instance);
        logStatus(ids.empty() ? Status::refused(tr("select the template instances to delete").toStdString())
                              : m_session.removeInstances(ids));
    });
    connect(selectAll, &QAction::triggered, this, [this] {
        const model::GuideDocument& document = m_session.document();
        if (m_session.mode() == EditorMode::Rig && m_session.rig()) {
            m_session.selectControllers(controllersOf(*m_session.rig(), nullptr), false);
            return;
        }
        std::vector<model::InstanceId> ids;
        for (const auto& instance : document.instances())
            ids.push_back(instance.id);
        m_session.selectGuideJoints(jointsOf(document, ids), false);
    });
    connect(hierarchy, &QAction::triggered, this, [this] {
        const model::GuideDocument& document = m_session.document();
        std::vector<model::InstanceId> roots = m_outliner->topSelectedInstances();
        if (roots.empty() && m_session.selection().instance != model::kNoId)
            roots.push_back(m_session.selection().instance);
        if (roots.empty()) {
            logStatus(Status::refused(tr("select a template instance first").toStdString()));
            return;
        }
        std::vector<model::InstanceId> ids;
        for (model::InstanceId root : roots)
            for (model::InstanceId id : document.subtree(root))
                if (std::find(ids.begin(), ids.end(), id) == ids.end())
                    ids.push_back(id);
        if (m_session.mode() == EditorMode::Rig && m_session.rig())
            m_session.selectControllers(controllersOf(*m_session.rig(), &ids), false);
        else
            m_session.selectGuideJoints(jointsOf(document, ids), false);
    });
    QMenu* edit = findChild<QMenu*>("editMenu");
    edit->addSeparator();
    edit->addActions({remove, selectAll, hierarchy});
    // The built rig's controller groups (template options `group`, `parent`),
    // nested as built; choosing one selects its controllers and its subgroups'.
    QMenu* groups = edit->addMenu(tr("Select Controller &Group"));
    groups->setObjectName("controllerGroupMenu");
    groups->setToolTipsVisible(true);
    connect(groups, &QMenu::aboutToShow, this, [this, groups] {
        groups->clear();
        const model::Rig* rig = m_session.rig();
        if (!rig || rig->groups.empty()) {
            groups->addAction(tr("(build the rig first)"))->setEnabled(false);
            return;
        }
        std::vector<int> depth(rig->groups.size(), 0);
        for (std::size_t g = 0; g < rig->groups.size(); ++g) {
            const auto& group = rig->groups[g];
            if (group.parent != model::ControllerGroup::kNoGroup)
                depth[g] = depth[group.parent] + 1;
            QAction* a = groups->addAction(QString(depth[g] * 3, QChar(' ')) + QString::fromStdString(group.name));
            a->setObjectName(QString("controllerGroup:") + QString::fromStdString(group.name));
            a->setToolTip(tr("%n controller(s), with its subgroups'", nullptr, int(group.controllers.size())));
            connect(a, &QAction::triggered, this, [this, g] {
                const model::Rig* built = m_session.rig();
                if (!built || g >= built->groups.size())
                    return;
                std::vector<bool> inside(built->groups.size(), false);
                std::vector<model::RigNodeIndex> nodes;
                for (std::size_t k = 0; k < built->groups.size(); ++k) { // parents come before children
                    const auto parent = built->groups[k].parent;
                    inside[k] = k == g || (parent != model::ControllerGroup::kNoGroup && inside[parent]);
                    if (inside[k])
                        nodes.insert(nodes.end(), built->groups[k].controllers.begin(), built->groups[k].controllers.end());
                }
                if (m_session.mode() != EditorMode::Rig)
                    m_session.setMode(EditorMode::Rig);
                m_session.selectControllers(nodes, false);
            });
        }
    });
}

} // namespace rs::app
