#include "Camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace rs::viewport {

glm::dvec3 Camera::position() const
{
    const glm::dvec3 forward(std::cos(pitch) * std::sin(yaw) * -1.0, std::sin(pitch), -std::cos(pitch) * std::cos(yaw));
    return target - forward * distance;
}

glm::dmat4 Camera::viewMatrix() const
{
    return glm::lookAt(position(), target, glm::dvec3(0.0, 1.0, 0.0));
}

glm::dmat4 Camera::projectionMatrix(double aspect) const
{
    aspect = std::max(aspect, 1e-3);
    if (orthographic) {
        const double h = distance * std::tan(fovYRadians / 2.0);
        return glm::ortho(-h * aspect, h * aspect, -h, h, -farPlane, farPlane);
    }
    return glm::perspective(fovYRadians, aspect, nearPlane, farPlane);
}

double Camera::metresPerPixel(double viewportHeightPixels) const
{
    return 2.0 * distance * std::tan(fovYRadians / 2.0) / std::max(viewportHeightPixels, 1.0);
}

void Camera::setView(CameraView view)
{
    constexpr double kHalfPi = 1.5707963267948966;
    m_view = view;
    orthographic = view != CameraView::Perspective;
    switch (view) {
    case CameraView::Perspective: yaw = 0.5; pitch = -0.3; break;
    case CameraView::Front: yaw = 0.0; pitch = 0.0; break;
    case CameraView::Side: yaw = kHalfPi; pitch = 0.0; break;
    case CameraView::Top: yaw = 0.0; pitch = -(kHalfPi - 1e-6); break;
    }
}

void Camera::orbit(double dxPixels, double dyPixels)
{
    orthographic = false;
    m_view = CameraView::Perspective;
    yaw -= dxPixels * 0.01;
    pitch = std::clamp(pitch - dyPixels * 0.01, -1.55, 1.55);
}

void Camera::pan(double dxPixels, double dyPixels, double viewportHeightPixels)
{
    const double metresPerPixel = this->metresPerPixel(viewportHeightPixels);
    const glm::dmat4 view = viewMatrix();
    const glm::dvec3 right(view[0][0], view[1][0], view[2][0]);
    const glm::dvec3 up(view[0][1], view[1][1], view[2][1]);
    target += (-dxPixels * right + dyPixels * up) * metresPerPixel;
}

void Camera::dolly(double steps)
{
    distance = std::clamp(distance * std::pow(0.85, steps), 0.05, 500.0);
}

void Camera::frame(const glm::dvec3& lo, const glm::dvec3& hi, double aspect)
{
    std::vector<glm::dvec3> corners;
    for (int corner = 0; corner < 8; ++corner)
        corners.emplace_back((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
    frame(corners, aspect);
}

void Camera::frame(const std::vector<glm::dvec3>& points, double aspect)
{
    if (points.empty())
        return;
    constexpr double kFill = 0.9; // the points take 90% of the view's height or width
    aspect = std::max(aspect, 1e-3);
    const glm::dmat4 view = viewMatrix(); // the direction only: the target moves, the angles do not
    const glm::dvec3 right(view[0][0], view[1][0], view[2][0]);
    const glm::dvec3 up(view[0][1], view[1][1], view[2][1]);
    const glm::dvec3 back(view[0][2], view[1][2], view[2][2]); // from the target towards the camera
    // The target goes to the middle of the points' extent along the view's axes.
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const glm::dvec3& p : points) {
        const glm::dvec3 v(glm::dot(p, right), glm::dot(p, up), glm::dot(p, back));
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    const glm::dvec3 middle = (lo + hi) * 0.5;
    target = right * middle.x + up * middle.y + back * middle.z;
    const double tanV = std::tan(fovYRadians / 2.0) * kFill;
    const double tanH = tanV * aspect;
    double needed = 0.0, nearest = 0.0;
    for (const glm::dvec3& p : points) {
        const glm::dvec3 d = p - target;
        const double x = std::abs(glm::dot(d, right)), y = std::abs(glm::dot(d, up));
        const double towards = glm::dot(d, back); // a point nearer the camera needs more room
        nearest = std::max(nearest, towards);
        if (orthographic)
            needed = std::max({needed, y / tanV, x / tanH});
        else
            needed = std::max({needed, y / tanV + towards, x / tanH + towards});
    }
    // Perspective: every point stays in front of the near plane, and a single point still gets a view.
    distance = std::clamp(std::max(needed, orthographic ? 0.1 : nearest + 10.0 * nearPlane), 0.1, 500.0);
}

bool projectToPixels(const glm::dmat4& viewProjection, const glm::dvec3& world, double width, double height,
                     glm::dvec2& pixel)
{
    const glm::dvec4 clip = viewProjection * glm::dvec4(world, 1.0);
    if (clip.w <= 1e-9)
        return false;
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    pixel = glm::dvec2((ndc.x * 0.5 + 0.5) * width, (1.0 - (ndc.y * 0.5 + 0.5)) * height);
    return true;
}

} // namespace rs::viewport
