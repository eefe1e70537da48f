// Weight painting's viewport maths (no GL): the mesh is hit where it is drawn
// (posed by the palette when skinned), and a box takes only the vertices
// facing the camera.
#include "WeightPaint.h"

#include <gtest/gtest.h>

using namespace rs;
using namespace rs::viewport;

namespace {

// A closed box of 8 vertices (-0.5..0.5), outward triangles, every vertex on joint 0.
Scene boxScene(const glm::mat4& skin, bool skinned)
{
    auto model = std::make_shared<model::Model>();
    model::Mesh mesh;
    for (int i = 0; i < 8; ++i)
        mesh.positions.emplace_back(i & 1 ? 0.5f : -0.5f, i & 2 ? 0.5f : -0.5f, i & 4 ? 0.5f : -0.5f);
    mesh.indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
    model->meshes.push_back(mesh);
    auto weights = std::make_shared<model::MeshWeights>();
    weights->joints = {NodeKey{}};
    weights->parents = {-1};
    for (std::uint32_t v = 0; v <= 8; ++v)
        weights->offsets.push_back(v);
    weights->influences.assign(8, {0, 1.0f});
    Scene scene;
    SceneMesh m;
    m.model = model;
    m.weights = weights;
    m.skinned = skinned;
    m.characterMesh = 3;
    scene.meshes.push_back(m);
    scene.palette = {skin};
    return scene;
}

Camera frontCamera()
{
    Camera camera;
    camera.setView(CameraView::Front); // looks down -Z
    camera.target = glm::dvec3(0.0);
    camera.distance = 5.0;
    return camera;
}

} // namespace

TEST(WeightPaint, TheRayHitsTheMeshWhereThePaletteDrawsIt)
{
    const glm::mat4 up = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 2.0f, 0.0f));
    const Ray down{{0.0, 2.1, 10.0}, {0.0, 0.0, -1.0}};
    const auto posed = hitCharacter(PosedCharacter::of(boxScene(up, true)), down);
    ASSERT_TRUE(posed);
    EXPECT_EQ(posed->characterMesh, 3u);
    EXPECT_NEAR(posed->point.z, 0.5, 1e-9);
    EXPECT_NEAR(posed->point.y, 2.1, 1e-9);
    EXPECT_NEAR(posed->normal.z, 1.0, 1e-9) << "the face towards the ray";
    EXPECT_TRUE(posed->vertex == 6 || posed->vertex == 7) << "a corner of the front face's upper edge: " << posed->vertex;
    EXPECT_FALSE(hitCharacter(PosedCharacter::of(boxScene(up, false)), down)) << "unskinned: drawn, and hit, at rest";
    EXPECT_TRUE(hitCharacter(PosedCharacter::of(boxScene(up, false)), Ray{{0.0, 0.1, 10.0}, {0.0, 0.0, -1.0}}));
}

TEST(WeightPaint, ABoxSelectsOnlyTheVerticesFacingTheCamera)
{
    const Camera camera = frontCamera();
    const auto picked = boxPickVertices(PosedCharacter::of(boxScene(glm::mat4(1.0f), true)), camera, 800, 600, {0, 0}, {800, 600});
    ASSERT_EQ(picked.size(), 1u);
    EXPECT_EQ(picked[0].first, 3u);
    EXPECT_EQ(picked[0].second, (std::vector<std::uint32_t>{4, 5, 6, 7})) << "the +Z face's corners only";
    EXPECT_TRUE(boxPickVertices(PosedCharacter::of(boxScene(glm::mat4(1.0f), true)), camera, 800, 600, {0, 0}, {10, 10}).empty());
}
