// The character's meshes skinned on the GPU (Renderer, MeshRenderer): a tube
// of two bones rendered through the GLFW host under Xvfb, read back and
// checked: posing moves its pixels without sending its vertices again, dual
// quaternions keep a 90 degree twist's volume where linear blending loses
// it, the weight heat map colours by the chosen bone. Also the packing of
// influences and the dual quaternion of a palette matrix, without GL.
#include "GlfwHost.h"
#include "render/MeshRenderer.h"
#include "render/Renderer.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace rs;
using namespace rs::viewport;

namespace {

constexpr int kRings = 21, kSides = 16;
constexpr float kLength = 2.0f, kRadius = 0.2f;

// A tube along +X from 0 to 2, bone 0 at the origin, bone 1 at x = 1; the
// weights blend from bone 0 to bone 1 between x = 0.6 and 1.4 (0.5 each at 1).
std::shared_ptr<const model::Model> tube()
{
    auto m = std::make_shared<model::Model>();
    model::Mesh mesh;
    mesh.name = "tube";
    for (int r = 0; r < kRings; ++r)
        for (int s = 0; s < kSides; ++s) {
            const float a = float(s) / kSides * 6.2831853f;
            const float x = kLength * float(r) / (kRings - 1);
            mesh.positions.push_back({x, kRadius * std::cos(a), kRadius * std::sin(a)});
            mesh.normals.push_back({0.0f, std::cos(a), std::sin(a)});
        }
    for (int r = 0; r + 1 < kRings; ++r)
        for (int s = 0; s < kSides; ++s) {
            const std::uint32_t a = std::uint32_t(r * kSides + s), b = std::uint32_t(r * kSides + (s + 1) % kSides);
            mesh.indices.insert(mesh.indices.end(), {a, b, a + kSides, b, b + kSides, a + kSides});
        }
    m->meshes.push_back(std::move(mesh));
    return m;
}

std::shared_ptr<const model::MeshWeights> tubeWeights(const model::Mesh& mesh)
{
    auto w = std::make_shared<model::MeshWeights>();
    w->joints.resize(2);
    w->parents = {-1, 0};
    for (const glm::vec3& p : mesh.positions) {
        w->offsets.push_back(std::uint32_t(w->influences.size()));
        const float t = std::clamp((p.x - 0.6f) / 0.8f, 0.0f, 1.0f);
        if (t < 1.0f) w->influences.push_back({0, 1.0f - t});
        if (t > 0.0f) w->influences.push_back({1, t});
    }
    w->offsets.push_back(std::uint32_t(w->influences.size()));
    return w;
}

// Bone 1 turned by `angleRadians` about `axis` at its joint (x = 1).
glm::mat4 turnAtJoint(const glm::vec3& axis, float angleRadians)
{
    const glm::mat4 to = glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    return to * glm::rotate(glm::mat4(1.0f), angleRadians, axis) * glm::inverse(to);
}

Scene tubeScene(const glm::mat4& bone1, Skinning skinning = Skinning::Linear)
{
    Scene scene;
    SceneMesh mesh;
    mesh.model = tube();
    mesh.weights = tubeWeights(mesh.model->meshes[0]);
    mesh.skinned = true;
    mesh.baseColor = {0.1f, 0.9f, 0.1f}; // green: neither the grid's greys, red and blue nor the background
    scene.meshes.push_back(mesh);
    scene.palette = {glm::mat4(1.0f), bone1};
    scene.skinning = skinning;
    return scene;
}

// Front view (orthographic, down -Z) of the box every pose of the tube stays
// in. The ground grid is edge-on there, a line along y = 0: samples avoid it.
Camera frontCamera(double aspect)
{
    Camera camera;
    camera.setView(CameraView::Front);
    camera.frame({-0.3, -1.3, -0.3}, {2.3, 1.3, 0.3}, aspect);
    return camera;
}

struct Image {
    std::vector<std::uint8_t> rgb;
    int width = 0, height = 0;
    glm::dmat4 viewProjection{1.0};
    const std::uint8_t* at(int x, int y) const { return &rgb[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3]; }
    bool isTube(int x, int y) const
    {
        const std::uint8_t* p = at(x, y);
        return p[1] > 90 && p[1] > p[0] + 40 && p[1] > p[2] + 40;
    }
    glm::ivec2 pixel(const glm::dvec3& world) const
    {
        glm::dvec2 p;
        projectToPixels(viewProjection, world, width, height, p);
        return {int(p.x), int(p.y)};
    }
    bool isTubeAt(const glm::dvec3& world) const
    {
        const glm::ivec2 p = pixel(world);
        return isTube(p.x, p.y);
    }
    // How many tube pixels the column through `world` holds.
    int columnHeight(const glm::dvec3& world) const
    {
        const int x = pixel(world).x;
        int count = 0;
        for (int y = 0; y < height; ++y)
            count += isTube(x, y);
        return count;
    }
};

Image render(GlfwHost& host, const Scene& scene)
{
    const Camera camera = frontCamera(double(host.width()) / host.height());
    host.render(scene, camera);
    Image image{host.readPixels(), host.width(), host.height(),
                camera.projectionMatrix(double(host.width()) / host.height()) * camera.viewMatrix()};
    return image;
}

std::unique_ptr<GlfwHost> makeHost()
{
    std::string error;
    auto host = GlfwHost::create(480, 480, "skin render test", false, error);
    EXPECT_TRUE(host) << error << " (GL tests need a display: run them under xvfb-run)";
    return host;
}

} // namespace

