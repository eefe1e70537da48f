#include "ViewportSurface.h"

#include "ViewportWidget.h"

#include <QCoreApplication>

namespace rs::viewport {

ViewportSurface::ViewportSurface(ViewportWidget& view) : m_view(view)
{
    setFlag(Qt::WindowTransparentForInput);
}

void ViewportSurface::initializeGL() { m_view.initializeGL(); }

void ViewportSurface::paintGL()
{
    const qreal ratio = devicePixelRatio();
    m_view.paintGL(int(width() * ratio), int(height() * ratio));
}

bool ViewportSurface::event(QEvent* event)
{
    switch (event->type()) {
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonRelease:
    case QEvent::MouseButtonDblClick:
    case QEvent::MouseMove:
    case QEvent::Wheel:
    case QEvent::KeyPress:
    case QEvent::KeyRelease:
    case QEvent::NativeGesture:
        // The surface and the widget share their origin and size: positions hold.
        return QCoreApplication::sendEvent(&m_view, event);
    default:
        return QOpenGLWindow::event(event);
    }
}

} // namespace rs::viewport
