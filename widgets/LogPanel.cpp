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
        bool ok = false;
        const int index = item->data(kSubjectRole).toInt(&ok);
        if (ok && index >= 0 && std::size_t(index) < m_subjects.size())
            emit subjectActivated(m_subjects[std::size_t(index)]);
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
        if (d.subject.isNone())
            continue;
        item(count() - 1)->setData(kSubjectRole, int(m_subjects.size()));
        m_subjects.push_back(d.subject);
    }
}

void LogPanel::clearMessages()
{
    clear();
    m_subjects.clear();
}

} // namespace rs::widgets
