#include "HistoryView.h"

#include <QSignalBlocker>

namespace rs::widgets {

HistoryView::HistoryView(QWidget* parent) : QListWidget(parent)
{
    setObjectName("historyView");
    connect(this, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) { emit jumpRequested(row(item)); });
}

void HistoryView::refresh(const edit::History& history)
{
    const QSignalBlocker blocker(this);
    clear();
    addItem(tr("Opened"));
    for (std::size_t i = 0; i < history.size(); ++i) {
        auto* item = new QListWidgetItem(QString::fromStdString(history.textAt(i)), this);
        if (i >= history.index())
            item->setForeground(palette().color(QPalette::Disabled, QPalette::Text));
    }
    setCurrentRow(int(history.index()));
}

} // namespace rs::widgets
