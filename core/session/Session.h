#pragma once
// One open guide, without a display: the document and its history, the
// template library, the selection, the built rig, its compiled program and the
// evaluated test pose. Every edit is a command in the history; a drag is a
// transaction (previews replace each other, the end commits one undo step or
// rolls back). Every change reaches subscribers as one typed edit::Change that
// names what changed, so views refresh only that.
//
// Live rebuild: once a rig is built, every change of the guide (a joint drag's
// previews included) rebuilds it and evaluates the test pose at once, so the
// rig follows under the cursor. The editor's Qt adapter (app/EditorSession)
// and the headless CLI both drive this class. Not thread-safe: one thread.
//
// Topic files: Session.cpp (documents, builds, events), SessionGuide.cpp
// (guide authoring), SessionPose.cpp (rig mode), SessionShapes.cpp (shape and
// CV editing), SessionSkin.cpp / SessionPaint.cpp (the character and its
// weights), SessionChunks.cpp (skin chunk export and import),
// SessionRefit.cpp (changed meshes re-fitted from their previous chunk).
// The value types it speaks in are in SessionTypes.h; what it holds of the
// character (models, meshes, skin bones, palette) and reads back without a
// command is SessionCharacter.h, its base.
#include "base/Status.h"
#include "edit/GuideMove.h"
#include "edit/History.h"
#include "edit/ShapeCvEdit.h"
#include "edit/SkinEdits.h"
#include "eval/Pickwalk.h"
#include "eval/PoseTools.h"
#include "model/Rig.h"
#include "session/MirroredGuides.h"
#include "session/RefitJob.h"
#include "session/SessionCharacter.h"
#include "session/SessionTypes.h"
#include "session/SkinChunkJob.h"
#include "skin/SkinBones.h"
#include "skin/WeightTools.h"
#include "templates/TemplateRegistry.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace rs::rigging {
class BuildCache;
}

namespace rs::session {

using edit::Change;
using edit::ChangeKind;

class Session : public SessionCharacter {
public:
    explicit Session(std::shared_ptr<const templates::TemplateRegistry> templates);
    virtual ~Session();
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    // --- documents, templates, events (Session.cpp)
    const model::GuideDocument& document() const { return m_document; }
    edit::History& history() { return m_history; }
    const edit::History& history() const { return m_history; }
    const templates::TemplateRegistry& templates() const { return *m_templates; }
    // The guide joints of the mirrored branch copies, for drawing (SessionGuide.cpp).
    std::vector<MirroredGuideJoint> mirroredGuideJoints() const;
    // Replaces the open document (open, new, recover): selection, rig and history start over.
    void replaceDocument(model::GuideDocument document);
    // The guide's asset name follows its file (Save As "hero.yml" names an
    // untitled guide "hero"); not an undo step, reported as a Names change.
    void setDocumentName(const std::string& name);
    // A reloaded template library; a built rig is rebuilt with it.
    void setTemplates(std::shared_ptr<const templates::TemplateRegistry> templates);

    using Listener = std::function<void(const Change&)>;
    int subscribe(Listener listener);
    void unsubscribe(int handle);
    // Where build and evaluation messages go (the editor's log, the CLI's stderr).
    using Reporter = std::function<void(const Diagnostics&)>;
    void setReporter(Reporter reporter) { m_reporter = std::move(reporter); }
    void setBuildProgress(BuildProgress progress) { m_progress = std::move(progress); }

    // Builds the rig from the document, compiles and poses it; returns the time
    // in milliseconds. From then on every guide change rebuilds it (live).
    double build();
    const model::Rig* rig() const { return m_rig ? &*m_rig : nullptr; }
    // The rig no longer matches the guide (live rebuild off).
    bool isRigStale() const { return m_rigStale; }
    bool isLiveRebuild() const { return m_liveRebuild; }
    void setLiveRebuild(bool on);
    double lastBuildMilliseconds() const { return m_lastBuildMs; }
    using BuildReuse = session::BuildReuse;
    BuildReuse lastBuildReuse() const;

    const eval::RigProgram* program() const { return m_program.get(); }
    const eval::Pose& pose() const { return m_pose; }
    // The posed rig; null without a compiled rig.
    const eval::EvalState* evaluation() const { return m_program ? &m_evaluation : nullptr; }

    const Selection& selection() const { return m_selection; }
    void select(const Selection& selection);
    // Selects what a diagnostic is about: its instance (the authored one for a
    // mirrored copy), the guide joint, or the rig node (on the copy it names).
    void selectSubject(const Subject& subject);
    Mode mode() const { return m_mode; }
    void setMode(Mode mode);

