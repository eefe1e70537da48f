#pragma once
// The undo history dock (issue 7): "Opened" then every edit of the command
// history, the current state highlighted and undone edits greyed; clicking a
// row asks to go back (or forward) to just after that edit.
#include "edit/History.h"

#include <QListWidget>

namespace rs::widgets {

class HistoryView : public QListWidget {
    Q_OBJECT
public:
    explicit HistoryView(QWidget* parent = nullptr);
    void refresh(const edit::History& history);

signals:
    // The number of edits that should be applied (0: the document as opened).
    void jumpRequested(int index);
};

} // namespace rs::widgets
