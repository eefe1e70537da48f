#pragma once
// The outliner: template instances as a tree with the manifest's ui.icon, each
// with its hooks (ui.hooks) as pseudo-items and child instances under the hook
// (or instance) they hang from. Its context menu offers "Add template" with one
// entry per hook, then the templates by category, Rename, Duplicate, Mirror,
// Reset options and Delete; dragging instances onto a hook, an instance or the
// empty area re-hangs them there. Ctrl/Shift+click selects several. It only
// emits requests; the app turns them into edits. The arrow keys pickwalk over
// instances (parent, first child, siblings).
#include "model/GuideDocument.h"
#include "templates/TemplateRegistry.h"

#include <QTreeView>

class QMenu;
class QStandardItemModel;

namespace rs::widgets {

class OutlinerView : public QTreeView {
    Q_OBJECT
public:
    explicit OutlinerView(QWidget* parent = nullptr);

    // Rebuilds the tree from the document; keeps the selected instance.
    void refresh(const model::GuideDocument& document, const templates::TemplateRegistry& templates);
    void selectInstance(model::InstanceId id);
    model::InstanceId selectedInstance() const;
    // Every selected instance (Ctrl/Shift+click select several), in tree order.
    std::vector<model::InstanceId> selectedInstances() const;
    // The selected instances not below another selected one (what a delete,
    // duplicate or drag acts on: the others come along).
    std::vector<model::InstanceId> topSelectedInstances() const;
    // The context menu for an instance (kNoId: the empty area, top-level adds).
    // Owned by the caller. Public so tests drive the same menu users see.
    QMenu* createContextMenu(model::InstanceId instance, QWidget* parent);

signals:
    void instanceSelected(quint32 instance);
    void addTemplateRequested(const QString& templateId, quint32 hookJoint);
    void removeRequested(const QList<quint32>& instances); // one undo step
    void duplicateRequested(const QList<quint32>& instances);
    // Drag and drop: hang `instance` under `hookJoint` (0: top level).
    void reparentRequested(quint32 instance, quint32 hookJoint);
    // A hook pseudo-item was clicked: its instance and joint.
    void hookSelected(quint32 instance, quint32 joint);
    void renameRequested(quint32 instance, const QString& newName);
    // Mirror: the instance's `branches` option ("[L, R]" to mirror, "[]" for one side).
    void branchesRequested(quint32 instance, const QString& branches);
    void resetOptionsRequested(quint32 instance);
    void walkRequested(int direction); // arrow keys: an rs::eval::WalkDirection over instances

public:
    // Where a drop at `pos` (viewport coordinates) hangs instances: a hook's
    // joint, an instance's first hook, or 0 for the top level.
    model::JointId dropTarget(const QPoint& pos) const;

protected:
    void dropEvent(QDropEvent* event) override;

private:
    // What a context-menu command acts on: the selection when the clicked instance is in it.
    std::vector<model::InstanceId> actedOn(model::InstanceId clicked) const;
    void addTemplateEntries(QMenu* menu, model::JointId hookJoint);
    void keyPressEvent(QKeyEvent* event) override;

    QStandardItemModel* m_model;
    const model::GuideDocument* m_document = nullptr;
    const templates::TemplateRegistry* m_templates = nullptr;
    bool m_refreshing = false;
};

} // namespace rs::widgets
