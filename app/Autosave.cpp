// EditorSession's autosave and crash recovery (issues 7 and 18).
//
// An autosave records the SHA-256 of the file its document came from (as
// opened or last saved) in its first line, a YAML comment the guide reader
// skips. It is offered back only when the file still has those bytes and the
// autosaved guide differs from it: an autosave left after undoing back to the
// saved state holds nothing newer, and one made from an older version of the
// file (another window or the CLI saved since) would load old work over new.
#include "EditorSession.h"

#include "io/AtomicFile.h"
#include "io/GuideFile.h"
#include "templates/GuideTemplates.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>

#include <optional>

namespace rs::app {

namespace {

constexpr char kHeader[] = "# Rigsmith autosave of the file with sha256 ";
constexpr char kUntitled[] = "(untitled)";

QByteArray readAll(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// The base an autosave records: a hash, kUntitled, or nullopt for an autosave
// written before bases were recorded.
std::optional<QByteArray> recordedBase(const QByteArray& autosave)
{
    if (!autosave.startsWith(kHeader))
        return std::nullopt;
    const qsizetype start = qsizetype(sizeof kHeader - 1);
    return autosave.mid(start, autosave.indexOf('\n') - start).trimmed();
}

// True when both guides write the same text (as saving them would).
bool sameGuide(const std::string& autosavePath, const QString& path)
{
    auto autosaved = io::readGuideFile(autosavePath);
    if (!autosaved)
        return false; // offered, so the recovery reports why it cannot be read
    model::GuideDocument reference;
    reference.name = "untitled"; // what File > New starts from
    if (!path.isEmpty()) {
        auto saved = io::readGuideFile(path.toStdString());
        if (!saved)
            return false;
        reference = saved.take();
    }
    return io::writeGuideText(*autosaved) == io::writeGuideText(reference);
}

} // namespace

QByteArray EditorSession::contentHash(const QString& path)
{
    if (path.isEmpty() || !QFileInfo::exists(path))
        return kUntitled;
    return QCryptographicHash::hash(readAll(path), QCryptographicHash::Sha256).toHex();
}

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
    if (history().isClean()) { // undone back to the saved state: an older autosave would bring the undone edits back
        discardAutosave();
        return false;
    }
    const std::string path = autosavePath().toStdString();
    const std::string text = kHeader + m_baseHash.toStdString() + "\n" +
                             io::writeGuideText(document(), QFileInfo(autosavePath()).absolutePath().toStdString());
    const Status written = io::writeFileAtomically(path, text);
    diagnostics = written.diagnostics();
    m_ownsAutosave = m_ownsAutosave || written.ok();
    return written.ok();
}

void EditorSession::discardAutosave() const
{
    if (m_ownsAutosave)
        QFile::remove(autosavePath());
    m_ownsAutosave = false;
}

EditorSession::Recovery EditorSession::recoveryState(const QString& path)
{
    const QString autosavePath = autosavePathFor(path);
    const QFileInfo autosave(autosavePath);
    if (!autosave.exists())
        return Recovery::None;
    const QFileInfo file(path);
    if (!path.isEmpty() && file.exists()) {
        const auto base = recordedBase(readAll(autosavePath));
        if (base ? *base != contentHash(path) : autosave.lastModified() < file.lastModified())
            return Recovery::OtherVersion;
    }
    if ((path.isEmpty() || file.exists()) && sameGuide(autosavePath.toStdString(), path))
        return Recovery::NothingNewer;
    return Recovery::Offer;
}

bool EditorSession::hasRecovery(const QString& path)
{
    return recoveryState(path) == Recovery::Offer;
}

bool EditorSession::recover(const QString& path, Diagnostics& diagnostics)
{
    auto loaded = io::readGuideFile(autosavePathFor(path).toStdString());
    diagnostics = loaded.takeDiagnostics();
    if (!loaded)
        return false;
    loadSavedChunks(path, diagnostics);
    replaceWith(loaded.take(), path); // the file is only read: saving is the rigger's choice
    const Diagnostics unknown = templates::checkGuideTemplates(document(), templates(), autosavePathFor(path).toStdString());
    diagnostics.insert(diagnostics.end(), unknown.begin(), unknown.end());
    m_ownsAutosave = true;           // saving the recovered guide removes it
    history().setModified();
    return true;
}

} // namespace rs::app