    // --- template instances (Session.cpp). Every edit returns a Status: a
    // refusal (from rs::edit, forwarded unchanged, or the session's own) names
    // what it is about, an instance, a guide joint or a rig node.
    Status addTemplate(const std::string& templateId, model::JointId hookJoint);
    Status removeInstances(const std::vector<model::InstanceId>& ids);
    Status renameInstance(model::InstanceId id, const std::string& name);
    // One option, one undo step; a guide parameter regenerates the joints.
    Status setOption(model::InstanceId id, const std::string& name, const Value& value);
    Status resetOptions(model::InstanceId id);
    Status setNameOverride(model::InstanceId id, const std::string& token, const std::string& name);
    Status duplicateInstances(const std::vector<model::InstanceId>& ids);
    Status reparentInstance(model::InstanceId id, model::JointId hookJoint);

    // --- the character (SessionSkin.cpp): the guide's models, read through
    // the host's loader (io::importModel; the session reads no file itself),
    // and their skin weights, carried onto each rebuilt rig by skin joint
    // identity. A binding made for another topology is kept and reported,
    // never applied to the wrong vertices.
    using ModelLoader = std::function<Result<model::Model>(const std::string& path)>;
    void setModelLoader(ModelLoader loader);
    // Reads the file first: one that fails is refused with the reader's reasons.
    Status addModel(const std::string& path);
    Status removeModel(const std::string& path);
    // Reads a model's file again (it changed on disk); not an undo step.
    Status reloadModel(const std::string& path);
    // The weights of a bind (skin::bindModels) as one undo step named `what`.
    Status setBindings(std::vector<model::MeshBinding> bindings, const std::string& what);
    // One weight edit as one undo step, or inside a stroke (beginWeightStroke:
    // the dabs of one stroke are one undo step named by endWeightStroke).
    Status setVertexWeights(edit::WeightEdit edit, const std::string& what);
    void beginWeightStroke(const std::string& what);
    void endWeightStroke();

    // --- skin chunks (SessionChunks.cpp; session/SkinChunkJob.h)
    // The chunks of the bound, unchanged meshes in `scope` in the current pose
    // (the evaluated rig; bind pose when nothing is posed), with their bind
    // positions (skin::makeSkinChunk). `stamp` gives tool, user, time, method
    // and neighbour sample; its rigs are set here. Fails without a built rig,
    // for an unbound mesh named by the scope, for two meshes of one name (a
    // chunk file holds one chunk per name) or when nothing is left to export.
    // A Joints scope exports the vertices those skin joints weight (all their
    // weights) of every bound mesh; a key that is no skin joint is an error.
    Result<std::vector<skin::SkinChunk>> exportSkinChunks(const SkinScope& scope, skin::ChunkExportOptions stamp = {}) const;
    // An import of `chunks` (many files' chunks: merged here, the newest of a
    // name wins) onto the meshes in `onto`, their influences resolved onto the
    // built rig's skin joints by `influences` (skin/InfluenceMap.h: identity,
    // name, name map; missing ones stop, listed, or, under create, become
    // guide joints: session/CreateInfluences.h, added by apply). Refused
    // without a built rig, for bad options, missing influences under stop or
    // map, no target, or selected vertices of a mesh without applied weights.
    Result<SkinImportJob> prepareSkinImport(std::vector<skin::SkinChunk> chunks, skin::TransferOptions options, const SkinScope& onto,
                                            const skin::InfluenceMapOptions& influences = {}) const;
    // The weighted influences of `chunks` the rig's skin joints and the name
    // map leave unplaced (skin::missingInfluences), for a list in the editor.
    std::vector<skin::InfluenceMatch> missingInfluences(const std::vector<skin::SkinChunk>& chunks,
                                                        const skin::InfluenceMapOptions& influences) const;
    // A run job's weights as one undo step named `what` (ChangeKind::Weights):
    // a whole mesh's record is replaced (or added); with selected vertices only
    // those change. The stored influences are the rig's skin joint keys the
    // prepare resolved them onto. With job.append, a mesh loaded 1:1 from a
    // chunk of some of its vertices keeps its weights on the others (a note
    // counts them). Joints the job creates are added in the same
    // undo step (refused when the guide changed since prepare). Refused, changing
    // nothing, when the job has not run or the models changed since prepare.
    Result<std::vector<skin::MeshImportReport>> applySkinImport(SkinImportJob job, const std::string& what);
    // prepare + run + apply on this thread.
    Result<std::vector<skin::MeshImportReport>> importSkinChunks(std::vector<skin::SkinChunk> chunks, skin::TransferOptions options,
                                                                 const SkinScope& onto, const skin::InfluenceMapOptions& influences = {},
                                                                 const std::string& what = "Import skin weights");

