#pragma once
// An orbit camera (Maya style): it looks at `target` from `distance` away,
// turned by yaw/pitch (radians). Y-up, metres. Pure maths, no GL.
#include <vector>

#include <glm/glm.hpp>

namespace rs::viewport {

// The standard views (Maya's and Blender's): the front looks down -Z at a
// character facing +Z, the side down -X, the top down -Y.
enum class CameraView { Perspective, Front, Side, Top };

class Camera {
public:
    // Turns the camera to a view; the three axis views are orthographic.
    // Orbiting an orthographic view turns it back into a perspective one.
    void setView(CameraView view);
    CameraView view() const { return m_view; }
    // World units per pixel at the target (the view's scale for pan and the gizmo).
    double metresPerPixel(double viewportHeightPixels) const;
    glm::dmat4 viewMatrix() const;
    glm::dmat4 projectionMatrix(double aspect) const;
    glm::dvec3 position() const;

    // Drags in pixels: orbit turns, pan slides the target in the view plane
    // (so the point under the cursor follows it), dolly scales the distance.
    void orbit(double dxPixels, double dyPixels);
    void pan(double dxPixels, double dyPixels, double viewportHeightPixels);
    void dolly(double steps);
    // Frames a bounding box so it fills the view (width / height `aspect`):
    // the box's corners, seen from the current direction, fit both the
    // vertical and the horizontal field of view with a small margin.
    void frame(const glm::dvec3& lo, const glm::dvec3& hi, double aspect = 1.0);
    // Frames points (a rig's joints and curve points) so they fill 90% of the
    // view's height or width, whichever binds, seen from the current
    // direction: tighter than their bounding box, whose corners stick out
    // towards the camera in perspective. No points: the camera stays.
    void frame(const std::vector<glm::dvec3>& points, double aspect = 1.0);

    glm::dvec3 target{0.0, 1.0, 0.0};
    double distance = 4.0;
    double yaw = 0.5;            // around +Y, 0 looks down -Z
    double pitch = -0.3;         // negative looks down on the scene
    double fovYRadians = 0.7;
    double nearPlane = 0.01, farPlane = 1000.0;
    bool orthographic = false;

private:
    CameraView m_view = CameraView::Perspective;
};

// Projects a world point to pixel coordinates (origin top-left); z > 1 or < -1
// means outside the depth range. Returns false for points behind the camera.
bool projectToPixels(const glm::dmat4& viewProjection, const glm::dvec3& world, double width, double height,
                     glm::dvec2& pixel);

} // namespace rs::viewport
