#include "WeightPaint.h"

#include "skin/Skinning.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rs::viewport {

namespace {

// Möller-Trumbore; both faces. The distance along the ray, or a negative number.
double rayTriangle(const Ray& ray, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
    const glm::dvec3 e1 = b - a, e2 = c - a;
    const glm::dvec3 p = glm::cross(ray.direction, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-14)
        return -1.0;
    const double inv = 1.0 / det;
    const glm::dvec3 s = ray.origin - a;
    const double u = glm::dot(s, p) * inv;
    if (u < 0.0 || u > 1.0)
        return -1.0;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(ray.direction, q) * inv;
    if (v < 0.0 || u + v > 1.0)
        return -1.0;
    return glm::dot(e2, q) * inv;
}

} // namespace

PosedCharacter PosedCharacter::of(const Scene& scene)
{
    PosedCharacter out;
    out.sceneRevision = scene.revision;
    const std::vector<Mat4> palette(scene.palette.begin(), scene.palette.end());
    for (const SceneMesh& sceneMesh : scene.meshes) {
        PosedMesh posed;
        posed.characterMesh = sceneMesh.characterMesh;
        posed.model = sceneMesh.model;
        posed.data = &sceneMesh.data();
        posed.positions = posed.data->positions;
        if (sceneMesh.skinned && sceneMesh.weights) {
            skin::SkinningJob job;
            job.method = scene.skinning == Skinning::DualQuaternion ? skin::SkinningMethod::DualQuaternion : skin::SkinningMethod::Linear;
            job.positions = posed.data->positions;
            job.weights = sceneMesh.weights.get();
            job.skinMatrices = palette;
            job.outPositions = posed.positions;
            if (job.validate().ok())
                job.run();
        }
        posed.normals = model::vertexNormals(*posed.data, posed.positions, glm::vec3(0.0f));
        out.meshes.push_back(std::move(posed));
    }
    return out;
}

std::optional<MeshHit> hitCharacter(const PosedCharacter& character, const Ray& ray)
{
    std::optional<MeshHit> best;
    for (const PosedMesh& mesh : character.meshes) {
        const auto& p = mesh.positions;
        const auto& indices = mesh.data->indices;
        for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
            const std::uint32_t ia = indices[t], ib = indices[t + 1], ic = indices[t + 2];
            if (ia >= p.size() || ib >= p.size() || ic >= p.size())
                continue;
            const glm::dvec3 a(p[ia]), b(p[ib]), c(p[ic]);
            const double d = rayTriangle(ray, a, b, c);
            if (d <= 0.0 || (best && d >= best->distance))
                continue;
            MeshHit hit;
            hit.characterMesh = mesh.characterMesh;
            hit.distance = d;
            hit.point = ray.origin + ray.direction * d;
            glm::dvec3 n = glm::cross(b - a, c - a);
            n = glm::length(n) > 0.0 ? glm::normalize(n) : -ray.direction;
            hit.normal = glm::dot(n, ray.direction) > 0.0 ? -n : n;
            const double da = glm::distance(hit.point, a), db = glm::distance(hit.point, b), dc = glm::distance(hit.point, c);
            hit.vertex = da <= db && da <= dc ? ia : db <= dc ? ib : ic;
            best = hit;
        }
    }
    return best;
}

VertexSelection boxPickVertices(const PosedCharacter& character, const Camera& camera, double width, double height,
                                glm::dvec2 cornerA, glm::dvec2 cornerB)
{
    const glm::dvec2 lo = glm::min(cornerA, cornerB), hi = glm::max(cornerA, cornerB);
    const glm::dmat4 vp = camera.projectionMatrix(width / std::max(1.0, height)) * camera.viewMatrix();
    const glm::dvec3 eye = camera.position();
    const glm::dvec3 forward = glm::normalize(camera.target - eye);
    VertexSelection out;
    for (const PosedMesh& mesh : character.meshes) {
        std::vector<std::uint32_t> vertices;
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            const glm::dvec3 p(mesh.positions[v]);
            const glm::dvec3 towardsEye = camera.orthographic ? -forward : eye - p;
            if (glm::dot(glm::dvec3(mesh.normals[v]), towardsEye) <= 0.0)
                continue;
            glm::dvec2 pixel;
            if (projectToPixels(vp, p, width, height, pixel) && pixel.x >= lo.x && pixel.x <= hi.x && pixel.y >= lo.y && pixel.y <= hi.y)
                vertices.push_back(std::uint32_t(v));
        }
        if (!vertices.empty())
            out.emplace_back(mesh.characterMesh, std::move(vertices));
    }
    return out;
}

SceneCurve brushCircle(const glm::dvec3& centre, const glm::dvec3& normal, double radius, const glm::dvec3& color)
{
    const glm::dvec3 n = glm::length(normal) > 0.0 ? glm::normalize(normal) : glm::dvec3(0.0, 0.0, 1.0);
    const glm::dvec3 helper = std::abs(n.y) < 0.9 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
    const glm::dvec3 u = glm::normalize(glm::cross(n, helper)), w = glm::cross(n, u);
    SceneCurve circle;
    circle.color = color;
    const int segments = 48;
    for (int i = 0; i <= segments; ++i) {
        const double angle = 2.0 * M_PI * i / segments;
        circle.points.push_back(centre + radius * (std::cos(angle) * u + std::sin(angle) * w));
    }
    return circle;
}

std::vector<glm::dvec3> selectedVertexPositions(const Scene& scene, const PosedCharacter& character)
{
    std::vector<glm::dvec3> out;
    for (std::size_t m = 0; m < scene.meshes.size() && m < character.meshes.size(); ++m)
        for (std::uint32_t v : scene.meshes[m].selectedVertices)
            if (v < character.meshes[m].positions.size())
                out.emplace_back(character.meshes[m].positions[v]);
    return out;
}

} // namespace rs::viewport
