// ViewportWidget's mouse and keyboard: camera drags (Maya's buttons, or
// Blender's with that navigation), clicks and box selection, the gizmo's
// handle drags, the wheel, the trackpad's scroll and pinch, the view keys
// (F, A, 1 / 3 / 7, 5 / 0), the gizmo keys (W/E/R, Q) and Rig mode's
// pickwalk keys. Weight paint mode's own input: ViewportPaint.cpp.
#include "ViewportWidget.h"

#include "ViewportSurface.h"
#include "render/Renderer.h"

#include "eval/Pickwalk.h"

#include <algorithm>
#include <QMouseEvent>
#include <QNativeGestureEvent>
#include <QWheelEvent>

namespace rs::viewport {

ViewportWidget::CameraDrag ViewportWidget::cameraDragFor(Qt::MouseButton button, Qt::KeyboardModifiers modifiers) const
{
    const bool alt = modifiers & Qt::AltModifier;
    if (button == Qt::LeftButton)
        return alt ? CameraDrag::Orbit : CameraDrag::None;
    if (button == Qt::MiddleButton) {
        if (m_navigation != Navigation::Blender)
            return CameraDrag::Pan;
        if (modifiers & Qt::ShiftModifier)
            return CameraDrag::Pan;
        return modifiers & Qt::ControlModifier ? CameraDrag::Dolly : CameraDrag::Orbit;
    }
    if (button == Qt::RightButton && alt)
        return CameraDrag::Dolly;
    return CameraDrag::None;
}

void ViewportWidget::mousePressEvent(QMouseEvent* event)
{
    m_pressPosition = m_lastPosition = event->position().toPoint();
    m_dragButton = event->button();
    m_dragged = false;
    m_cameraDrag = cameraDragFor(event->button(), event->modifiers());
    if (event->button() != Qt::LeftButton || m_cameraDrag != CameraDrag::None)
        return;
    if (paintPress(event))
        return;
    const glm::dvec2 pixel(event->position().x(), event->position().y());
    if (const auto g = gizmo()) {
        const int handle = pickGizmoHandle(*g, m_camera, width(), height(), pixel);
        if (handle >= 0) {
            m_gizmoDrag.emplace(*g, handle, rayThroughPixel(m_camera, width(), height(), pixel));
            m_activeHandle = handle;
            emit gizmoDragStarted(m_gizmoTarget);
            update();
        }
    }
}

void ViewportWidget::mouseMoveEvent(QMouseEvent* event)
{
    if (paintMove(event))
        return;
    const QPoint p = event->position().toPoint();
    const QPoint delta = p - m_lastPosition;
    m_lastPosition = p;
    if ((p - m_pressPosition).manhattanLength() > 3)
        m_dragged = true;
    if (!m_dragged)
        return;
    if (m_gizmoDrag) {
        const Ray ray = rayThroughPixel(m_camera, width(), height(), glm::dvec2(p.x(), p.y()));
        emit gizmoDragged(m_gizmoTarget, m_gizmoDrag->worldFor(ray));
        return;
    }
    const bool wasOrtho = m_camera.orthographic;
    if (m_dragButton == Qt::LeftButton && m_cameraDrag == CameraDrag::None) { // box select
        m_selectBox = QRect(m_pressPosition, p).normalized();
        update();
        return;
    }
    if (m_cameraDrag == CameraDrag::Orbit)
        m_camera.orbit(delta.x(), delta.y());
    else if (m_cameraDrag == CameraDrag::Pan)
        m_camera.pan(delta.x(), delta.y(), height());
    else if (m_cameraDrag == CameraDrag::Dolly)
        m_camera.dolly((delta.x() - delta.y()) * 0.05);
    if (wasOrtho && !m_camera.orthographic)
        emit viewChanged(int(m_camera.view()));
    update();
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event)
{
    const bool add = event->modifiers() & Qt::ShiftModifier;
    if (paintRelease(event)) {
        m_dragButton = Qt::NoButton;
        m_cameraDrag = CameraDrag::None;
        update();
        return;
    }
    if (m_gizmoDrag) {
        m_gizmoDrag.reset();
        m_activeHandle = -1;
        emit gizmoDragFinished(m_gizmoTarget);
    } else if (event->button() == Qt::LeftButton && m_dragged && m_cameraDrag == CameraDrag::None) {
        m_selectBox = QRect();
        const glm::dvec2 a(m_pressPosition.x(), m_pressPosition.y()), b(event->position().x(), event->position().y());
        if (m_rigMode) {
            const auto nodes = boxPick(m_scene, m_camera, width(), height(), a, b);
            emit controllersBoxSelected(QList<quint32>(nodes.begin(), nodes.end()), add);
        } else if (!m_scene.cvs.empty()) {
            emit cvsSelected(boxPickCvs(m_scene, m_camera, width(), height(), a, b), add);
        } else {
            const auto joints = boxPickJoints(m_scene, m_camera, width(), height(), a, b);
            emit guideJointsBoxSelected(QList<quint32>(joints.begin(), joints.end()), add);
        }
    } else if (event->button() == Qt::LeftButton && !m_dragged) {
        const PickResult hit = pick(m_scene, m_camera, width(), height(),
                                    glm::dvec2(event->position().x(), event->position().y()));
        if (hit.kind == PickResult::Kind::Cv)
            emit cvsSelected(coincidentCvs(m_scene, hit.cv), add);
        else if (hit.kind == PickResult::Kind::GuideJoint)
            emit guideJointPicked(hit.joint, hit.owner, add);
        else if (hit.kind == PickResult::Kind::Controller)
            emit controllerPicked(hit.node, add);
        else if (!add)
            emit nothingPicked();
    }
    m_dragButton = Qt::NoButton;
    m_cameraDrag = CameraDrag::None;
    update();
}

void ViewportWidget::wheelEvent(QWheelEvent* event)
{
    const bool wasOrtho = m_camera.orthographic;
    if (m_navigation != Navigation::Touchpad || event->modifiers() & Qt::ControlModifier) {
        m_camera.dolly(event->angleDelta().y() / 120.0);
    } else {
        // A two-finger scroll: pixels where the platform gives them, else 120 per notch = 15 pixels.
        const QPoint pixels = event->pixelDelta().isNull() ? event->angleDelta() / 8 : event->pixelDelta();
        if (event->modifiers() & Qt::ShiftModifier)
            m_camera.pan(-pixels.x(), -pixels.y(), height());
        else
            m_camera.orbit(-pixels.x(), -pixels.y());
    }
    if (wasOrtho && !m_camera.orthographic)
        emit viewChanged(int(m_camera.view()));
    update();
}

bool ViewportWidget::event(QEvent* event)
{
    if (event->type() == QEvent::NativeGesture) {
        auto* gesture = static_cast<QNativeGestureEvent*>(event);
        if (gesture->gestureType() == Qt::ZoomNativeGesture) {
            m_camera.dolly(gesture->value() * 10.0);
            update();
            return true;
        }
    }
    return QWidget::event(event);
}

bool ViewportWidget::handleViewKey(QKeyEvent* event)
{
    if ((event->modifiers() & ~Qt::KeypadModifier) != Qt::NoModifier)
        return false;
    const std::pair<int, CameraView> views[] = {{Qt::Key_1, CameraView::Front}, {Qt::Key_3, CameraView::Side},
                                                {Qt::Key_7, CameraView::Top},   {Qt::Key_5, CameraView::Perspective},
                                                {Qt::Key_0, CameraView::Perspective}};
    for (const auto& [key, view] : views)
        if (event->key() == key) {
            setView(view);
            return true;
        }
    if (event->key() == Qt::Key_F)
        frameSelection();
    else if (event->key() == Qt::Key_A)
        frameAll();
    else
        return false;
    return true;
}

void ViewportWidget::keyPressEvent(QKeyEvent* event)
{
    if (handleViewKey(event) || paintKey(event))
        return;
    const std::pair<int, GizmoMode> gizmoKeys[] = {
        {Qt::Key_W, GizmoMode::Translate}, {Qt::Key_E, GizmoMode::Rotate}, {Qt::Key_R, GizmoMode::Scale}};
    for (const auto& [key, mode] : gizmoKeys)
        if (event->key() == key && event->modifiers() == Qt::NoModifier) {
            setGizmoMode(mode);
            setSelectTool(false);
            return;
        }
    if (event->key() == Qt::Key_Q && event->modifiers() == Qt::NoModifier) {
        setSelectTool(true);
        return;
    }
    if (m_rigMode) {
        using eval::WalkDirection;
        const std::pair<int, WalkDirection> walkKeys[] = {{Qt::Key_Up, WalkDirection::Up},     {Qt::Key_Down, WalkDirection::Down},
                                                          {Qt::Key_Left, WalkDirection::Left}, {Qt::Key_Right, WalkDirection::Right},
                                                          {Qt::Key_M, WalkDirection::Mirror}};
        for (const auto& [key, direction] : walkKeys)
            if (event->key() == key) {
                emit pickwalkRequested(int(direction));
                return;
            }
    }
    QWidget::keyPressEvent(event);
}

} // namespace rs::viewport
