#include "Picking.h"

#include <algorithm>
#include <limits>

namespace rs::viewport {

double distanceToSegment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b)
{
    const glm::dvec2 ab = b - a;
    const double lengthSquared = glm::dot(ab, ab);
    const double t = lengthSquared > 0.0 ? std::clamp(glm::dot(p - a, ab) / lengthSquared, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

PickResult pick(const Scene& scene, const Camera& camera, double width, double height, glm::dvec2 cursor,
                double jointRadius, double curveRadius)
{
    const glm::dmat4 viewProjection = camera.projectionMatrix(width / height) * camera.viewMatrix();
    PickResult best;
    best.distancePixels = std::numeric_limits<double>::max();
    for (const auto& cv : scene.cvs) {
        glm::dvec2 p;
        if (!projectToPixels(viewProjection, cv.position, width, height, p))
            continue;
        const double d = glm::length(p - cursor);
        if (d <= jointRadius && d < best.distancePixels) {
            best = {PickResult::Kind::Cv, model::kNoId, model::kNoId, cv.cv.node, d, cv.cv};
        }
    }
    if (best.kind != PickResult::Kind::Nothing)
        return best;
    if (scene.showGuides)
        for (const auto& j : scene.guideJoints) {
            glm::dvec2 p;
            if (!projectToPixels(viewProjection, j.position, width, height, p))
                continue;
            const double d = glm::length(p - cursor);
            if (d <= jointRadius && d < best.distancePixels)
                best = {PickResult::Kind::GuideJoint, j.id, j.owner, model::kNoNode, d, {}};
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
                best = {PickResult::Kind::Controller, model::kNoId, model::kNoId, c.node, d, {}};
        }
    if (best.kind == PickResult::Kind::Nothing)
        best.distancePixels = 0.0;
    return best;
}

namespace {

// Tests world points against a pixel rectangle.
struct PixelBox {
    PixelBox(const Camera& camera, double width, double height, glm::dvec2 a, glm::dvec2 b)
        : viewProjection(camera.projectionMatrix(width / height) * camera.viewMatrix()), width(width), height(height),
          lo(glm::min(a, b)), hi(glm::max(a, b)) {}
    bool contains(const glm::dvec3& world) const
    {
        glm::dvec2 p;
        return projectToPixels(viewProjection, world, width, height, p) && p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y;
    }
    glm::dmat4 viewProjection;
    double width, height;
    glm::dvec2 lo, hi;
};

} // namespace

std::vector<model::CurveCv> boxPickCvs(const Scene& scene, const Camera& camera, double width, double height,
                                       glm::dvec2 cornerA, glm::dvec2 cornerB)
{
    const PixelBox box(camera, width, height, cornerA, cornerB);
    std::vector<model::CurveCv> out;
    for (const auto& cv : scene.cvs)
        if (box.contains(cv.position)) out.push_back(cv.cv);
    return out;
}

std::vector<model::CurveCv> coincidentCvs(const Scene& scene, const model::CurveCv& cv)
{
    const auto hit = std::find_if(scene.cvs.begin(), scene.cvs.end(), [&](const SceneCv& c) { return c.cv == cv; });
    if (hit == scene.cvs.end())
        return {cv};
    std::vector<model::CurveCv> out;
    for (const auto& c : scene.cvs)
        if (c.cv.node == cv.node && glm::length(c.position - hit->position) < 1e-6) out.push_back(c.cv);
    return out;
}

std::vector<model::JointId> boxPickJoints(const Scene& scene, const Camera& camera, double width, double height,
                                          glm::dvec2 cornerA, glm::dvec2 cornerB)
{
    const PixelBox box(camera, width, height, cornerA, cornerB);
    std::vector<model::JointId> out;
    if (scene.showGuides)
        for (const auto& j : scene.guideJoints)
            if (box.contains(j.position)) out.push_back(j.id);
    return out;
}

std::vector<model::RigNodeIndex> boxPick(const Scene& scene, const Camera& camera, double width, double height,
                                         glm::dvec2 cornerA, glm::dvec2 cornerB)
{
    const PixelBox box(camera, width, height, cornerA, cornerB);
    std::vector<model::RigNodeIndex> out;
    for (const auto& c : scene.curves) {
        if (!out.empty() && out.back() == c.node)
            continue;
        for (const auto& point : c.points) {
            if (box.contains(point)) {
                if (std::find(out.begin(), out.end(), c.node) == out.end())
                    out.push_back(c.node);
                break;
            }
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace rs::viewport
