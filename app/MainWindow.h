#pragma once
// The editor window: the composition root. It creates the actions and docks and
// wires the session (core) to the views; it holds no rigging logic itself.
#include "EditorSession.h"
#include "Scene.h"
#include "SceneCharacter.h"

#include <QElapsedTimer>
#include <QImage>
#include <QMainWindow>

#include <functional>
#include <map>
#include <memory>
#include <optional>

class QAction;
class QDockWidget;
class QFileSystemWatcher;
class QLabel;
class QMenu;
class QProgressBar;

namespace rs::viewport { class ViewportWidget; }
namespace rs::widgets { class OutlinerView; class LogPanel; class ChannelBox; class ExportDialog; class OptionsEditor; class HistoryView; class TemplateLibrary; class TransformPanel; class WeightPaintPanel; class OverridesPanel; class ModsPanel; class SkinChunkPanel; }

namespace rs::app {

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    EditorSession& session() { return m_session; }
    viewport::ViewportWidget* viewportWidget() const { return m_viewport; }
    widgets::OutlinerView* outliner() const { return m_outliner; }
    widgets::LogPanel* log() const { return m_log; }
    widgets::ChannelBox* channelBox() const { return m_channelBox; }
    widgets::OptionsEditor* optionsEditor() const { return m_options; }
    widgets::HistoryView* historyView() const { return m_historyView; }
    widgets::TemplateLibrary* templateLibrary() const { return m_library; }
    widgets::TransformPanel* transformPanel() const { return m_transformPanel; }
    widgets::WeightPaintPanel* paintPanel() const { return m_paintPanel; }
    widgets::OverridesPanel* overridesPanel() const { return m_overridesPanel; }
    widgets::ModsPanel* modsPanel() const { return m_modsPanel; }
    const viewport::DisplayOptions& displayOptions() const { return m_display; }
    QAction* action(const QString& objectName) const;

    // Offers to recover an autosave newer than the file (a crash left it).
    bool openFile(const QString& path);
    // At startup: an untitled guide's autosave left by a crash is offered back.
    void offerUntitledRecovery();
    // How a recovery is offered (a question box; tests answer it themselves).
    using RecoveryPrompt = std::function<bool(const QString& file, const QString& autosave)>;
    void setRecoveryPrompt(RecoveryPrompt prompt) { m_recoveryPrompt = std::move(prompt); }
    // How an error the rigger must see is shown (a warning box; tests catch it,
    // and a window driven by tests or not shown yet only logs it).
    using ErrorPrompt = std::function<void(const QString& title, const QString& text)>;
    void setErrorPrompt(ErrorPrompt prompt) { m_errorPrompt = std::move(prompt); }
    static constexpr int kAutosaveMilliseconds = 60000;
    // Off for measurements and screenshots (nothing to recover from them).
    void setAutosaveEnabled(bool on);
    // File > New: an untitled copy of a sample (empty path: an empty guide).
    bool newFromSample(const QString& samplePath);
    bool saveFile(const QString& path);
    // File > Close: an empty untitled guide (asks to save unsaved changes first).
    bool closeDocument();
    // Exports with the default options (glTF preset, skeleton only); builds first when needed.
    bool exportTo(const QString& path);
    bool exportRig(const io::ExportRequest& request);
    widgets::ExportDialog* exportDialog(); // File > Export..., made on first use
    void buildRig();
    void reloadTemplates();

    // The character (SkinActions.cpp). Guide > Add Model: reads the file and
    // adds it (one undo step); false with the reader's reasons in the log.
    bool addModel(const QString& path);
    // Skin > Bind: binds every model to the built rig's skin joints on a
    // worker thread, with a progress dialog whose Cancel keeps the previous
    // weights; the result lands as one undo step. Builds first when needed.
    void bindSkin();
    bool isBinding() const { return m_bind != nullptr; }
    void cancelBind();
    // A model file changed on disk: asks whether to read it again (tests answer).
    using ReloadPrompt = std::function<bool(const QString& file)>;
    void setReloadPrompt(ReloadPrompt prompt) { m_reloadPrompt = std::move(prompt); }

