#pragma once
// One open guide in the editor: the document, its undo history, the template
// registry, the last built rig and the selection. All edits go through
// rs::edit on the history; this object only adds Qt signals so the views can
// follow. It holds no widgets.
#include "edit/GuideMove.h"
#include "edit/ShapeCvEdit.h"
#include "edit/History.h"
#include "eval/Pickwalk.h"
#include "eval/PoseTools.h"
#include "io/ExportRequest.h"
#include "model/Rig.h"
#include "templates/TemplateRegistry.h"

#include <QObject>
#include <QString>

#include <functional>
#include <memory>
#include <optional>

namespace rs::app {

struct Selection {
    model::InstanceId instance = model::kNoId;
    model::JointId joint = model::kNoId;           // the current guide joint (the gizmo's)
    std::vector<model::JointId> joints;            // every selected guide joint, `joint` among them
    model::RigNodeIndex node = model::kNoNode;     // the current controller (rig mode)
    std::vector<model::RigNodeIndex> nodes;        // every selected controller, `node` among them
    std::vector<model::CurveCv> cvs;               // CV mode: selected CVs, all of `node`

    // An instance (and one of its guide joints), no controllers.
    static Selection ofInstance(model::InstanceId id, model::JointId joint = model::kNoId)
    {
        Selection s;
        s.instance = id;
        s.joint = joint;
        return s;
    }
};

enum class EditorMode { Guide, Rig };
enum class PoseTool { ResetSelected, ResetAll, Mirror, Flip, IkToFk, FkToIk };

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

    // Autosave (Autosave.cpp): the unsaved document goes to autosavePath()
    // ("<file>.autosave", or untitled.autosave.yml in the app data folder for an
    // untitled guide), atomically. A save or a clean close removes it; one left
    // behind means a crash, and opening the file offers to recover it.
    static QString autosavePathFor(const QString& path);
    QString autosavePath() const { return autosavePathFor(m_filePath); }
    // Writes the autosave when there are unsaved changes; true when written.
    bool autosave(Diagnostics& diagnostics) const;
    // Removes the autosave this session wrote or recovered (never another
    // session's crash autosave the rigger declined to recover).
    void discardAutosave() const;
    // An autosave of `path` newer than the file itself (or of an untitled guide when `path` is empty).
    static bool hasRecovery(const QString& path);
    // Opens the autosave of `path` as `path`, with its changes unsaved.
    bool recover(const QString& path, Diagnostics& diagnostics);
    // Builds the rig; returns the build time in milliseconds.
    double build();
    // Runs io::runExport on the built rig with the document's pose.
    Diagnostics exportRig(const io::ExportRequest& request, std::function<bool(double)> progress = {}) const;
    // Rescans the template folders (F5): new and edited manifests and shapes take
    // effect without a restart; a built rig is rebuilt with them. Returns the scan's
    // diagnostics; a broken manifest drops only that template.
    Diagnostics reloadTemplates();
    // Adds a template instance hanging under `hookJoint` (kNoId: top level) and
    // selects it. Returns an error message, empty on success.
    QString addTemplate(const QString& templateId, model::JointId hookJoint);
    // The instances with everything below them, one undo step.
    QString removeInstances(const std::vector<model::InstanceId>& ids);
    QString renameInstance(model::InstanceId id, const QString& name);
    // One option of an instance, one undo step; a guide parameter (`guides`)
    // regenerates the instance's guide joints, keeping those that still exist.
    QString setOption(model::InstanceId id, const std::string& name, const Value& value);
    // Every `opts` value back to the template's default (guide parameters, which
    // shape the joints, stay), one undo step.
    QString resetOptions(model::InstanceId id);
    // A name override of one of the template's name tokens (empty: the default).
    QString setNameOverride(model::InstanceId id, const std::string& token, const QString& name);
    void select(const Selection& selection);
    // Selects what a diagnostic is about: its instance (the authored one for a
    // mirrored copy), the guide joint, or the rig node (highlighted, on the copy
    // it names) when the rig is built. Subjects of nothing here change nothing.
    void selectSubject(const Subject& subject);
    model::InstanceId instanceNamed(const QString& name) const;

    // Guide authoring in the viewport (GuideSession.cpp). Joints: click (add
    // toggles) and box select; the current joint (or a selected instance's
    // root) carries the gizmo. A drag previews without history and lands as one
    // undo step; symmetry moves side-named twins, snapping rounds to the grid.
    void selectGuideJoints(const std::vector<model::JointId>& joints, bool add);
    model::JointId gizmoJoint() const;
    void beginGuideDrag(model::JointId lead);
    void dragGuideTo(const Mat4& leadWorld);
    QString endGuideDrag(const QString& what);
    void setGuideDragOptions(edit::GuideDragOptions options) { m_guideDragOptions = options; }
    const edit::GuideDragOptions& guideDragOptions() const { return m_guideDragOptions; }
    // Shape editing (Guide mode, a controller selected; ShapeSession.cpp): the
    // gizmo moves, turns or scales the controller's shape in its space (an
    // instance `shapes` edit). On a mirrored branch copy the edit lands on the
    // authored side, reflected. A shape edit (or its undo) rebuilds a current rig at once.
    std::optional<Mat4> shapeFrame(model::RigNodeIndex node) const;
    void beginShapeDrag(model::RigNodeIndex node);
    void dragShapeTo(const Mat4& world);
    QString endShapeDrag();
    // CV mode (Guide mode; ShapeSession.cpp): the selected controllers show
    // their shapes' CVs; CVs of one controller are picked (add toggles) or
    // box-selected, and the gizmo moves, turns or scales them about their
    // centre, previewed live, one undo step, rebuilt at once so a mirrored
    // side follows. Turning it on builds the rig when it is missing or stale.
    bool isCvMode() const { return m_cvMode; }
    void setCvMode(bool on);
    void selectCvs(const std::vector<model::CurveCv>& cvs, bool add);
    // The gizmo's frame on the selected CVs; nullopt without an editable selection.
    std::optional<Mat4> cvFrame() const;
    void beginCvDrag();
    void dragCvsTo(const Mat4& world);
    QString endCvDrag(const QString& verb);
    // Duplicates the instances (with what hangs below them) and selects the copies.
    QString duplicateInstances(const std::vector<model::InstanceId>& ids);
    QString reparentInstance(model::InstanceId id, model::JointId hookJoint);
    // A reference model (FBX, OBJ, glTF...) shown see-through for placing
    // guides; empty path clears it. The guide keeps its path (one undo step),
    // so reopening the guide shows it again. A file that fails to load is
    // reported and changes nothing.
    bool loadReference(const QString& path, Diagnostics& diagnostics);
    const std::vector<glm::vec3>& referenceTriangles() const { return m_reference; }

