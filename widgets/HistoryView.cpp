#include "HistoryView.h"

#include <QSignalBlocker>

#include <algorithm>

namespace rs::widgets {

HistoryView::HistoryView(QWidget* parent) : QListWidget(parent)
{
    setObjectName("historyView");
    connect(this, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) { emit jumpRequested(row(item)); });
}

void HistoryView::refresh(const edit::History& history)
{
    // Rows are kept where their text still holds: a commit appends one row
    // (and drops the redo rows it replaced) instead of rebuilding the list,
    // whose layout grows with the history.
    const QSignalBlocker blocker(this);
    if (count() == 0)
        addItem(tr("Opened"));
    const int rows = int(history.size()) + 1;
    for (int i = 1; i < std::min(count(), rows); ++i)
        if (item(i)->text() != QString::fromStdString(history.textAt(std::size_t(i - 1)))) {
            while (count() > i)
                delete takeItem(count() - 1);
            break;
        }
    while (count() > rows)
        delete takeItem(count() - 1);
    for (int i = count(); i < rows; ++i)
        addItem(QString::fromStdString(history.textAt(std::size_t(i - 1))));
    const QColor undone = palette().color(QPalette::Disabled, QPalette::Text);
    for (int i = 1; i < rows; ++i) { // undone steps greyed, the others in the view's own colour
        QListWidgetItem* row = item(i);
        if (std::size_t(i - 1) >= history.index()) {
            if (row->foreground().color() != undone)
                row->setForeground(undone);
        } else if (row->data(Qt::ForegroundRole).isValid()) {
            row->setData(Qt::ForegroundRole, QVariant());
        }
    }
    setCurrentRow(int(history.index()));
}

} // namespace rs::widgets
