#pragma once
// The Qt host of the Renderer: a widget with an orbit camera, as in
// Maya by default (Navigation::Maya): Alt+left drag orbits, middle drag pans,
// the wheel (or Alt+right drag) zooms. Navigation::Blender: middle drag
// orbits, Shift+middle pans, Ctrl+middle zooms. Navigation::Touchpad: a
// two-finger scroll orbits, Shift+scroll pans, Ctrl+scroll or a pinch zooms
// (Alt+left drag still orbits in every scheme). A left click picks (Shift adds), a left drag on empty
// space box-selects (guide joints in Guide mode, the shown CVs in CV mode,
// controllers in Rig mode), F
// frames the selection and A frames all; 1 / 3 / 7 turn to the front, side and
// top orthographic views and 5 (or 0) back to perspective, as Blender's keypad.
// W/E/R pick the gizmo (translate, rotate, scale; Q hides it) whose handles drag the
// target the app sets (a guide joint, a shape, CVs or a controller). In Rig mode the arrow
// keys pickwalk and M walks to the mirror twin. In paint mode (setPaintMode,
// ViewportPaint.cpp) the left button paints weights on the character's meshes
// as drawn (posed in Rig mode, the bind pose in Guide mode) or, with the
// select-vertices tool, picks and box-selects mesh vertices; the camera keys
// and buttons work as always. Knows nothing about the
// widgets library or the app; it reports picks, walks and drags as signals
// carrying core ids and world matrices.
//
// It draws through a QOpenGLWindow in a window container (ViewportSurface),
// not a QOpenGLWidget: a QOpenGLWidget makes Qt compose the whole main window
// with GL on every frame (the widgets' backing store blended over the GL
// texture), which on a software rasteriser cost about 35 ms of CPU per frame;
// the window swaps only its own pixels. The surface ignores input: the mouse,
// the wheel and the keys reach this widget as before. Labels, the selection box
// and everything else are drawn into the same GL frame; grab() (screenshots)
// includes the frame, rendered again off screen.
#include "Camera.h"
#include "Manipulator.h"
#include "Picking.h"
#include "Scene.h"
#include "WeightPaint.h"

#include <QWidget>

#include <memory>
#include <optional>


namespace rs::viewport {

class Renderer;
class ViewportSurface;

// How mouse buttons and the wheel move the camera (see the class comment).
enum class Navigation { Maya, Blender, Touchpad };

// Paint mode's left button: paint with the brush, or select vertices.
enum class PaintTool { Brush, SelectVertices };
// What a stroke's modifiers ask for: the panel's tool, Ctrl subtracts, Shift smooths.
enum class PaintStroke { Tool, Subtract, Smooth };

class ViewportWidget : public QWidget {
    Q_OBJECT
public:
    explicit ViewportWidget(QWidget* parent = nullptr);
    ~ViewportWidget() override;

    // Asks for a new frame (hides QWidget::update: the frame is the GL
    // surface's). Call through a ViewportWidget pointer.
    void update();

    // A new scene to draw. With `changed` (the instances a change touched,
    // sorted, unique), only what they own differs from the previous scene, and
    // the renderer sends only their vertices (Scene::delta); without it, all.
    void setScene(Scene scene, std::optional<std::vector<model::InstanceId>> changed = std::nullopt);
    const Scene& scene() const { return m_scene; }
    // Vertices the renderer has sent to the GPU (0 before the first frame).
    std::uint64_t verticesUploaded() const;
    std::uint64_t sceneVerticesUploaded() const; // of them, the scene layers (Renderer::sceneVerticesUploaded)
    // Mesh vertices and vertex weights sent so far: posing sends neither.
    std::uint64_t meshVerticesUploaded() const;
    std::uint64_t weightVerticesUploaded() const;
    Camera& camera() { return m_camera; }
    const Camera& camera() const { return m_camera; }
    void frameAll();
    // Where a world point lands in widget pixels (for tests and tools).
    QPoint toWidgetPixels(const glm::dvec3& world) const;
    QString renderError() const { return m_renderError; }

    void setRigMode(bool on);
    bool isRigMode() const { return m_rigMode; }
    // What the gizmo drags (a guide joint id in Guide mode, a controller's
    // node index in Rig mode) and its world matrix; kNoNode hides it.
    void setGizmoTarget(quint32 target, const glm::dmat4& world);
    void setView(CameraView view);
    // Frames the selected guide joints or controllers (everything when none).
    void frameSelection();
    void setGizmoMode(GizmoMode mode);
    GizmoMode gizmoMode() const { return m_gizmo.mode; }
    void setGizmoWorldSpace(bool world);
    // Maya's select tool (Q): no gizmo, so clicks near the selection pick
    // rather than grab a handle; W/E/R bring the gizmo back.
    void setSelectTool(bool on);
    bool isSelectTool() const { return m_selectTool; }
    // The gizmo as drawn (size for the current camera); nullopt when hidden.
    std::optional<Gizmo> gizmo() const;
    void setNavigation(Navigation navigation) { m_navigation = navigation; }
    Navigation navigation() const { return m_navigation; }