    // Skin > Paint Weights (PaintWiring.cpp): the viewport's paint mode and the Paint dock.
    void setPaintMode(bool on);
    bool isPainting() const;
    // The painted joint (into session().skinBones()), -1 none; choosing one also shows its weights.
    int paintBone() const;
    void choosePaintJoint(int bone);

    // Skin > Skin Chunks (SkinChunkWiring.cpp): the Skin Chunks dock. Export
    // writes the dock's scope to `path`; false with the reasons in the log.
    bool exportSkinChunks(const QString& path);
    // Imports (or previews: runs without applying, selects the vertices of
    // the route the dock names) the files with the dock's options onto its
    // target, on a worker thread with a progress dialog whose Cancel changes nothing.
    void importSkinChunks(const QStringList& files, bool preview);
    bool isImportingChunks() const { return m_chunkImport != nullptr; }
    // A re-fit of changed meshes (on open, reload or build) running on its
    // worker thread (RefitWiring.cpp); its progress is in the status bar.
    bool isRefitting() const { return m_refit != nullptr; }
    // View > Display > Skin Chunk Steps (RouteOverlay.cpp): the character's
    // vertices coloured by the step that placed their weights, outside painting.
    bool isShowingRoutes() const { return m_showRoutes; }
    static glm::vec3 routeColour(session::VertexRoute route);
    void cancelChunkImport();
    void inspectSkinChunks(const QString& file);
    widgets::SkinChunkPanel* chunkPanel() const { return m_chunkPanel; }

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void showBuildProgress(double fraction, const QString& stage);
    void createActions();   // Actions.cpp
    void createPoseActions(); // Actions.cpp: Guide/Rig mode, pose tools, gizmo space
    void createViewActions(); // ViewActions.cpp: camera views, framing, guide authoring tools
    void connectViewport();   // ViewportWiring.cpp: picks, box selection, gizmo drags
    void createEditActions();    // EditActions.cpp: delete, select all / hierarchy
    void createDisplayActions(); // DisplayActions.cpp: View > Display and Navigation, the Window menu
    void createWeightDisplayActions(QMenu* display); // View > Display > Weights and Skinning
    void createHelpActions();    // HelpActions.cpp: About, the README, the selected template's help
    void createSkinActions();    // SkinActions.cpp: Guide > Add Model, the Skin menu
    void watchModels();          // SkinActions.cpp: the model files the guide uses
    void modelFileChanged(const QString& path);
    void finishBind();
    void createPaintActions(QMenu* skinMenu); // PaintWiring.cpp
    void createPaintDock();
    void connectPaint();
    void refreshPaintPanel();
    void showPaintedWeights();
    QString skinBoneName(int bone) const;
    void createSkinChunkActions(QMenu* skinMenu); // SkinChunkWiring.cpp
    void createSkinChunkDock();
    void finishChunkImport();
    void createRouteOverlay(); // RouteOverlay.cpp
    void setRoutes(std::size_t characterMesh, std::vector<session::VertexRoute> routes);
    void clearRoutes();
    void applyRouteColours(viewport::Scene& scene);
    void startRefit(session::RefitJob job); // RefitWiring.cpp
    void finishRefit();
    void createRestoreActions(QMenu* rigMenu); // OverrideWiring.cpp: Rig > Restore on Build, Clean Up on Build
    void syncBuildActions(); // their checks from the guide's build settings (after an undo, an open)
    void createOverridesDock(QDockWidget* tabWith);
    void refreshOverridesPanel();
    void connectChannelOverrides(); // the channel box's Set as Default, Lock, Limit...
    void createModsDock(QDockWidget* tabWith); // ModWiring.cpp: the Mods dock
    void refreshModsPanel();
    // The compiled channels named `names` on every selected controller (Rig mode).
    std::vector<int> selectedChannels(const QStringList& names) const;
    // A controller's override record for the channel box's marks (null with defaults not restored).
    const model::Override* channelBoxRecord(model::RigNodeIndex node) const;
    void connectTransformPanel(); // TransformWiring.cpp
    void refreshTransformPanel();
    void showHelpText(const QString& title, const QString& markdown, const QImage& picture = {});
    // The template's help page (TemplateHelp.h) in the help window.
    void showTemplateHelp(const std::string& templateId);
    void showError(const QString& title, const QString& text);
    void createDocks();
    QDockWidget* addDock(QWidget* widget, const QString& title, const QString& objectName, Qt::DockWidgetArea area);
    void connectDocument();
    void connectRigMode();  // pickwalk, channel box
    void connectOptions();  // options, template library and history docks
    void refreshViews();
    void refreshScene();
    void refreshOptions();
    void follow(const edit::Change& change); // the views that show what changed
    void followMode();                        // Guide / Rig mode: viewport and actions
    void updateUndoActions();
    void updateTitle();
    void report(const QString& what, const Diagnostics& diagnostics);
    // An edit's outcome: its diagnostics (a refusal's error, naming the instance,
    // joint or node it is about, so its log line selects it) go to the log.
    void logStatus(const Status& status);
    // A save or export that wrote nothing: the status bar, and a warning box for a rigger.
    void showWriteFailure(const QString& what, const Diagnostics& diagnostics);
    // Unsaved changes: asks Save / Discard / Cancel; true when the document may be replaced.
    bool maySwitchDocument(const QString& question);