    // --- re-fitting (SessionRefit.cpp; what a re-fit does and when it runs:
    // session/RefitJob.h). Saved chunks and options: SessionCharacter.h.
    // What a save writes beside the weights: per binding, the chunk of its
    // mesh when it fits (bind positions, triangles, the record's weights), or
    // the previous chunk kept for a changed or missing mesh (nothing lost).
    std::vector<skin::SkinChunk> bindingChunks() const;
    // Re-fits every changed mesh with a previous chunk; the reports of those
    // re-fitted (empty: nothing to do, or it failed, said in the log). With a
    // refit runner set, the prepared job goes to it instead and this returns
    // nothing: the host runs it and calls applyRefit (session/RefitJob.h).
    std::vector<skin::MeshImportReport> refitChangedMeshes();
    // What a re-fit reads, copied; nullopt when no changed mesh has a previous chunk.
    std::optional<RefitJob> prepareRefit() const;
    // A run job's records as one undo step ("Re-fit weights of mesh 'x'"),
    // its notes to the reporter. Refused, changing nothing, for a stale job.
    Result<std::vector<skin::MeshImportReport>> applyRefit(RefitJob job);
    // Whether nothing a re-fit reads changed since `job` was prepared.
    bool isCurrent(const RefitJob& job) const { return job.revision == m_revision; }
    using RefitRunner = std::function<void(RefitJob job)>;
    void setRefitRunner(RefitRunner runner) { m_refitRunner = std::move(runner); }
    // Counts the changes of the document, its models, weights and rig.
    std::uint64_t revision() const { return m_revision; }

    // --- weight painting (SessionPaint.cpp). Tools act on the bound,
    // unchanged character meshes; every one keeps weights normalised and
    // leaves locked joints alone, and is one undo step (a brush stroke too).
    // Locks are by skin joint identity, so they hold across rebuilds.
    const std::set<NodeKey>& lockedJoints() const { return m_lockedJoints; }
    void setJointLocked(const NodeKey& joint, bool locked);
    // Selected vertices (click, box), per characterMeshes() entry.
    const std::map<std::size_t, std::vector<std::uint32_t>>& selectedVertices() const { return m_selectedVertices; }
    void selectVertices(std::size_t mesh, std::vector<std::uint32_t> vertices, bool add);
    void clearVertexSelection();
    // One dab on character mesh `mesh`: `joint` (a skin bone's key) painted
    // with `brush` (its joint field is set here). Inside a stroke when one is open.
    Status paintWeights(std::size_t mesh, const NodeKey& joint, skin::Brush brush);
    enum class WeightOperation { Smooth, Prune, Normalise, Limit };
    // On the selected vertices, or every bound mesh's vertices when none is
    // selected. `amount`: smooth strength (0 to 1), prune threshold, or the
    // influence limit.
    Status applyWeightOperation(WeightOperation operation, double amount);
    // Mirrors every bound mesh's weights across x = 0, each skin joint swapped
    // for its twin on the other branch; `fromPositive`: +x (the left of a
    // character facing +z) is the source.
    Status mirrorWeights(bool fromPositive = true);
    // Copy the first selected vertex's weights; paste them onto every selected vertex.
    Status copyVertexWeights();
    Status pasteVertexWeights();

    // --- guide authoring (SessionGuide.cpp): joints are clicked (add toggles)
    // or box-selected; a drag is one transaction, previews rebuild the rig live.
    void selectGuideJoints(const std::vector<model::JointId>& joints, bool add);
    model::JointId gizmoJoint() const;
    void beginGuideDrag(model::JointId lead);
    void dragGuideTo(const Mat4& leadWorld);
    Status endGuideDrag(const std::string& what);
    // A typed move (the transform panel): `lead` gets the world matrix
    // `leadWorld` and the other selected guide joints move with it as in a
    // drag (relative, about their own pivots; mirror twins with symmetric
    // editing; no grid snap). One undo step named `what`; refused (naming the
    // joint) for an unknown joint or when nothing moves.
    Status moveGuideJoints(model::JointId lead, const Mat4& leadWorld, const std::string& what);
    void setGuideDragOptions(edit::GuideDragOptions options) { m_guideDragOptions = options; }
    const edit::GuideDragOptions& guideDragOptions() const { return m_guideDragOptions; }

