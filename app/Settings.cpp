#include "Settings.h"

#include <QFileInfo>
#include <QMainWindow>
#include <QSettings>

namespace rs::app::settings {

namespace {

// Bumped when the dock layout changes, so an old saved layout is not restored onto new docks.
constexpr int kLayoutVersion = 2;

const char* const kOrganisation = "Rigsmith";
const char* const kApplication = "rigsmith";

} // namespace

QStringList recentFiles()
{
    QStringList out;
    const QSettings s(kOrganisation, kApplication);
    for (const QString& path : s.value("recentFiles").toStringList())
        if (QFileInfo::exists(path))
            out << path;
    return out;
}

void addRecentFile(const QString& path)
{
    const QString absolute = QFileInfo(path).absoluteFilePath();
    QSettings s(kOrganisation, kApplication);
    QStringList files = s.value("recentFiles").toStringList();
    files.removeAll(absolute);
    files.prepend(absolute);
    while (files.size() > kMaxRecentFiles)
        files.removeLast();
    s.setValue("recentFiles", files);
}

QString navigation()
{
    return QSettings(kOrganisation, kApplication).value("view/navigation", "maya").toString();
}

void setNavigation(const QString& scheme)
{
    QSettings(kOrganisation, kApplication).setValue("view/navigation", scheme);
}

bool isDisplayed(const QString& layer, bool fallback)
{
    return QSettings(kOrganisation, kApplication).value("display/" + layer, fallback).toBool();
}

void setDisplayed(const QString& layer, bool shown)
{
    QSettings(kOrganisation, kApplication).setValue("display/" + layer, shown);
}

void saveWindow(const QMainWindow& window)
{
    QSettings s(kOrganisation, kApplication);
    s.setValue("window/geometry", window.saveGeometry());
    s.setValue("window/state", window.saveState(kLayoutVersion));
}

void restoreWindow(QMainWindow& window)
{
    const QSettings s(kOrganisation, kApplication);
    window.restoreGeometry(s.value("window/geometry").toByteArray());
    window.restoreState(s.value("window/state").toByteArray(), kLayoutVersion);
}

} // namespace rs::app::settings
