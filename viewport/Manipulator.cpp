#include "Manipulator.h"

#include "Picking.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace rs::viewport {

namespace {

constexpr int kCircleSegments = 48;

const glm::dvec3 kAxisColors[3] = {{0.95, 0.25, 0.25}, {0.35, 0.9, 0.3}, {0.3, 0.5, 1.0}};
const glm::dvec3 kActiveColor(1.0, 0.9, 0.2);

// Two unit vectors perpendicular to `a` and to each other.
void basisAround(const glm::dvec3& a, glm::dvec3& u, glm::dvec3& v)
{
    u = glm::normalize(glm::cross(a, std::abs(a.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0)));
    v = glm::cross(a, u);
}

} // namespace

Ray rayThroughPixel(const Camera& camera, double width, double height, glm::dvec2 pixel)
{
    const glm::dmat4 inverse = glm::inverse(camera.projectionMatrix(width / std::max(1.0, height)) * camera.viewMatrix());
    const double x = 2.0 * pixel.x / width - 1.0, y = 1.0 - 2.0 * pixel.y / height;
    glm::dvec4 nearPoint = inverse * glm::dvec4(x, y, -1.0, 1.0), farPoint = inverse * glm::dvec4(x, y, 1.0, 1.0);
    nearPoint /= nearPoint.w;
    farPoint /= farPoint.w;
    return {glm::dvec3(nearPoint), glm::normalize(glm::dvec3(farPoint - nearPoint))};
}

glm::dvec3 Gizmo::axis(int k) const
{
    if (worldSpace && mode != GizmoMode::Scale) { // scaling always follows the node's own axes
        glm::dvec3 a(0.0);
        a[k] = 1.0;
        return a;
    }
    const glm::dvec3 column(target[k]);
    const double length = glm::length(column);
    return length > 1e-12 ? column / length : glm::dvec3(k == 0, k == 1, k == 2);
}

double Gizmo::sizeFor(const Camera& camera, const glm::dvec3& origin, double heightPixels, double sizePixels)
{
    if (camera.orthographic)
        return camera.metresPerPixel(heightPixels) * sizePixels;
    const double distance = glm::length(camera.position() - origin);
    return 2.0 * distance * std::tan(camera.fovYRadians / 2.0) * sizePixels / std::max(1.0, heightPixels);
}

std::vector<SceneCurve> gizmoCurves(const Gizmo& gizmo, int active)
{
    std::vector<SceneCurve> out;
    const glm::dvec3 o = gizmo.origin();
    for (int k = 0; k < 3; ++k) {
        SceneCurve c;
        c.color = k == active ? kActiveColor : kAxisColors[k];
        const glm::dvec3 a = gizmo.axis(k);
        if (gizmo.mode == GizmoMode::Rotate) {
            glm::dvec3 u, v;
            basisAround(a, u, v);
            for (int i = 0; i <= kCircleSegments; ++i) {
                const double t = 2.0 * glm::pi<double>() * i / kCircleSegments;
                c.points.push_back(o + (u * std::cos(t) + v * std::sin(t)) * gizmo.size);
            }
        } else {
            const glm::dvec3 tip = o + a * gizmo.size;
            c.points = {o, tip};
            glm::dvec3 u, v;
            basisAround(a, u, v);
            const double h = gizmo.size * 0.08;
            if (gizmo.mode == GizmoMode::Translate) // an arrow head
                c.points.insert(c.points.end(), {tip - a * h * 2.0 + u * h, tip, tip - a * h * 2.0 - u * h});
            else // a small box end
                c.points.insert(c.points.end(), {tip + u * h, tip + u * h + v * h, tip + v * h, tip, tip + u * h});
        }
        out.push_back(std::move(c));
    }
    return out;
}

int pickGizmoHandle(const Gizmo& gizmo, const Camera& camera, double width, double height, glm::dvec2 pixel,
                    double radiusPixels)
{
    const glm::dmat4 vp = camera.projectionMatrix(width / std::max(1.0, height)) * camera.viewMatrix();
    int best = -1;
    double bestDistance = radiusPixels;
    const auto curves = gizmoCurves(gizmo, -1);
    for (int k = 0; k < 3; ++k) {
        const auto& points = curves[k].points;
        const std::size_t segments = gizmo.mode == GizmoMode::Rotate ? points.size() - 1 : 1; // shafts only
        for (std::size_t i = 0; i < segments; ++i) {
            glm::dvec2 a, b;
            if (!projectToPixels(vp, points[i], width, height, a) || !projectToPixels(vp, points[i + 1], width, height, b))
                continue;
            if (const double d = distanceToSegment(pixel, a, b); d < bestDistance) {
                bestDistance = d;
                best = k;
            }
        }
    }
    return best;
}

GizmoDrag::GizmoDrag(const Gizmo& gizmo, int handle, const Ray& start)
    : m_gizmo(gizmo), m_handle(handle), m_axis(gizmo.axis(std::clamp(handle, 0, 2)))
{
    m_startAlong = alongAxis(start);
    if (!onPlane(start, m_startPoint))
        m_startPoint = m_gizmo.origin();
}

double GizmoDrag::alongAxis(const Ray& ray) const
{
    // Closest points of two lines: the axis through the origin and the ray.
    const glm::dvec3 w = m_gizmo.origin() - ray.origin;
    const double b = glm::dot(m_axis, ray.direction);
    const double d = glm::dot(m_axis, w), e = glm::dot(ray.direction, w);
    const double denominator = 1.0 - b * b;
    if (denominator < 1e-9) // looking straight down the axis: no motion along it
        return m_startAlong;
    return (b * e - d) / denominator;
}

bool GizmoDrag::onPlane(const Ray& ray, glm::dvec3& point) const
{
    const double facing = glm::dot(ray.direction, m_axis);
    if (std::abs(facing) < 1e-9)
        return false;
    const double t = glm::dot(m_gizmo.origin() - ray.origin, m_axis) / facing;
    point = ray.origin + ray.direction * t;
    return true;
}

glm::dmat4 GizmoDrag::worldFor(const Ray& now) const
{
    const glm::dmat4& start = m_gizmo.target;
    const glm::dvec3 o = m_gizmo.origin();
    switch (m_gizmo.mode) {
    case GizmoMode::Translate:
        return glm::translate(glm::dmat4(1.0), m_axis * (alongAxis(now) - m_startAlong)) * start;
    case GizmoMode::Rotate: {
        glm::dvec3 point;
        if (!onPlane(now, point))
            return start;
        const glm::dvec3 from = m_startPoint - o, to = point - o;
        if (glm::length(from) < 1e-12 || glm::length(to) < 1e-12)
            return start;
        const double angle = std::atan2(glm::dot(glm::cross(from, to), m_axis), glm::dot(from, to));
        return glm::translate(glm::dmat4(1.0), o) * glm::rotate(glm::dmat4(1.0), angle, m_axis) *
               glm::translate(glm::dmat4(1.0), -o) * start;
    }
    case GizmoMode::Scale: {
        if (std::abs(m_startAlong) < 1e-9)
            return start;
        const double factor = std::max(alongAxis(now) / m_startAlong, 1e-3);
        glm::dvec3 s(1.0);
        s[m_handle] = factor;
        return start * glm::scale(glm::dmat4(1.0), s);
    }
    }
    return start;
}

} // namespace rs::viewport
