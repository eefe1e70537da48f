// ViewportWidget, the viewport's Qt host: the GL surface and the frame it
// draws (on screen, and again off screen for grab()), the scene and camera it
// shows, the gizmo, and the labels and selection box over the frame. Mouse
// and keys: ViewportInput.cpp; weight paint mode: ViewportPaint.cpp.
#include "ViewportWidget.h"

#include "ViewportSurface.h"
#include "render/Renderer.h"

#include <algorithm>
#include <QPainter>
#include <QBackingStore>
#include <QFileInfo>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLPaintDevice>
#include <QVBoxLayout>
#include <QSurfaceFormat>

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

} // namespace rs::viewport
