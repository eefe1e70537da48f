#include "ViewportWidget.h"

#include "render/Renderer.h"

#include <QMouseEvent>
#include <QOpenGLContext>
#include <QSurfaceFormat>
#include <QWheelEvent>

namespace rs::viewport {

void requestOpenGl33Core()
{
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setSamples(4);
    QSurfaceFormat::setDefaultFormat(format);
}

ViewportWidget::ViewportWidget(QWidget* parent) : QOpenGLWidget(parent)
{
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(320, 240);
}

ViewportWidget::~ViewportWidget()
{
    cleanup();
}

void ViewportWidget::cleanup()
{
    if (!m_renderer || !context())
        return;
    makeCurrent();
    m_renderer->release();
    m_renderer.reset();
    doneCurrent();
}

void ViewportWidget::setScene(Scene scene)
{
    m_scene = std::move(scene);
    update();
}

void ViewportWidget::frameAll()
{
    glm::dvec3 lo, hi;
    if (m_scene.bounds(lo, hi))
        m_camera.frame(lo, hi);
    update();
}

QPoint ViewportWidget::toWidgetPixels(const glm::dvec3& world) const
{
    const glm::dmat4 vp = m_camera.projectionMatrix(double(width()) / std::max(1, height())) * m_camera.viewMatrix();
    glm::dvec2 p;
    projectToPixels(vp, world, width(), height(), p);
    return QPoint(int(std::lround(p.x)), int(std::lround(p.y)));
}

void ViewportWidget::initializeGL()
{
    m_renderer = std::make_unique<Renderer>();
    std::string error;
    if (!m_renderer->initialize(error)) {
        m_renderError = QString::fromStdString(error);
        qWarning("Rigsmith viewport: %s", error.c_str());
    }
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &ViewportWidget::cleanup);
}

void ViewportWidget::paintGL()
{
    if (m_renderer)
        m_renderer->render(m_scene, m_camera, int(width() * devicePixelRatio()), int(height() * devicePixelRatio()));
}

void ViewportWidget::mousePressEvent(QMouseEvent* event)
{
    m_pressPosition = m_lastPosition = event->position().toPoint();
    m_dragButton = event->button();
    m_dragged = false;
}

void ViewportWidget::mouseMoveEvent(QMouseEvent* event)
{
    const QPoint p = event->position().toPoint();
    const QPoint delta = p - m_lastPosition;
    m_lastPosition = p;
    if ((p - m_pressPosition).manhattanLength() > 3)
        m_dragged = true;
    if (!m_dragged)
        return;
    const bool alt = event->modifiers() & Qt::AltModifier;
    if (m_dragButton == Qt::LeftButton)
        m_camera.orbit(delta.x(), delta.y());
    else if (m_dragButton == Qt::MiddleButton)
        m_camera.pan(delta.x(), delta.y(), height());
    else if (m_dragButton == Qt::RightButton && alt)
        m_camera.dolly(delta.x() * 0.05);
    update();
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton && !m_dragged) {
        const PickResult hit = pick(m_scene, m_camera, width(), height(),
                                    glm::dvec2(event->position().x(), event->position().y()));
        if (hit.kind == PickResult::Kind::GuideJoint)
            emit guideJointPicked(hit.joint, hit.owner);
        else if (hit.kind == PickResult::Kind::Controller)
            emit controllerPicked(hit.node);
        else
            emit nothingPicked();
    }
    m_dragButton = Qt::NoButton;
}

void ViewportWidget::wheelEvent(QWheelEvent* event)
{
    m_camera.dolly(event->angleDelta().y() / 120.0);
    update();
}

void ViewportWidget::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_A || event->key() == Qt::Key_F) {
        frameAll();
        return;
    }
    QOpenGLWidget::keyPressEvent(event);
}

} // namespace rs::viewport
