#pragma once
// The build log: one line per diagnostic, coloured by severity. Activating a line
// whose diagnostic has a subject (an instance name) asks to select that cause.
#include "base/Diagnostic.h"

#include <QListWidget>

namespace rs::widgets {

class LogPanel : public QListWidget {
    Q_OBJECT
public:
    explicit LogPanel(QWidget* parent = nullptr);
    void addMessage(const QString& text, Severity severity = Severity::Note);
    void addDiagnostics(const Diagnostics& diagnostics);

signals:
    void subjectActivated(const QString& subject);
};

} // namespace rs::widgets
