#pragma once
// The Overrides dock: every override record of the guide, as a tree
// instance > node > kinds, with a text filter. An orphan (a record whose node
// the built rig does not make) is shown in orange with its reason. Actions:
// Delete (the selected nodes' records, or only the selected kinds), Re-target...
// (a picker of the rig's nodes: the record moves there), Delete All Orphans.
// Clicking a node (or one of its kinds) asks the app to select it. It only
// shows what `refresh` gives and emits requests; the app turns each into one
// undoable session edit.
#include "model/Override.h"

#include <QString>
#include <QWidget>

#include <map>
#include <vector>

class QLineEdit;
class QPushButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace rs::widgets {

class OverridesPanel : public QWidget {
    Q_OBJECT
public:
    struct Entry {
        NodeKey key;
        QString instance;     // the instance's name ("rig" for the root, "#7 (deleted)" for a gone one)
        QString node;         // the node's name in the rig, else its tag
        model::Override record;
        QString orphanReason; // empty: the record applies
    };
    // A node of the built rig a record can be re-targeted to.
    struct Target {
        NodeKey key;
        QString label; // "arm_L / c_arm_fk0_L"
    };

    explicit OverridesPanel(QWidget* parent = nullptr);

    void refresh(std::vector<Entry> entries, std::vector<Target> targets);
    void setFilter(const QString& text);
    QTreeWidget* tree() const { return m_tree; }
    // The tree item of a node's record (null when filtered out or absent), for tests.
    QTreeWidgetItem* itemOf(const NodeKey& key) const;
    // Opens the picker (objectName "retargetDialog", not blocking) for the
    // current node; choosing a node emits recordsEditRequested.
    void openRetargetDialog();
    void deleteSelected();
    void deleteAllOrphans();
    // One line per kind of a record ("limits: rx -10 to 10").
    static QStringList describe(const model::Override& record);

signals:
    void nodeActivated(const rs::NodeKey& key);
    // Records to set (an empty record deletes its node's) as one step named `what`.
    void recordsEditRequested(const std::map<rs::NodeKey, rs::model::Override>& records, const QString& what);
    void retargetRequested(const rs::NodeKey& from, const rs::NodeKey& to);

private:
    void rebuild();
    const Entry* entryOf(const QTreeWidgetItem* item) const;
    void updateButtons();

    QLineEdit* m_filter;
    QTreeWidget* m_tree;
    QPushButton* m_delete;
    QPushButton* m_retarget;
    QPushButton* m_deleteOrphans;
    std::vector<Entry> m_entries;
    std::vector<Target> m_targets;
};

} // namespace rs::widgets
