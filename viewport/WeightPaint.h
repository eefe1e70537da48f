#pragma once
// Weight painting's viewport maths, no GL: the character's meshes where they
// are drawn (skinned meshes posed on the CPU with the scene's palette, the
// others in the bind pose), the mouse ray's hit on them, the vertices a click
// or a box selects, and the brush circle. The GPU skins what is drawn; the
// CPU copy (PosedCharacter) is made once per stroke or per scene, since
// skinning 100k vertices costs about a millisecond.
#include "Camera.h"
#include "Manipulator.h" // Ray
#include "Scene.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace rs::viewport {

// One drawn mesh, posed as drawn, with per-vertex normals (area-weighted from
// the posed triangles, so they follow the pose).
struct PosedMesh {
    std::size_t characterMesh = 0; // SceneMesh::characterMesh
    std::shared_ptr<const model::Model> model; // keeps `data` alive
    const model::Mesh* data = nullptr;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
};

// The scene's meshes as drawn (sharing the scene's immutable models).
struct PosedCharacter {
    std::vector<PosedMesh> meshes;
    std::uint64_t sceneRevision = 0; // the scene it was made from
    // Skins the meshes the scene draws posed (SceneMesh::skinned) with
    // scene.palette; a mesh whose weights the palette does not cover stays in the bind pose.
    static PosedCharacter of(const Scene& scene);
};

// Where a ray first meets a mesh (triangles seen from either side).
struct MeshHit {
    std::size_t characterMesh = 0;
    glm::dvec3 point{0.0};   // world
    glm::dvec3 normal{0.0};  // the hit triangle's, unit, facing the ray's origin
    std::uint32_t vertex = 0; // the hit triangle's corner nearest the point (a file vertex)
    double distance = 0.0;    // along the ray, metres
};
std::optional<MeshHit> hitCharacter(const PosedCharacter& character, const Ray& ray);

// Vertices per characterMesh inside the pixel rectangle whose (posed) normal
// faces the camera. Back-facing vertices are skipped; a front-facing vertex
// hidden behind another part of the body is still taken (no depth test).
using VertexSelection = std::vector<std::pair<std::size_t, std::vector<std::uint32_t>>>;
VertexSelection boxPickVertices(const PosedCharacter& character, const Camera& camera, double width, double height,
                                glm::dvec2 cornerA, glm::dvec2 cornerB);

// The brush: a circle of `radius` metres around `centre` in the plane of
// `normal` (so it shows the brush's reach on the surface, foreshortened).
SceneCurve brushCircle(const glm::dvec3& centre, const glm::dvec3& normal, double radius, const glm::dvec3& color);

// Where the selected vertices (SceneMesh::selectedVertices) are drawn.
std::vector<glm::dvec3> selectedVertexPositions(const Scene& scene, const PosedCharacter& character);

} // namespace rs::viewport