    EditorSession m_session;
    viewport::ViewportWidget* m_viewport = nullptr;
    widgets::OutlinerView* m_outliner = nullptr;
    widgets::LogPanel* m_log = nullptr;
    widgets::ChannelBox* m_channelBox = nullptr;
    widgets::ExportDialog* m_exportDialog = nullptr;
    RecoveryPrompt m_recoveryPrompt;
    widgets::OptionsEditor* m_options = nullptr;
    widgets::HistoryView* m_historyView = nullptr;
    widgets::TemplateLibrary* m_library = nullptr;
    widgets::TransformPanel* m_transformPanel = nullptr;
    widgets::WeightPaintPanel* m_paintPanel = nullptr;
    widgets::OverridesPanel* m_overridesPanel = nullptr;
    widgets::ModsPanel* m_modsPanel = nullptr;
    std::optional<NodeKey> m_paintJoint; // the painted skin joint, by identity
    skin::Brush m_strokeBrush;           // the stroke under way
    bool m_strokeOpen = false, m_strokeRefused = false;
    viewport::DisplayOptions m_display;
    viewport::CharacterWeights m_characterWeights; // the weights objects the viewport draws
    ErrorPrompt m_errorPrompt;
    QString m_exportDialogGuide; // the guide the export dialog's path was made for
    QLabel* m_status = nullptr;
    QProgressBar* m_buildProgress = nullptr;
    QElapsedTimer m_buildPainted; // when the build's progress was last painted
    bool m_optionsEditing = false; // an option edit from the Options dock is being applied
    model::InstanceId m_optionsInstance = model::kNoId; // whose options the dock shows
    struct BindJob;
    std::shared_ptr<BindJob> m_bind; // the bind running on its worker thread (shared_ptr: BindJob is SkinActions.cpp's)
    ReloadPrompt m_reloadPrompt;
    widgets::SkinChunkPanel* m_chunkPanel = nullptr;
    struct ChunkImportJob;
    std::shared_ptr<ChunkImportJob> m_chunkImport; // the import running on its worker thread
    std::map<std::size_t, std::vector<session::VertexRoute>> m_routes; // per character mesh: the last import, preview or re-fit
    struct RouteColours {
        const model::Mesh* mesh = nullptr;
        bool fromRoutes = false;
        std::shared_ptr<const std::vector<glm::vec3>> colours; // the renderer uploads a new object only
    };
    std::map<std::size_t, RouteColours> m_routeColours;
    bool m_showRoutes = false;
    // What the change being followed lets the viewport send again (ChangeWiring's
    // instancesDrawnAnew); taken by refreshScene, none meaning everything.
    std::optional<std::vector<model::InstanceId>> m_sceneChanged;
    struct RefitRun;
    std::shared_ptr<RefitRun> m_refit; // the re-fit running on its worker thread
    QFileSystemWatcher* m_modelWatcher = nullptr;
    QStringList m_modelsAsked; // changed model files already offered (asked once per change)
};

} // namespace rs::app
