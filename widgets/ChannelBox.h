#pragma once
// The channel box (Rig mode): the current controller's channels, as in Maya's.
// Transform channels get spin boxes; custom channels (ik_blend, roll...) get a
// spin box and a slider over their range; enum channels (space) a combo box
// with their labels (the rotate order `ro` too), plus a "match" switch so a
// space or rotate-order change keeps the control in place. It only emits
// edits; the app turns each into one undoable step.
//
// Channels are selected by clicking their names (Ctrl toggles, Shift extends;
// a right-click on an unselected name selects it); the selection is kept by
// channel name, so it applies to every selected controller. The context menu
// acts on it: Set as Default, Reset to Default, Lock / Unlock, Make Keyable /
// Non-keyable, Limit... (a small min / max dialog) and Remove Limit. Names
// show the state: locked (grey on slate, the editor disabled), not keyable
// (italic), default overridden (bold teal, the default in the tooltip). Each
// name label carries the properties "locked", "keyable", "defaultOverridden"
// and "selected" for tests.
#include "eval/Channels.h"
#include "model/Override.h"

#include <QStringList>
#include <QWidget>

#include <vector>

class QAction;
class QCheckBox;
class QGridLayout;
class QKeyEvent;
class QLabel;

namespace rs::widgets {

class ChannelBox : public QWidget {
    Q_OBJECT
public:
    explicit ChannelBox(QWidget* parent = nullptr);

    // Shows `node`'s channels (kNoNode or no layout: empty). Rebuilds the rows
    // only when the node changes; otherwise just updates the values.
    // `record`: the node's override record (its defaults are marked), or null.
    void showNode(const eval::ChannelLayout* layout, model::RigNodeIndex node, const QString& title, const eval::Pose* pose,
                  const model::Override* record = nullptr);
    // Forget the rows (the rig was rebuilt: channel indices may have moved).
    void invalidate();
    bool matchesSpaces() const;
    // The editor of channel `channel` (QDoubleSpinBox or QComboBox), for tests.
    QWidget* editorFor(int channel) const;
    // The name label of channel `channel`, for tests.
    QLabel* labelFor(int channel) const;
    // Selected channel names, in the order of the rows shown.
    QStringList selectedChannels() const;
    void setSelectedChannels(const QStringList& names);

    enum class ChannelAction { SetDefault, ResetDefault, Lock, Unlock, Keyable, NonKeyable, RemoveLimit };
    // The context menu's action (objectName "channelSetDefault", "channelResetDefault",
    // "channelLock", "channelUnlock", "channelKeyable", "channelNonKeyable",
    // "channelLimit", "channelRemoveLimit").
    QAction* channelAction(const QString& objectName) const;
    // Limit...: opens the min / max dialog (objectName "limitDialog", not
    // blocking) for the selected channels; OK emits limitRequested.
    void openLimitDialog();

signals:
    void channelEdited(int channel, double value, bool matchSpace);
    // A value was entered (Enter, a combo choice, a slider let go) or Escape
    // pressed: the owner gives the keyboard back to the viewport, so hotkeys
    // and arrow-key pickwalk work again.
    void editingDone();
    // A context menu action on the selected channels (by name).
    void channelActionRequested(rs::widgets::ChannelBox::ChannelAction action, const QStringList& channels);
    void limitRequested(const QStringList& channels, double min, double max);

protected:
    void keyPressEvent(QKeyEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void createActions();
    void decorate(const model::Override* record);
    void clickLabel(const QString& name, Qt::KeyboardModifiers modifiers, bool rightButton);
    void emitAction(ChannelAction action);
    void rebuild(const eval::ChannelLayout& layout, model::RigNodeIndex node);
    void updateValues(const eval::Pose& pose);

    QLabel* m_title;
    QGridLayout* m_grid;
    QWidget* m_rows;
    QCheckBox* m_match;
    const eval::ChannelLayout* m_layout = nullptr;
    model::RigNodeIndex m_node = model::kNoNode;
    std::vector<std::pair<int, QWidget*>> m_editors;
    std::vector<std::pair<int, QLabel*>> m_labels;
    QStringList m_selected;
    QString m_anchor; // Shift-click extends from here
    bool m_updating = false;
};

} // namespace rs::widgets