    // --- shapes and CVs (SessionShapes.cpp): the gizmo moves, turns or scales a
    // controller's shape (its shape override) or its selected CVs; on a
    // mirrored copy the edit lands on the authored side, reflected.
    std::optional<Mat4> shapeFrame(model::RigNodeIndex node) const;
    void beginShapeDrag(model::RigNodeIndex node);
    void dragShapeTo(const Mat4& world);
    Status endShapeDrag();
    bool isCvMode() const { return m_cvMode; }
    void setCvMode(bool on);
    void selectCvs(const std::vector<model::CurveCv>& cvs, bool add);
    std::optional<Mat4> cvFrame() const;
    void beginCvDrag();
    void dragCvsTo(const Mat4& world);
    Status endCvDrag(const std::string& verb);

    // --- overrides (SessionOverrides.cpp): every manual adjustment of the built
    // rig, one undo step each, kept in the guide by node key (model/Override.h).
    // The channel box's commands take a channel of the compiled rig (as setChannel).
    Status setOverride(const NodeKey& key, const model::Override& record, const std::string& what = {});
    Status removeOverride(const NodeKey& key);
    // "Set as default": the channel's current value becomes what reset returns to.
    Status setChannelAsDefault(int channel);
    // "Reset to default": the channel's test pose value goes back to its default.
    Status resetChannelToDefault(int channel);
    Status setChannelLocked(int channel, bool locked);
    // Limits [min, max] (min <= max), or none (nullopt) to drop the override.
    Status setChannelLimit(int channel, std::optional<model::ChannelLimit> limit);
    // The channel box's edits on many channels at once (the selected channels
    // of the selected controllers), one undo step: set as default (the rotate
    // order is skipped), lock / unlock, keyable / not keyable, limit (enum
    // channels are skipped; nullopt removes the limit). Refused, changing
    // nothing, for an unknown channel or when no channel is left to change.
    enum class ChannelEdit { SetDefault, Lock, Unlock, Keyable, NonKeyable, Limit };
    Status editChannels(const std::vector<int>& channels, ChannelEdit edit,
                        std::optional<model::ChannelLimit> limit = std::nullopt);
    // "Reset to default" on many channels: one pose step.
    Status resetChannelsToDefault(const std::vector<int>& channels);
    // Sets many nodes' records as one undo step named `what` (an empty record
    // removes its node's: "Delete all orphans"); refused when nothing changes.
    Status setOverrides(const std::map<NodeKey, model::Override>& records, const std::string& what);
    // Moves `from`'s record onto `to` (a node of the built rig), one undo step;
    // kinds `to` already has are replaced by the moved ones, the rest kept.
    // Refused without a record at `from`, for the same key, for a node the rig
    // does not make, or for a post transform off the rig root.
    Status retargetOverride(const NodeKey& from, const NodeKey& to);
    // Why a record is an orphan (the built rig makes no node for it), or
    // nullopt when it applies or no rig is built. As the build decides: a
    // shape record of an authored side (branch "") applies to its copies.
    std::optional<std::string> orphanReason(const NodeKey& key) const;
    // The guide's build settings (model/BuildSettings.h, saved with it): which
    // override kinds builds restore (all by default) and whether they clean
    // the rig up. Each change is one undo step (ChangeKind::Build) and
    // rebuilds a built rig; refused when nothing changes.
    Status setRestore(const model::RestoreToggles& restore);
    const model::RestoreToggles& restore() const { return m_document.build.restore; }
    Status setCleanup(bool cleanup);
    bool cleanup() const { return m_document.build.cleanup; }

    // --- mods (SessionMods.cpp): the guide's mods (model/Mod.h) by index in
    // document order, one undo step each (change kind Mods); a built rig is
    // rebuilt with them. Refused for a malformed mod (edit::modProblem) or an index past the end.
    Status addMod(const model::Mod& mod);
    Status setMod(std::size_t index, const model::Mod& mod);
    Status removeMod(std::size_t index);

