#pragma once
// The outliner: template instances as a tree (children under the instance they
// hang from), with the manifest's ui.icon. Its context menu offers "Add template"
// with one entry per hook of the instance's ui.hooks, then the templates by
// category; it only emits requests, the app turns them into edits. The arrow
// keys pickwalk over instances (parent, first child, siblings).
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
    // The context menu for an instance (kNoId: the empty area, top-level adds).
    // Owned by the caller. Public so tests drive the same menu users see.
    QMenu* createContextMenu(model::InstanceId instance, QWidget* parent);

signals:
    void instanceSelected(quint32 instance);
    void addTemplateRequested(const QString& templateId, quint32 hookJoint);
    void removeRequested(quint32 instance);
    void renameRequested(quint32 instance, const QString& newName);
    // Mirror: the instance's `branches` option ("[L, R]" to mirror, "[]" for one side).
    void branchesRequested(quint32 instance, const QString& branches);
    void resetOptionsRequested(quint32 instance);
    void walkRequested(int direction); // arrow keys: an rs::eval::WalkDirection over instances

private:
    void addTemplateEntries(QMenu* menu, model::JointId hookJoint);
    void keyPressEvent(QKeyEvent* event) override;

    QStandardItemModel* m_model;
    const model::GuideDocument* m_document = nullptr;
    const templates::TemplateRegistry* m_templates = nullptr;
    bool m_refreshing = false;
};

} // namespace rs::widgets
