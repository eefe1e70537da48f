#pragma once
// The build log: one line per diagnostic, coloured by severity. Activating a line
// whose diagnostic has a subject (an instance, a node of a mirrored copy, a guide
// joint...) asks to select that cause.
#include "base/Diagnostic.h"

#include <QListWidget>

#include <vector>

namespace rs::widgets {

class LogPanel : public QListWidget {
    Q_OBJECT
public:
    explicit LogPanel(QWidget* parent = nullptr);
    void addMessage(const QString& text, Severity severity = Severity::Note);
    void addDiagnostics(const Diagnostics& diagnostics);

    void clearMessages();

signals:
    void subjectActivated(const rs::Subject& subject);

private:
    std::vector<Subject> m_subjects; // kSubjectRole of a row indexes this
};

} // namespace rs::widgets