    // --- rig mode (SessionPose.cpp)
    void selectControllers(const std::vector<model::RigNodeIndex>& nodes, bool add);
    // Over controllers in Rig mode, else (or with `instances`) over template instances.
    void pickwalk(eval::WalkDirection direction, bool instances = false);
    void beginDrag(model::RigNodeIndex node);
    void dragTo(model::RigNodeIndex node, const Mat4& world);
    void endDrag(model::RigNodeIndex node, const std::string& what);
    Status setChannel(int channel, double value, bool matchSpace);
    Status applyPoseTool(PoseTool tool);

protected:
    // Every change, after the session has followed it (rebuilt, evaluated).
    void emitChange(const Change& change);
    void report(const Diagnostics& diagnostics);

private:
    void onHistoryChange(Change change);
    // Reverts the open transaction's last preview and applies the next one
    // (`apply` pushes it) as one change: one rebuild, one event.
    void replacePreview(const std::function<void()>& apply);
    const templates::TemplateManifest* manifestOf(model::InstanceId id) const;
    void rebuild(bool reportDiagnostics, bool explicitBuild = false);
    // Compiles the rig (or takes the program its build compiled) and poses it.
    void compileRig(std::optional<Result<eval::RigProgram>> compiled = std::nullopt);
    void poseFromDocument();
    void previewPose(eval::Pose pose);
    Status commitPose(const eval::Pose& pose, const std::string& what);
    std::optional<edit::CvDrag> selectedCvDrag() const;
    void restoreSelection(const std::vector<NodeKey>& nodes, const std::vector<std::pair<NodeKey, model::CurveCv>>& cvs);
    // Keeps the character in step with a change before subscribers hear it.
    void followCharacter(const Change& change);
    void loadModels();
    // Pairs meshes with bindings; with `only`, carries just those bindings' weights again.
    void matchMeshes(const std::vector<std::size_t>* only = nullptr);
    const skin::Surface& surfaceOf(std::size_t mesh);
    // Appends `key` to binding `b`'s joints in `edit` when it is not there; its index.
    std::uint32_t jointIndex(edit::WeightEdit& edit, const NodeKey& key) const;
    skin::WeightContext weightContext(std::size_t mesh, const model::MeshWeights& weights);
    void updatePalette();
    // The character meshes a scope covers, each with its vertices (empty: all).
    Result<std::vector<std::pair<std::size_t, std::vector<std::uint32_t>>>> scopeMeshes(const SkinScope& scope) const;
    // The export names of the skin bones (their rig nodes' names), one per bone.
    std::vector<std::string> skinBoneNames() const;
    // The rig in the evaluated pose; none when it is the bind pose.
    std::optional<model::Rig> posedRigNow() const;
    // The chunk holding binding `b`'s previous mesh, or null.
    const skin::SkinChunk* previousChunk(const model::MeshBinding& binding) const;
    // Keeps the chunks of the bindings that fit `model`'s meshes (before a reload replaces it).
    void rememberChunks(const LoadedModel& model);

    model::GuideDocument m_document;
    edit::History m_history{m_document};
    std::shared_ptr<const templates::TemplateRegistry> m_templates;
    std::vector<std::pair<int, Listener>> m_listeners;
    bool m_batching = false;
    Change m_batched;
    int m_nextListener = 1;
    Reporter m_reporter;
    BuildProgress m_progress;

    std::unique_ptr<rigging::BuildCache> m_buildCache; // live rebuilds generate only the instances an edit touched
    std::optional<model::Rig> m_rig;
    bool m_rigStale = false;
    bool m_liveRebuild = true;
    double m_lastBuildMs = 0.0;
    std::string m_reportedBuild; // the build messages last reported
    std::unique_ptr<eval::RigProgram> m_program;
    std::unique_ptr<eval::Posing> m_posing;
    eval::Pose m_pose;
    eval::EvalState m_evaluation;
    std::vector<std::pair<NodeKey, double>> m_rolledPaths; // the wheels' roll, kept across rebuilds and failed compiles
    Selection m_selection;
    Mode m_mode = Mode::Guide;
    bool m_cvMode = false;

    std::optional<eval::Pose> m_dragStart;
    std::optional<edit::GuideDrag> m_guideDrag;
    edit::GuideDragOptions m_guideDragOptions;
    struct ShapeDrag {
        model::RigNodeIndex node;
        model::InstanceId instance;
        std::string tag;
        model::ShapeEdit start;
        Mat4 nodeWorld;
        Mat4 reflection; // dragging a mirrored copy: its space -> the authored side's
    };
    std::optional<ShapeDrag> m_shapeDrag;
    struct CvDragState {
        edit::CvDrag drag;
        Mat4 change{1.0};
    };
    std::optional<CvDragState> m_cvDrag;

    ModelLoader m_modelLoader;
    RefitRunner m_refitRunner;
    std::uint64_t m_revision = 0;
};

} // namespace rs::session