    // Weight painting (ViewportPaint.cpp). In the brush tool a left drag on a
    // mesh is one stroke: paintStrokeStarted, a paintDabbed every quarter
    // radius along the drag (the first where the press hits), then
    // paintStrokeFinished. Ctrl+drag subtracts, Shift+drag smooths. B+drag
    // (right: larger) or [ and ] change the radius. In the select-vertices
    // tool a click picks the vertex nearest the hit, a drag box-selects the
    // vertices facing the camera (Shift adds). The mesh is posed on the CPU
    // once per stroke (and when the scene changes between strokes).
    void setPaintMode(bool on);
    bool isPaintMode() const { return m_paintMode; }
    void setPaintTool(PaintTool tool);
    PaintTool paintTool() const { return m_paintTool; }
    void setBrushRadius(double metres); // clamped to [0.001, 10]
    double brushRadius() const { return m_brushRadius; }
    // The mesh under a widget pixel, as painting sees it (tests and tools).
    std::optional<MeshHit> meshHitAt(QPoint pixel);

signals:
    void guideJointPicked(quint32 joint, quint32 owner, bool add);
    void guideJointsBoxSelected(const QList<quint32>& joints, bool add);
    void controllerPicked(quint32 node, bool add);
    // CV mode: a click on a CV (one, add toggles) or a box around several.
    void cvsSelected(const std::vector<rs::model::CurveCv>& cvs, bool add);
    void controllersBoxSelected(const QList<quint32>& nodes, bool add);
    void nothingPicked();
    void pickwalkRequested(int direction); // an rs::eval::WalkDirection
    void gizmoModeChanged(int mode);       // a GizmoMode
    void gizmoDragStarted(quint32 target);
    void gizmoDragged(quint32 target, const glm::dmat4& world);
    void gizmoDragFinished(quint32 target);
    void viewChanged(int view); // a CameraView
    void paintStrokeStarted(int stroke); // a PaintStroke
    // One dab on characterMeshes()[mesh]: the hit point and its nearest vertex.
    void paintDabbed(quint64 mesh, const glm::dvec3& centre, quint32 vertex);
    void paintStrokeFinished();
    // Select-vertices tool: per character mesh, the vertices clicked or boxed (empty: nothing hit).
    void verticesSelected(const rs::viewport::VertexSelection& vertices, bool add);
    void brushRadiusChanged(double metres);
    // A drawing problem the rigger should know of (an unreadable texture), once each.
    void renderWarning(const QString& message);
    // A frame reached the screen (swapped): tests and latency measurements wait for it.
    void frameSwapped();

protected:
    void paintEvent(QPaintEvent* event) override; // only for grab(): the frame drawn off screen
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    bool event(QEvent* event) override; // pinch to zoom

private:
    friend class ViewportSurface;
    void initializeGL();
    void paintGL(int pixelWidth, int pixelHeight);
    enum class CameraDrag { None, Orbit, Pan, Dolly };
    CameraDrag cameraDragFor(Qt::MouseButton button, Qt::KeyboardModifiers modifiers) const;
    void cleanup();
    bool handleViewKey(QKeyEvent* event);
    void paintLabels(int pixelWidth, int pixelHeight); // and the selection box, with QPainter over GL
    // Paint mode's mouse and keys (ViewportPaint.cpp); true when handled.
    bool paintPress(QMouseEvent* event);
    bool paintMove(QMouseEvent* event);
    bool paintRelease(QMouseEvent* event);
    bool paintKey(QKeyEvent* event);
    void paintOverlay();                // the brush circle and the selected vertices
    const PosedCharacter& posedCharacter(); // the scene's meshes as drawn, made again when the scene changed
    void dabAlong(QPoint from, QPoint to); // dabs spaced along a drag

    std::unique_ptr<Renderer> m_renderer;
    Scene m_scene;
    std::uint64_t m_sceneRevision = 0;
    Camera m_camera;
    QPoint m_pressPosition, m_lastPosition;
    Qt::MouseButton m_dragButton = Qt::NoButton;
    bool m_dragged = false;
    CameraDrag m_cameraDrag = CameraDrag::None;
    Navigation m_navigation = Navigation::Maya;
    QString m_renderError;
    bool m_rigMode = false;
    Gizmo m_gizmo;
    quint32 m_gizmoTarget = model::kNoNode;
    std::optional<GizmoDrag> m_gizmoDrag;
    bool m_selectTool = false;
    int m_activeHandle = -1;
    ViewportSurface* m_surface = nullptr; // owned by its window container, a child of this widget
    QRect m_selectBox;                    // a box select under way (widget pixels), null when none
    bool m_paintMode = false;
    PaintTool m_paintTool = PaintTool::Brush;
    double m_brushRadius = 0.05;
    PosedCharacter m_posed;
    bool m_posedValid = false;
    bool m_painting = false;         // the left button is down with the brush tool
    bool m_stroking = false;         // ... and a stroke has started (it hit a mesh)
    int m_stroke = 0;                // PaintStroke of the stroke under way
    glm::dvec3 m_lastDab{0.0};
    std::optional<MeshHit> m_hover;  // under the cursor (the brush circle)
    bool m_resizeKey = false;        // B held
    bool m_resizing = false;         // B+drag under way
    double m_resizeStart = 0.0;
};

// Must run before the QApplication is created: asks for OpenGL 3.3 core.
void requestOpenGl33Core();

} // namespace rs::viewport
