#pragma once
// The Qt host of the Renderer: a QOpenGLWidget with an orbit camera.
// Alt+left drag orbits (in Guide mode a left drag on empty space too), middle
// drag pans, the wheel (or Alt+right drag) zooms, a left click picks, F frames
// the selection's scene and A frames all. In Rig mode a left drag on empty
// space box-selects controllers (Shift adds), W/E/R pick the gizmo (translate,
// rotate, scale) whose handles drag the selected controller, the arrow keys
// pickwalk and M walks to the mirror twin. Knows nothing about the widgets
// library or the app; it reports picks, walks and drags as signals carrying
// core ids and world matrices.
#include "Camera.h"
#include "Manipulator.h"
#include "Picking.h"
#include "Scene.h"

#include <QOpenGLWidget>

#include <memory>
#include <optional>

class QRubberBand;

namespace rs::viewport {

class Renderer;

class ViewportWidget : public QOpenGLWidget {
    Q_OBJECT
public:
    explicit ViewportWidget(QWidget* parent = nullptr);
    ~ViewportWidget() override;

    void setScene(Scene scene);
    const Scene& scene() const { return m_scene; }
    Camera& camera() { return m_camera; }
    void frameAll();
    // Where a world point lands in widget pixels (for tests and tools).
    QPoint toWidgetPixels(const glm::dvec3& world) const;
    QString renderError() const { return m_renderError; }

    void setRigMode(bool on);
    bool isRigMode() const { return m_rigMode; }
    // The controller the gizmo drags and its world matrix; kNoNode hides it.
    void setGizmoTarget(model::RigNodeIndex node, const glm::dmat4& world);
    void setGizmoMode(GizmoMode mode);
    GizmoMode gizmoMode() const { return m_gizmo.mode; }
    void setGizmoWorldSpace(bool world);
    // The gizmo as drawn (size for the current camera); nullopt when hidden.
    std::optional<Gizmo> gizmo() const;

signals:
    void guideJointPicked(quint32 joint, quint32 owner);
    void controllerPicked(quint32 node, bool add);
    void controllersBoxSelected(const QList<quint32>& nodes, bool add);
    void nothingPicked();
    void pickwalkRequested(int direction); // an rs::eval::WalkDirection
    void gizmoModeChanged(int mode);       // a GizmoMode
    void gizmoDragStarted(quint32 node);
    void gizmoDragged(quint32 node, const glm::dmat4& world);
    void gizmoDragFinished(quint32 node);

protected:
    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    void cleanup();

    std::unique_ptr<Renderer> m_renderer;
    Scene m_scene;
    Camera m_camera;
    QPoint m_pressPosition, m_lastPosition;
    Qt::MouseButton m_dragButton = Qt::NoButton;
    bool m_dragged = false;
    bool m_orbiting = false;
    QString m_renderError;
    bool m_rigMode = false;
    Gizmo m_gizmo;
    model::RigNodeIndex m_gizmoNode = model::kNoNode;
    std::optional<GizmoDrag> m_gizmoDrag;
    int m_activeHandle = -1;
    QRubberBand* m_rubberBand = nullptr;
};

// Must run before the QApplication is created: asks for OpenGL 3.3 core.
void requestOpenGl33Core();

} // namespace rs::viewport
