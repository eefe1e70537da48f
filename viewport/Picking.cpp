#include "Picking.h"

#include <algorithm>
#include <limits>

namespace rs::viewport {

namespace {

double distanceToSegment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b)
{
    const glm::dvec2 ab = b - a;
    const double lengthSquared = glm::dot(ab, ab);
    const double t = lengthSquared > 0.0 ? std::clamp(glm::dot(p - a, ab) / lengthSquared, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

} // namespace

PickResult pick(const Scene& scene, const Camera& camera, double width, double height, glm::dvec2 cursor,
                double jointRadius, double curveRadius)
{
    const glm::dmat4 viewProjection = camera.projectionMatrix(width / height) * camera.viewMatrix();
    PickResult best;
    best.distancePixels = std::numeric_limits<double>::max();
    if (scene.showGuides)
        for (const auto& j : scene.guideJoints) {
            glm::dvec2 p;
            if (!projectToPixels(viewProjection, j.position, width, height, p))
                continue;
            const double d = glm::length(p - cursor);
            if (d <= jointRadius && d < best.distancePixels)
                best = {PickResult::Kind::GuideJoint, j.id, j.owner, model::kNoNode, d};
        }
    if (best.kind != PickResult::Kind::Nothing)
        return best;
    for (const auto& c : scene.curves)
        for (std::size_t i = 1; i < c.points.size(); ++i) {
            glm::dvec2 a, b;
            if (!projectToPixels(viewProjection, c.points[i - 1], width, height, a) ||
                !projectToPixels(viewProjection, c.points[i], width, height, b))
                continue;
            const double d = distanceToSegment(cursor, a, b);
            if (d <= curveRadius && d < best.distancePixels)
                best = {PickResult::Kind::Controller, model::kNoId, model::kNoId, c.node, d};
        }
    if (best.kind == PickResult::Kind::Nothing)
        best.distancePixels = 0.0;
    return best;
}

} // namespace rs::viewport
