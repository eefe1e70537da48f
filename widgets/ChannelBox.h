#pragma once
// The channel box (Rig mode): the current controller's channels, as in Maya's.
// Transform channels get spin boxes; custom channels (ik_blend, roll...) get a
// spin box and a slider over their range; enum channels (space) a combo box
// with their labels (the rotate order `ro` too), plus a "match" switch so a
// space or rotate-order change keeps the control in place. Locked channels are shown greyed. It only emits edits; the app
// turns each into one undoable step.
#include "eval/Channels.h"

#include <QWidget>

#include <vector>

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
    void showNode(const eval::ChannelLayout* layout, model::RigNodeIndex node, const QString& title, const eval::Pose* pose);
    // Forget the rows (the rig was rebuilt: channel indices may have moved).
    void invalidate();
    bool matchesSpaces() const;
    // The editor of channel `channel` (QDoubleSpinBox or QComboBox), for tests.
    QWidget* editorFor(int channel) const;

signals:
    void channelEdited(int channel, double value, bool matchSpace);
    // A value was entered (Enter, a combo choice, a slider let go) or Escape
    // pressed: the owner gives the keyboard back to the viewport, so hotkeys
    // and arrow-key pickwalk work again.
    void editingDone();

protected:
    void keyPressEvent(QKeyEvent* event) override;

private:
    void rebuild(const eval::ChannelLayout& layout, model::RigNodeIndex node);
    void updateValues(const eval::Pose& pose);

    QLabel* m_title;
    QGridLayout* m_grid;
    QWidget* m_rows;
    QCheckBox* m_match;
    const eval::ChannelLayout* m_layout = nullptr;
    model::RigNodeIndex m_node = model::kNoNode;
    std::vector<std::pair<int, QWidget*>> m_editors;
    bool m_updating = false;
};

} // namespace rs::widgets
