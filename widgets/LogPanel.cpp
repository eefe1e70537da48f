#include "LogPanel.h"

namespace rs::widgets {

namespace {
constexpr int kSubjectRole = Qt::UserRole + 1;
}

LogPanel::LogPanel(QWidget* parent) : QListWidget(parent)
{
    setObjectName("buildLog");
    setWordWrap(true);
    connect(this, &QListWidget::itemActivated, this, [this](QListWidgetItem* item) {
        const QString subject = item->data(kSubjectRole).toString();
        if (!subject.isEmpty())
            emit subjectActivated(subject);
    });
    connect(this, &QListWidget::itemClicked, this, &QListWidget::itemActivated);
}

void LogPanel::addMessage(const QString& text, Severity severity)
{
    auto* item = new QListWidgetItem(text, this);
    if (severity == Severity::Error)
        item->setForeground(QColor(255, 110, 110));
    else if (severity == Severity::Warning)
        item->setForeground(QColor(240, 200, 90));
    scrollToBottom();
}

void LogPanel::addDiagnostics(const Diagnostics& diagnostics)
{
    for (const Diagnostic& d : diagnostics) {
        addMessage(QString::fromStdString(d.format()), d.severity);
        item(count() - 1)->setData(kSubjectRole, QString::fromStdString(d.subject));
    }
}

} // namespace rs::widgets
