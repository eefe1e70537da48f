#pragma once
// A picture of a scene without a window: an offscreen OpenGL 3.3 core context
// (Qt), a framebuffer object and the viewport's renderer. The help pages show
// each template's built rig this way. Needs a running QGuiApplication.
#include "Camera.h"
#include "Scene.h"

#include <QImage>

#include <string>

namespace rs::viewport {

// The scene seen by `camera` as a `width` x `height` image; a null image with
// `error` set when no suitable context or framebuffer can be made.
QImage renderOffscreen(const Scene& scene, const Camera& camera, int width, int height, std::string& error);

// A camera in front of the scene, turned a little to its side and looking
// slightly down, framing everything drawn.
Camera pictureCamera(const Scene& scene, double aspect);

} // namespace rs::viewport