TEST(SkinRender, PosingABoneMovesTheMeshWithoutSendingItsVerticesAgain)
{
    auto host = makeHost();
    ASSERT_TRUE(host);
    Scene scene = tubeScene(glm::mat4(1.0f));
    const Image rest = render(*host, scene);
    const std::uint64_t vertices = host->renderer().meshVerticesUploaded();
    const std::uint64_t weights = host->renderer().weightVerticesUploaded();
    EXPECT_EQ(vertices, std::uint64_t(kRings * kSides));
    EXPECT_EQ(weights, std::uint64_t(kRings * kSides));
    EXPECT_TRUE(rest.isTubeAt({1.8, 0.1, 0.0}));
    EXPECT_FALSE(rest.isTubeAt({1.0, 0.8, 0.0}));

    // Bone 1 bends up by 90 degrees: the far half now points up (+Y).
    Scene bent = tubeScene(turnAtJoint({0, 0, 1}, glm::radians(90.0f)));
    bent.meshes = scene.meshes; // the same mesh and weights objects, a new palette
    const Image posed = render(*host, bent);
    EXPECT_FALSE(posed.isTubeAt({1.8, 0.1, 0.0}));
    EXPECT_TRUE(posed.isTubeAt({1.0, 0.8, 0.0}));
    EXPECT_TRUE(posed.isTubeAt({0.3, 0.1, 0.0})) << "bone 0's half stays";
    EXPECT_EQ(host->renderer().meshVerticesUploaded(), vertices) << "posing sends the palette only";
    EXPECT_EQ(host->renderer().weightVerticesUploaded(), weights);

    // Not skinned (Guide mode, or unbound): the bind pose, see-through.
    bent.meshes[0].skinned = false;
    const Image guide = render(*host, bent);
    EXPECT_FALSE(guide.isTubeAt({1.0, 0.8, 0.0}));
    const std::uint8_t* p = guide.at(guide.pixel({1.8, 0.1, 0.0}).x, guide.pixel({1.8, 0.1, 0.0}).y);
    EXPECT_GT(int(p[1]), 50);
    EXPECT_LT(int(p[1]), 120) << "see-through: the background shows through";

    // New weights (a weight edit) are sent again; the vertices are not.
    bent.meshes[0].weights = tubeWeights(bent.meshes[0].data());
    render(*host, bent);
    EXPECT_EQ(host->renderer().weightVerticesUploaded(), 2 * weights);
    EXPECT_EQ(host->renderer().meshVerticesUploaded(), vertices);
}

