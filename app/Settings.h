#pragma once
// What the editor keeps between runs (QSettings, organisation "Rigsmith"): the
// window's geometry and dock layout, and the recent guide files (most recent
// first, at most kMaxRecentFiles, missing files dropped when listed), and the
// view preferences: the navigation scheme and the View > Display toggles.
#include <QStringList>

class QMainWindow;

namespace rs::app::settings {

constexpr int kMaxRecentFiles = 8;

QStringList recentFiles();
void addRecentFile(const QString& path);
void saveWindow(const QMainWindow& window);
// "maya" (Alt+drag, the default), "blender" (middle-drag orbits) or "touchpad".
QString navigation();
void setNavigation(const QString& scheme);
// A View > Display toggle ("guides", "axes"...); `fallback` when never set.
bool isDisplayed(const QString& layer, bool fallback);
void setDisplayed(const QString& layer, bool shown);
void restoreWindow(QMainWindow& window);

} // namespace rs::app::settings
