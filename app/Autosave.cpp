// EditorSession's autosave and crash recovery (issue 7).
#include "EditorSession.h"

#include "io/GuideFile.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>

namespace rs::app {

QString EditorSession::autosavePathFor(const QString& path)
{
    if (!path.isEmpty())
        return path + ".autosave";
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    QDir().mkpath(folder);
    return folder + "/untitled.autosave.yml";
}

bool EditorSession::autosave(Diagnostics& diagnostics) const
{
    if (history().isClean())
        return false;
    const Status saved = io::saveGuideFile(document(), autosavePath().toStdString());
    diagnostics = saved.diagnostics();
    m_ownsAutosave = m_ownsAutosave || saved.ok();
    return saved.ok();
}

void EditorSession::discardAutosave() const
{
    if (m_ownsAutosave)
        QFile::remove(autosavePath());
}

bool EditorSession::hasRecovery(const QString& path)
{
    const QFileInfo autosave(autosavePathFor(path));
    if (!autosave.exists())
        return false;
    const QFileInfo file(path);
    return path.isEmpty() || !file.exists() || autosave.lastModified() >= file.lastModified();
}

bool EditorSession::recover(const QString& path, Diagnostics& diagnostics)
{
    auto loaded = io::readGuideFile(autosavePathFor(path).toStdString());
    diagnostics = loaded.takeDiagnostics();
    if (!loaded)
        return false;
    replaceWith(loaded.take(), path);
    m_ownsAutosave = true; // saving the recovered guide removes it
    history().setModified();
    return true;
}

} // namespace rs::app
