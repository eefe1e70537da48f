#pragma once
// Shared by the window's action topic files.
#include <QAction>
#include <QKeySequence>
#include <QString>

namespace rs::app {

// An action named `objectName` (tests find it by that), with an optional
// shortcut and an icon from resources/icons/<icon>.svg.
QAction* makeAction(QObject* owner, const QString& objectName, const QString& text, const QKeySequence& shortcut,
                    const QString& icon = {});

} // namespace rs::app
