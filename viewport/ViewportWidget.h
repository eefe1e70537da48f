#pragma once
// The Qt host of the Renderer: a QOpenGLWidget with an orbit camera.
// Alt+left drag or left drag on empty space orbits, middle drag pans, the wheel
// (or Alt+right drag) zooms, a left click picks, F frames the selection's scene
// and A frames all. Knows nothing about the widgets library or the app; it
// reports picks as signals carrying core ids.
#include "Camera.h"
#include "Picking.h"
#include "Scene.h"

#include <QOpenGLWidget>

#include <memory>

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

signals:
    void guideJointPicked(quint32 joint, quint32 owner);
    void controllerPicked(quint32 node);
    void nothingPicked();

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
    QString m_renderError;
};

// Must run before the QApplication is created: asks for OpenGL 3.3 core.
void requestOpenGl33Core();

} // namespace rs::viewport
