#include "ViewportWidget.h"

#include "ViewportSurface.h"
#include "render/Renderer.h"

#include "eval/Pickwalk.h"

#include <algorithm>
#include <QMouseEvent>
#include <QNativeGestureEvent>
#include <QPainter>
#include <QBackingStore>
#include <QFileInfo>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLPaintDevice>
#include <QVBoxLayout>
#include <QSurfaceFormat>
#include <QWheelEvent>

namespace rs::viewport {

void requestOpenGl33Core()
{
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    // 4x multisampling where a GPU draws; none on Mesa's software rasteriser
    // (no render node: llvmpipe), where it triples the cost of every frame.
    // RIGSMITH_SAMPLES=N overrides.
    const bool gpu = QFileInfo::exists(QStringLiteral("/dev/dri/renderD128")) && !qEnvironmentVariableIsSet("LIBGL_ALWAYS_SOFTWARE");
    format.setSamples(qEnvironmentVariableIsSet("RIGSMITH_SAMPLES") ? qEnvironmentVariableIntValue("RIGSMITH_SAMPLES") : gpu ? 4 : 0);
    QSurfaceFormat::setDefaultFormat(format);
}

ViewportWidget::ViewportWidget(QWidget* parent) : QWidget(parent), m_surface(new ViewportSurface(*this))
{
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(320, 240);
    QWidget* container = QWidget::createWindowContainer(m_surface, this);
    container->setAttribute(Qt::WA_TransparentForMouseEvents); // clicks land on this widget
    container->setFocusPolicy(Qt::NoFocus);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(container);
    connect(m_surface, &QOpenGLWindow::frameSwapped, this, &ViewportWidget::frameSwapped);
}

ViewportWidget::~ViewportWidget()
{
    cleanup();
}

void ViewportWidget::cleanup()
{
    if (!m_renderer || !m_surface->context())
        return;
    m_surface->makeCurrent();
    m_renderer->release();
    m_renderer.reset();
    m_surface->doneCurrent();
}

void ViewportWidget::update()
{
    m_surface->update();
}

std::uint64_t ViewportWidget::verticesUploaded() const { return m_renderer ? m_renderer->verticesUploaded() : 0; }
std::uint64_t ViewportWidget::sceneVerticesUploaded() const { return m_renderer ? m_renderer->sceneVerticesUploaded() : 0; }
std::uint64_t ViewportWidget::meshVerticesUploaded() const { return m_renderer ? m_renderer->meshVerticesUploaded() : 0; }
std::uint64_t ViewportWidget::weightVerticesUploaded() const { return m_renderer ? m_renderer->weightVerticesUploaded() : 0; }

void ViewportWidget::setScene(Scene scene, std::optional<std::vector<model::InstanceId>> changed)
{
    const std::uint64_t previous = m_sceneRevision;
    const bool rendered = m_renderer && m_renderer->sceneRevision() == previous;
    Scene::Delta delta; // all, unless only named instances changed since what the renderer holds
    if (changed && previous != 0 && rendered) {
        delta = {false, previous, std::move(*changed)};
    } else if (changed && previous != 0 && !m_scene.delta.all) { // the previous scene was never drawn: both changes
        delta = m_scene.delta;
        delta.instances.insert(delta.instances.end(), changed->begin(), changed->end());
        std::sort(delta.instances.begin(), delta.instances.end());
        delta.instances.erase(std::unique(delta.instances.begin(), delta.instances.end()), delta.instances.end());
    }
    m_scene = std::move(scene);
    m_scene.revision = ++m_sceneRevision;
    m_scene.delta = std::move(delta);
    update();
}

void ViewportWidget::frameAll()
{
    m_camera.frame(m_scene.drawnPoints(), double(width()) / std::max(1, height()));
    update();
}

QPoint ViewportWidget::toWidgetPixels(const glm::dvec3& world) const
{
    const glm::dmat4 vp = m_camera.projectionMatrix(double(width()) / std::max(1, height())) * m_camera.viewMatrix();
    glm::dvec2 p;
    projectToPixels(vp, world, width(), height(), p);
    return QPoint(int(std::lround(p.x)), int(std::lround(p.y)));
}

void ViewportWidget::frameSelection()
{
    // The selection's bounding box, not its points: a selected control's CVs
    // lie outside its curve and stay in view for CV mode.
    glm::dvec3 lo, hi;
    if (selectionBounds(m_scene, lo, hi))
        m_camera.frame(lo, hi, double(width()) / std::max(1, height()));
    else
        frameAll();
    update();
}

void ViewportWidget::setView(CameraView view)
{
    m_camera.setView(view);
    emit viewChanged(int(view));
    update();
}

void ViewportWidget::setRigMode(bool on)
{
    m_rigMode = on;
    m_gizmoTarget = model::kNoNode;
    update();
}

void ViewportWidget::setGizmoTarget(quint32 target, const glm::dmat4& world)
{
    m_gizmoTarget = target;
    if (!m_gizmoDrag) // mid-drag the gizmo stays where the drag began
        m_gizmo.target = world;
    update();
}

void ViewportWidget::setGizmoMode(GizmoMode mode)
{
    if (m_gizmo.mode == mode)
        return;
    m_gizmo.mode = mode;
    emit gizmoModeChanged(int(mode));
    update();
}

void ViewportWidget::setSelectTool(bool on)
{
    m_selectTool = on;
    update();
}

void ViewportWidget::setGizmoWorldSpace(bool world)
{
    m_gizmo.worldSpace = world;
    update();
}

std::optional<Gizmo> ViewportWidget::gizmo() const
{
    if (m_gizmoTarget == model::kNoNode || m_selectTool || m_paintMode)
        return std::nullopt;
    Gizmo g = m_gizmo;
    g.size = Gizmo::sizeFor(m_camera, g.origin(), height());
    return g;
}

void ViewportWidget::initializeGL()
{
    m_renderer = std::make_unique<Renderer>();
    std::string error;
    if (!m_renderer->initialize(error)) {
        m_renderError = QString::fromStdString(error);
        qWarning("Rigsmith viewport: %s", error.c_str());
    }
    connect(m_surface->context(), &QOpenGLContext::aboutToBeDestroyed, this, &ViewportWidget::cleanup);
}

void ViewportWidget::paintGL(int pixelWidth, int pixelHeight)
{
    m_scene.overlay.clear();
    if (const auto g = gizmo())
        m_scene.overlay = gizmoCurves(*g, m_activeHandle);
    paintOverlay();
    if (m_renderer) {
        m_renderer->render(m_scene, m_camera, pixelWidth, pixelHeight);
        for (const std::string& warning : m_renderer->takeWarnings())
            emit renderWarning(QString::fromStdString(warning));
    }
    paintLabels(pixelWidth, pixelHeight);
}

// On screen the surface shows the frame and this widget, under it, paints
// nothing. Rendered into anything else (grab(), render(): screenshots), the
// window container shows nothing, so the frame is drawn again off screen here.
void ViewportWidget::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    if ((backingStore() && painter.device() == backingStore()->paintDevice()) || !m_surface->isValid())
        return;
    m_surface->makeCurrent();
    const qreal ratio = devicePixelRatio();
    const QSize pixels(int(width() * ratio), int(height() * ratio));
    QOpenGLFramebufferObject frame(pixels, QOpenGLFramebufferObject::CombinedDepthStencil);
    frame.bind();
    paintGL(pixels.width(), pixels.height());
    QImage image = frame.toImage();
    frame.release();
    m_surface->doneCurrent();
    image.setDevicePixelRatio(ratio);
    painter.drawImage(QPointF(0.0, 0.0), image);
}

// Text and the selection box go over the GL frame with QPainter (its GL
// paint engine), in the same frame: no widget over the surface to compose.
void ViewportWidget::paintLabels(int pixelWidth, int pixelHeight)
{
    if (m_scene.labels.empty() && m_selectBox.isNull())
        return;
    QOpenGLPaintDevice device(pixelWidth, pixelHeight);
    device.setDevicePixelRatio(devicePixelRatio());
    QPainter painter(&device);
    painter.setPen(QColor(225, 225, 215));
    const glm::dmat4 vp = m_camera.projectionMatrix(double(width()) / std::max(1, height())) * m_camera.viewMatrix();
    for (const SceneLabel& label : m_scene.labels) {
        glm::dvec2 p;
        if (projectToPixels(vp, label.position, width(), height(), p))
            painter.drawText(QPointF(p.x + 7.0, p.y - 5.0), QString::fromStdString(label.text));
    }
    if (!m_selectBox.isNull()) {
        painter.setPen(QColor(235, 235, 235));
        painter.setBrush(QColor(255, 255, 255, 28));
        painter.drawRect(m_selectBox);
    }
}

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
