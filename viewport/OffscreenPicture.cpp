#include "OffscreenPicture.h"

#include "render/Renderer.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QSurfaceFormat>

#include <memory>

namespace rs::viewport {

QImage renderOffscreen(const Scene& scene, const Camera& camera, int width, int height, std::string& error)
{
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    QOffscreenSurface surface;
    surface.setFormat(format);
    surface.create();
    QOpenGLContext context;
    context.setFormat(format);
    if (!surface.isValid() || !context.create()) {
        error = "no OpenGL context for an offscreen picture";
        return {};
    }
    // The caller's context (a viewport's) comes back current afterwards.
    QOpenGLContext* previous = QOpenGLContext::currentContext();
    QSurface* previousSurface = previous ? previous->surface() : nullptr;
    if (!context.makeCurrent(&surface)) {
        error = "cannot make the offscreen OpenGL context current";
        return {};
    }
    QImage image;
    {
        QOpenGLFramebufferObjectFormat fboFormat;
        fboFormat.setAttachment(QOpenGLFramebufferObject::CombinedDepthStencil);
        fboFormat.setSamples(4);
        QOpenGLFramebufferObject fbo(width, height, fboFormat);
        Renderer renderer;
        if (!fbo.isValid()) {
            error = "cannot make an offscreen framebuffer";
        } else if (renderer.initialize(error)) {
            fbo.bind();
            renderer.render(scene, camera, width, height);
            image = fbo.toImage(); // resolved from the multisampled buffer, top row first
            fbo.release();
            renderer.release();
        }
    }
    context.doneCurrent();
    if (previous && previousSurface)
        previous->makeCurrent(previousSurface);
    return image;
}

Camera pictureCamera(const Scene& scene, double aspect)
{
    Camera camera;
    camera.yaw = 0.45;
    camera.pitch = -0.2;
    camera.frame(scene.drawnPoints(), aspect);
    return camera;
}

} // namespace rs::viewport
