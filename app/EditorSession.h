#pragma once
// One open guide in the editor: the document, its undo history, the template
// registry, the last built rig and the selection. All edits go through
// rs::edit on the history; this object only adds Qt signals so the views can
// follow. It holds no widgets.
#include "edit/History.h"
#include "model/Rig.h"
#include "templates/TemplateRegistry.h"

#include <QObject>
#include <QString>

#include <memory>
#include <optional>

namespace rs::app {

struct Selection {
    model::InstanceId instance = model::kNoId;
    model::JointId joint = model::kNoId;
    model::RigNodeIndex node = model::kNoNode;
};

class EditorSession : public QObject {
    Q_OBJECT
public:
    explicit EditorSession(QObject* parent = nullptr);
    ~EditorSession() override;

    const model::GuideDocument& document() const { return m_document; }
    edit::History& history() { return m_history; }
    const templates::TemplateRegistry& templates() const { return *m_templates; }
    const Diagnostics& templateDiagnostics() const { return m_templateDiagnostics; }
    const model::Rig* rig() const { return m_rig ? &*m_rig : nullptr; }
    bool isRigStale() const { return m_rigStale; }
    QString filePath() const { return m_filePath; }
    const Selection& selection() const { return m_selection; }

    // A failed load reports why and leaves the open document untouched.
    bool open(const QString& path, Diagnostics& diagnostics);
    // File > New: a copy of a guide (a bundled sample) as an untitled document,
    // so saving asks where and never overwrites the sample; an empty path gives
    // an empty guide.
    bool newDocument(const QString& templatePath, Diagnostics& diagnostics);
    bool save(const QString& path, Diagnostics& diagnostics);
    // Builds the rig; returns the build time in milliseconds.
    double build();
    Diagnostics exportGltf(const QString& path) const;
    // Rescans the template folders (F5): new and edited manifests and shapes take
    // effect without a restart; a built rig is rebuilt with them. Returns the scan's
    // diagnostics; a broken manifest drops only that template.
    Diagnostics reloadTemplates();
    // Adds a template instance hanging under `hookJoint` (kNoId: top level) and
    // selects it. Returns an error message, empty on success.
    QString addTemplate(const QString& templateId, model::JointId hookJoint);
    QString removeInstance(model::InstanceId id);
    QString renameInstance(model::InstanceId id, const QString& name);
    void select(const Selection& selection);
    model::InstanceId instanceNamed(const QString& name) const;

signals:
    void documentChanged();
    void rigChanged();
    void selectionChanged();
    void diagnosticsReported(const rs::Diagnostics& diagnostics);
    void templatesReloaded();

private:
    // Replaces the open document (selection, rig and history start over).
    void replaceDocument(model::GuideDocument document, const QString& path);

    model::GuideDocument m_document;
    edit::History m_history{m_document};
    std::shared_ptr<templates::TemplateRegistry> m_templates;
    Diagnostics m_templateDiagnostics;
    std::optional<model::Rig> m_rig;
    bool m_rigStale = false;
    QString m_filePath;
    Selection m_selection;
};

} // namespace rs::app

Q_DECLARE_METATYPE(rs::Diagnostics)
