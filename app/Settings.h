#pragma once
// What the editor keeps between runs (QSettings, organisation "Rigsmith"): the
// window's geometry and dock layout, and the recent guide files (most recent
// first, at most kMaxRecentFiles, missing files dropped when listed).
#include <QStringList>

class QMainWindow;

namespace rs::app::settings {

constexpr int kMaxRecentFiles = 8;

QStringList recentFiles();
void addRecentFile(const QString& path);
void saveWindow(const QMainWindow& window);
void restoreWindow(QMainWindow& window);

} // namespace rs::app::settings
