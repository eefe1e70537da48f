#pragma once
// The GL surface a ViewportWidget draws into: a QOpenGLWindow shown in a
// window container that fills the widget. It swaps only its own pixels, where
// a QOpenGLWidget would have Qt compose the whole main window through GL on
// every frame. It takes no input (Qt::WindowTransparentForInput): the mouse,
// the wheel and the keys go to the ViewportWidget under it, with its focus and
// the main window's shortcuts; on a platform that delivers input to it anyway,
// it hands the events to the widget. The widget owns the Renderer; the
// surface owns the GL context (made when it is first shown).
#include <QOpenGLWindow>

namespace rs::viewport {

class ViewportWidget;

class ViewportSurface : public QOpenGLWindow {
public:
    explicit ViewportSurface(ViewportWidget& view);

protected:
    void initializeGL() override;
    void paintGL() override;
    bool event(QEvent* event) override;

private:
    ViewportWidget& m_view;
};

} // namespace rs::viewport
