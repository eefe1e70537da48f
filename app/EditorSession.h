#pragma once
// The editor's Qt adapter of one open guide: a core session::Session (the
// document, history, selection, built rig and evaluated pose, Qt-free) plus
// what needs files or Qt: the file path, autosave and recovery, opening and
// saving, the template folders, the model loader and export.
// Every core change is re-emitted as one `changed` signal carrying the typed
// edit::Change, so each view refreshes only what it names.
#include "io/ExportRequest.h"
#include "session/Session.h"

#include <QByteArray>
#include <QMetaType>
#include <QObject>
#include <QString>

#include <functional>
#include <memory>
#include <vector>

namespace rs::app {

using Selection = session::Selection;
using EditorMode = session::Mode;
using PoseTool = session::PoseTool;

class EditorSession : public QObject, public session::Session {
    Q_OBJECT
public:
    explicit EditorSession(QObject* parent = nullptr);
    ~EditorSession() override;

    const Diagnostics& templateDiagnostics() const { return m_templateDiagnostics; }
    QString filePath() const { return m_filePath; }

    // A failed load reports why and leaves the open document untouched.
    bool open(const QString& path, Diagnostics& diagnostics);
    // File > New: a copy of a guide (a bundled sample) as an untitled document,
    // so saving asks where and never overwrites the sample; an empty path gives
    // an empty guide.
    bool newDocument(const QString& templatePath, Diagnostics& diagnostics);
    bool save(const QString& path, Diagnostics& diagnostics);

    // Autosave (Autosave.cpp): the unsaved document goes to autosavePath()
    // ("<file>.autosave", or untitled.autosave.yml in the app data folder for an
    // untitled guide), atomically, with the hash of the file it came from. A
    // save, a clean close or undoing back to the saved state removes it; one left
    // behind means a crash, and opening the file offers to recover it when it
    // holds something newer than the file and came from the file as it is now.
    // Recovery only reads: the guide opens unsaved, the file is untouched.
    enum class Recovery {
        None,         // no autosave
        Offer,        // came from the file as it is, holds changes
        NothingNewer, // the same guide as the file (or an empty untitled one): safe to delete
        OtherVersion, // made from other bytes than the file has now: not offered, kept
    };
    static QString autosavePathFor(const QString& path);
    QString autosavePath() const { return autosavePathFor(m_filePath); }
    bool autosave(Diagnostics& diagnostics) const;
    void discardAutosave() const;
    static Recovery recoveryState(const QString& path);
    static bool hasRecovery(const QString& path); // recoveryState(path) == Offer
    bool recover(const QString& path, Diagnostics& diagnostics);
    // SHA-256 (hex) of the file's bytes; "(untitled)" for no file.
    static QByteArray contentHash(const QString& path);

    // Runs io::runExport on the built rig with the document's pose.
    Diagnostics exportRig(const io::ExportRequest& request, std::function<bool(double)> progress = {}) const;
    // Rescans the template folders (F5); a built rig is rebuilt with them.
    Diagnostics reloadTemplates();
    model::InstanceId instanceNamed(const QString& name) const;


signals:
    void changed(const rs::edit::Change& change);
    void diagnosticsReported(const rs::Diagnostics& diagnostics);
    // During a build: the fraction done and the stage (session::BuildProgress).
    void buildProgressed(double fraction, const QString& stage);

private:
    void replaceWith(model::GuideDocument document, const QString& path);
    // The chunks saved beside the guide's weights, for re-fitting changed meshes.
    void loadSavedChunks(const QString& guidePath, Diagnostics& diagnostics);

    Diagnostics m_templateDiagnostics;
    QString m_filePath;
    QByteArray m_baseHash; // contentHash of m_filePath as opened or last saved
    mutable bool m_ownsAutosave = false;
};

} // namespace rs::app

Q_DECLARE_METATYPE(rs::Diagnostics)
Q_DECLARE_METATYPE(rs::edit::Change)
