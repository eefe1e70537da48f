// ViewportWidget's weight paint mode: brush strokes, vertex selection, the
// brush radius keys and the brush circle. Camera buttons are handled before
// these are asked, so navigation works as in every other mode.
#include "ViewportWidget.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QRubberBand>

#include <algorithm>
#include <cmath>

namespace rs::viewport {

namespace {
const glm::dvec3 kBrushColor(1.0, 1.0, 1.0);
const glm::dvec3 kResizeColor(1.0, 0.85, 0.2);
constexpr double kDabSpacing = 0.25; // of the radius
} // namespace

void ViewportWidget::setPaintMode(bool on)
{
    if (m_paintMode == on)
        return;
    m_paintMode = on;
    m_painting = m_stroking = m_resizing = false;
    m_hover.reset();
    m_posedValid = false;
    setMouseTracking(on); // the brush circle follows the cursor
    setCursor(on ? Qt::CrossCursor : Qt::ArrowCursor);
    update();
}

void ViewportWidget::setPaintTool(PaintTool tool)
{
    m_paintTool = tool;
    update();
}

void ViewportWidget::setBrushRadius(double metres)
{
    metres = std::clamp(metres, 0.001, 10.0);
    if (metres == m_brushRadius)
        return;
    m_brushRadius = metres;
    emit brushRadiusChanged(metres);
    update();
}

const PosedCharacter& ViewportWidget::posedCharacter()
{
    // Mid-stroke the pose the stroke began on is kept: each dab changes the
    // weights (a new scene), and re-skinning per dab would cost for nothing.
    if (!m_posedValid || (!m_stroking && m_posed.sceneRevision != m_scene.revision)) {
        m_posed = PosedCharacter::of(m_scene);
        m_posedValid = true;
    }
    return m_posed;
}

std::optional<MeshHit> ViewportWidget::meshHitAt(QPoint pixel)
{
    return hitCharacter(posedCharacter(), rayThroughPixel(m_camera, width(), height(), glm::dvec2(pixel.x(), pixel.y())));
}

bool ViewportWidget::paintPress(QMouseEvent* event)
{
    if (!m_paintMode)
        return false;
    if (m_resizeKey) {
        m_resizing = true;
        m_resizeStart = m_brushRadius;
        return true;
    }
    if (m_paintTool != PaintTool::Brush)
        return false; // select-vertices: a click or a box, on release
    m_painting = true;
    m_stroking = false;
    const Qt::KeyboardModifiers mods = event->modifiers();
    m_stroke = int(mods & Qt::ShiftModifier ? PaintStroke::Smooth : mods & Qt::ControlModifier ? PaintStroke::Subtract : PaintStroke::Tool);
    m_posedValid = false; // the pose as it is now
    const QPoint p = event->position().toPoint();
    dabAlong(p, p);
    return true;
}

void ViewportWidget::dabAlong(QPoint from, QPoint to)
{
    // Samples the drag every few pixels, so a fast drag still leaves its dabs
    // along the surface rather than only where the move events land.
    const int steps = std::clamp((to - from).manhattanLength() / 4, 1, 16);
    const double spacing = m_brushRadius * kDabSpacing;
    for (int i = 1; i <= steps; ++i) {
        const QPointF pixel = QPointF(from) + QPointF(to - from) * (double(i) / steps);
        const auto hit = hitCharacter(posedCharacter(), rayThroughPixel(m_camera, width(), height(), glm::dvec2(pixel.x(), pixel.y())));
        m_hover = hit;
        if (!hit)
            continue;
        if (!m_stroking) {
            m_stroking = true;
            emit paintStrokeStarted(m_stroke);
        } else if (glm::distance(hit->point, m_lastDab) < spacing) {
            continue;
        }
        m_lastDab = hit->point;
        emit paintDabbed(quint64(hit->characterMesh), hit->point, hit->vertex);
    }
    update();
}

bool ViewportWidget::paintMove(QMouseEvent* event)
{
    if (!m_paintMode)
        return false;
    const QPoint p = event->position().toPoint();
    if (m_resizing) {
        setBrushRadius(m_resizeStart * std::exp((p.x() - m_pressPosition.x()) / 150.0));
        m_lastPosition = p;
        return true;
    }
    if (m_painting) {
        dabAlong(m_lastPosition, p);
        m_lastPosition = p;
        return true;
    }
    if (event->buttons() != Qt::NoButton)
        return false; // a camera drag or a select box
    m_hover = meshHitAt(p);
    update();
    return true;
}

bool ViewportWidget::paintRelease(QMouseEvent* event)
{
    if (!m_paintMode || event->button() != Qt::LeftButton || m_cameraDrag != CameraDrag::None)
        return false;
    if (m_resizing) {
        m_resizing = false;
        return true;
    }
    if (m_painting) {
        m_painting = false;
        if (m_stroking) {
            m_stroking = false;
            emit paintStrokeFinished();
        }
        return true;
    }
    if (m_paintTool != PaintTool::SelectVertices)
        return false;
    const bool add = event->modifiers() & Qt::ShiftModifier;
    if (m_dragged) {
        m_selectBox = QRect();
        const glm::dvec2 a(m_pressPosition.x(), m_pressPosition.y()), b(event->position().x(), event->position().y());
        emit verticesSelected(boxPickVertices(posedCharacter(), m_camera, width(), height(), a, b), add);
    } else if (const auto hit = meshHitAt(event->position().toPoint())) {
        emit verticesSelected({{hit->characterMesh, {hit->vertex}}}, add);
    } else {
        emit verticesSelected({}, add);
    }
    return true;
}

bool ViewportWidget::paintKey(QKeyEvent* event)
{
    if (!m_paintMode || (event->modifiers() & ~Qt::KeypadModifier) != Qt::NoModifier)
        return false;
    if (event->key() == Qt::Key_B) {
        m_resizeKey = true;
        update();
    } else if (event->key() == Qt::Key_BracketLeft) {
        setBrushRadius(m_brushRadius / 1.25);
    } else if (event->key() == Qt::Key_BracketRight) {
        setBrushRadius(m_brushRadius * 1.25);
    } else {
        return false;
    }
    return true;
}

void ViewportWidget::keyReleaseEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_B && !event->isAutoRepeat()) {
        m_resizeKey = false;
        update();
        return;
    }
    QWidget::keyReleaseEvent(event);
}

void ViewportWidget::paintOverlay()
{
    m_scene.overlayPoints.clear();
    if (!m_paintMode)
        return;
    if (m_paintTool == PaintTool::Brush && m_hover)
        m_scene.overlay.push_back(brushCircle(m_hover->point, m_hover->normal, m_brushRadius, m_resizeKey ? kResizeColor : kBrushColor));
    const bool anySelected = std::any_of(m_scene.meshes.begin(), m_scene.meshes.end(),
                                         [](const SceneMesh& mesh) { return !mesh.selectedVertices.empty(); });
    if (anySelected)
        m_scene.overlayPoints = selectedVertexPositions(m_scene, posedCharacter());
}

} // namespace rs::viewport