    // Rig mode: the built rig posed by the document's pose (Build switches to it).
    EditorMode mode() const { return m_mode; }
    void setMode(EditorMode mode);
    const eval::RigProgram* program() const { return m_program.get(); }
    const eval::Pose& pose() const { return m_pose; }
    // The posed rig; null without a compiled rig.
    const eval::EvalState* evaluation() const { return m_program ? &m_evaluation : nullptr; }
    // Controllers: click (add toggles), box select, pickwalk.
    void selectControllers(const std::vector<model::RigNodeIndex>& nodes, bool add);
    // Over controllers in Rig mode, else (or with `instances`) over template instances.
    void pickwalk(eval::WalkDirection direction, bool instances = false);
    // A gizmo drag: begin keeps the pose it started from, drag previews (no
    // history), end records one undo step.
    void beginDrag(model::RigNodeIndex node);
    void dragTo(model::RigNodeIndex node, const Mat4& world);
    void endDrag(model::RigNodeIndex node, const QString& what);
    // One channel from the channel box; a space enum switches with matching when asked.
    QString setChannel(int channel, double value, bool matchSpace);
    QString applyPoseTool(PoseTool tool);

signals:
    void documentChanged();
    void rigChanged();
    void selectionChanged();
    void diagnosticsReported(const rs::Diagnostics& diagnostics);
    void templatesReloaded();
    void modeChanged();
    void poseChanged();
    void guidePreviewed(); // a guide drag moved joints (no history yet)
    // During build(): the fraction done and the stage (rigging::BuildProgress).
    void buildProgressed(double fraction, const QString& stage);
    void referenceChanged();

private:
    // An edit's refusal as the message the views show (empty on success).
    static QString messageOf(const edit::Error& error) { return error ? QString::fromStdString(*error) : QString(); }
    // The manifest of an instance's template; null when either is missing.
    const templates::TemplateManifest* manifestOf(model::InstanceId id) const;
    // Replaces the open document (selection, rig and history start over).
    void replaceDocument(model::GuideDocument document, const QString& path);
    mutable bool m_ownsAutosave = false;
    void compileRig();          // after a build: program, pose, evaluation
    void poseFromDocument();    // after any edit (undo included)
    void previewPose(eval::Pose pose);
    QString commitPose(const eval::Pose& pose, const QString& what);

    model::GuideDocument m_document;
    edit::History m_history{m_document};
    std::shared_ptr<templates::TemplateRegistry> m_templates;
    Diagnostics m_templateDiagnostics;
    std::optional<model::Rig> m_rig;
    bool m_rigStale = false;
    QString m_filePath;
    Selection m_selection;
    model::GuideDocument m_builtFrom; // the guide of the last build
    EditorMode m_mode = EditorMode::Guide;
    std::unique_ptr<eval::RigProgram> m_program;
    std::unique_ptr<eval::Posing> m_posing;
    eval::Pose m_pose;
    eval::EvalState m_evaluation;
    std::optional<eval::Pose> m_dragStart;
    std::optional<edit::GuideDrag> m_guideDrag;
    std::vector<edit::JointTransform> m_guideDragLast;
    edit::GuideDragOptions m_guideDragOptions;
    std::vector<glm::vec3> m_reference;
    std::string m_referencePath; // what m_reference shows
    // Shows the document's reference model when it changed (open, undo, redo).
    void syncReference();
    struct ShapeDrag {
        model::RigNodeIndex node;
        model::InstanceId instance;
        std::string tag;
        model::ShapeEdit start, now;
        Mat4 nodeWorld;
        Mat4 reflection;                             // dragging a mirrored copy: its space -> the authored side's
        std::vector<model::ControllerCurve> curves;
    };
    std::optional<ShapeDrag> m_shapeDrag;
    bool m_cvMode = false;
    struct CvDragState {
        edit::CvDrag drag;
        Mat4 change{1.0};
        std::map<model::RigNodeIndex, std::vector<model::ControllerCurve>> original; // the previewed nodes' curves
    };
    std::optional<CvDragState> m_cvDrag;
    // A drag of the selected CVs (CV mode, a current rig); nullopt otherwise.
    std::optional<edit::CvDrag> selectedCvDrag() const;

    void previewJoints(const std::vector<edit::JointTransform>& transforms);
};

} // namespace rs::app

Q_DECLARE_METATYPE(rs::Diagnostics)