TEST(SkinRender, DualQuaternionsKeepATwistedTubesVolumeWhereLinearBlendingLosesIt)
{
    auto host = makeHost();
    ASSERT_TRUE(host);
    const Image rest = render(*host, tubeScene(glm::mat4(1.0f)));
    const glm::mat4 twist = turnAtJoint({1, 0, 0}, glm::radians(90.0f));
    const Image linear = render(*host, tubeScene(twist, Skinning::Linear));
    const Image dq = render(*host, tubeScene(twist, Skinning::DualQuaternion));
    const glm::dvec3 middle(1.0, 0.0, 0.0); // both bones weigh 0.5 here
    const int restHeight = rest.columnHeight(middle);
    ASSERT_GT(restHeight, 20);
    // Linear blending averages the ring with its 90 degree turn: cos 45 = 0.71 of the radius.
    EXPECT_LT(linear.columnHeight(middle), 0.8 * restHeight);
    EXPECT_GT(dq.columnHeight(middle), 0.95 * restHeight);
    EXPECT_LT(dq.columnHeight(middle), 1.05 * restHeight);
    // Away from the blend both agree with the rest pose (a rigid twist of a round tube).
    EXPECT_NEAR(dq.columnHeight({1.8, 0, 0}), restHeight, 2);
    EXPECT_NEAR(linear.columnHeight({0.2, 0, 0}), restHeight, 2);
}

TEST(SkinRender, SelectedJointWeightsAreAHeatMapFromBlueToRed)
{
    auto host = makeHost();
    ASSERT_TRUE(host);
    Scene scene = tubeScene(glm::mat4(1.0f));
    scene.weightDisplay = WeightDisplay::SelectedJoint;
    scene.weightBone = 1;
    const Image heat = render(*host, scene);
    const glm::ivec2 tip = heat.pixel({1.9, 0.1, 0.0}), root = heat.pixel({0.1, 0.1, 0.0});
    const std::uint8_t* red = heat.at(tip.x, tip.y);
    const std::uint8_t* blue = heat.at(root.x, root.y);
    EXPECT_GT(int(red[0]), 150);
    EXPECT_LT(int(red[2]), 60);
    EXPECT_GT(int(blue[2]), 90);
    EXPECT_LT(int(blue[0]), 60);

    scene.weightDisplay = WeightDisplay::DominantJoint; // one colour per bone: the two halves differ
    const Image dominant = render(*host, scene);
    const std::uint8_t* a = dominant.at(tip.x, tip.y);
    const std::uint8_t* b = dominant.at(root.x, root.y);
    EXPECT_GT(std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]), 60);
}

TEST(SkinRender, KeepsTheFourLargestInfluencesRenormalised)
{
    model::MeshWeights w;
    w.joints.resize(6);
    w.offsets = {0, 6, 6};
    w.influences = {{0, 0.05f}, {1, 0.3f}, {2, 0.1f}, {3, 0.25f}, {4, 0.2f}, {5, 0.1f}};
    std::vector<std::uint16_t> joints;
    std::vector<float> shares;
    MeshRenderer::packInfluences(w, 2, joints, shares);
    ASSERT_EQ(joints.size(), 8u);
    EXPECT_EQ(joints[0], 1);
    EXPECT_EQ(joints[1], 3);
    EXPECT_EQ(joints[2], 4);
    EXPECT_NEAR(shares[0] + shares[1] + shares[2] + shares[3], 1.0f, 1e-6f);
    EXPECT_NEAR(shares[0], 0.3f / 0.85f, 1e-6f);
    EXPECT_EQ(shares[4] + shares[5] + shares[6] + shares[7], 0.0f) << "a vertex without influences weighs nothing";
}

TEST(SkinRender, DualQuaternionOfAPaletteMatrixMovesPointsAsTheMatrixDoes)
{
    const glm::mat4 m = glm::translate(glm::mat4(1.0f), {0.3f, -1.0f, 2.0f}) *
                        glm::rotate(glm::mat4(1.0f), 1.1f, glm::normalize(glm::vec3(1, 2, 3)));
    glm::vec4 real, dual;
    MeshRenderer::toDualQuaternion(m, real, dual);
    EXPECT_NEAR(glm::length(real), 1.0f, 1e-5f);
    // The shader's transform: p' = rotate(real, p) + t.
    const glm::vec3 q(real), p(0.5f, 0.7f, -0.2f);
    const glm::vec3 rotated = p + 2.0f * glm::cross(q, glm::cross(q, p) + real.w * p);
    const glm::vec3 t = 2.0f * (real.w * glm::vec3(dual) - dual.w * q + glm::cross(q, glm::vec3(dual)));
    const glm::vec3 expected(m * glm::vec4(p, 1.0f));
    EXPECT_NEAR(glm::distance(rotated + t, expected), 0.0f, 1e-5f);
}
