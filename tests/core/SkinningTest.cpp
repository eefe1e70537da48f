// CPU skinning (skin/Skinning.h): linear blend and dual-quaternion skinning of
// bind positions and normals by skin matrices; a job is validated before it runs.
#include "skin/Skinning.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <random>

using namespace rs;

namespace {

model::MeshWeights weightsOf(const std::vector<std::vector<model::Influence>>& perVertex, std::size_t joints)
{
    model::MeshWeights w;
    w.joints.resize(joints);
    w.offsets.push_back(0);
    for (const auto& influences : perVertex) {
        w.influences.insert(w.influences.end(), influences.begin(), influences.end());
        w.offsets.push_back(std::uint32_t(w.influences.size()));
    }
    return w;
}

struct Skinned {
    std::vector<glm::vec3> positions, normals;
};

Skinned skinned(skin::SkinningMethod method, const std::vector<glm::vec3>& positions, const model::MeshWeights& weights,
             const std::vector<Mat4>& matrices)
{
    Skinned out;
    out.positions.resize(positions.size());
    out.normals.resize(positions.size());
    skin::SkinningJob job;
    job.method = method;
    job.positions = positions;
    job.normals = positions; // any unit-ish vectors
    job.weights = &weights;
    job.skinMatrices = matrices;
    job.outPositions = out.positions;
    job.outNormals = out.normals;
    EXPECT_TRUE(job.validate().ok()) << job.validate().message();
    job.run();
    return out;
}

// Random weights: per vertex `minInfluences` to `maxInfluences` distinct-or-not
// joints of `joints`, shares summing to 1.
model::MeshWeights randomWeights(std::mt19937& random, std::size_t vertices, std::size_t joints, int minInfluences,
                                 int maxInfluences)
{
    std::uniform_int_distribution<int> count(minInfluences, maxInfluences);
    std::uniform_int_distribution<std::uint32_t> joint(0, std::uint32_t(joints - 1));
    std::uniform_real_distribution<float> share(0.01f, 1.0f);
    std::vector<std::vector<model::Influence>> perVertex(vertices);
    for (auto& influences : perVertex) {
        float sum = 0.0f;
        for (int k = count(random); k > 0; --k) {
            influences.push_back({joint(random), share(random)});
            sum += influences.back().weight;
        }
        for (auto& influence : influences)
            influence.weight /= sum;
    }
    return weightsOf(perVertex, joints);
}

// Random rigid motions, some with scale (linear blending keeps it; dual quaternions drop it).
std::vector<Mat4> randomMatrices(std::mt19937& random, std::size_t joints)
{
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<Mat4> matrices;
    for (std::size_t j = 0; j < joints; ++j) {
        const Vec3 axis = glm::normalize(Vec3(unit(random), unit(random), unit(random)) + Vec3(0.0, 0.0, 1e-3));
        matrices.push_back(glm::translate(Mat4(1.0), Vec3(unit(random), unit(random), unit(random))) *
                           glm::rotate(Mat4(1.0), 3.0 * unit(random), axis) * glm::scale(Mat4(1.0), Vec3(1.0 + 0.2 * unit(random))));
    }
    return matrices;
}

std::vector<glm::vec3> randomPoints(std::mt19937& random, std::size_t count)
{
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<glm::vec3> points(count);
    for (auto& p : points)
        p = glm::normalize(glm::vec3(unit(random), unit(random), unit(random)) + glm::vec3(0.0f, 0.0f, 1e-3f));
    return points;
}

// Skins the same vertices with prepared weights and with the weights read in place.
void expectPreparedMatchesInPlace(const model::MeshWeights& weights, bool expectFixedLayout, bool withNormals)
{
    std::mt19937 random(7);
    const std::size_t n = weights.vertexCount();
    const std::vector<glm::vec3> positions = randomPoints(random, n), normals = randomPoints(random, n);
    const std::vector<Mat4> matrices = randomMatrices(random, weights.joints.size());
    auto prepared = skin::PreparedSkin::prepare(weights);
    ASSERT_TRUE(prepared.ok()) << formatAll(prepared.diagnostics());
    EXPECT_EQ(prepared->hasFixedLayout(), expectFixedLayout);
    for (auto method : {skin::SkinningMethod::Linear, skin::SkinningMethod::DualQuaternion}) {
        Skinned fast, general;
        for (Skinned* out : {&fast, &general}) {
            out->positions.resize(n);
            out->normals.resize(withNormals ? n : 0);
            skin::SkinningJob job;
            job.method = method;
            job.positions = positions;
            if (withNormals)
                job.normals = normals;
            if (out == &fast)
                job.prepared = &*prepared;
            else
                job.weights = &weights;
            job.skinMatrices = matrices;
            job.outPositions = out->positions;
            job.outNormals = out->normals;
            ASSERT_TRUE(job.validate().ok()) << job.validate().message();
            job.run();
        }
        for (std::size_t v = 0; v < n; ++v) {
            ASSERT_LT(glm::length(fast.positions[v] - general.positions[v]), 1e-5f) << "vertex " << v;
            if (withNormals) {
                ASSERT_LT(glm::length(fast.normals[v] - general.normals[v]), 1e-5f) << "vertex " << v;
                ASSERT_NEAR(glm::length(fast.normals[v]), 1.0f, 1e-5f) << "vertex " << v;
            }
        }
    }
}

} // namespace

TEST(Skinning, PreparedWeightsOfUpToFourInfluencesSkinAsTheGeneralLoopsDo)
{
    std::mt19937 random(19);
    const auto weights = randomWeights(random, 20000, 80, 1, 4);
    expectPreparedMatchesInPlace(weights, true, true);
    expectPreparedMatchesInPlace(weights, true, false);
}

TEST(Skinning, PreparedWeightsOfMoreThanFourInfluencesKeepTheGeneralLayout)
{
    std::mt19937 random(23);
    const auto weights = randomWeights(random, 20000, 80, 1, 8);
    expectPreparedMatchesInPlace(weights, false, true);
}

TEST(Skinning, PreparedWeightsWithAnUnweightedVertexKeepTheGeneralLayout)
{
    std::mt19937 random(29);
    auto perVertex = std::vector<std::vector<model::Influence>>{{{0, 1.0f}}, {}, {{1, 0.5f}, {2, 0.5f}}};
    expectPreparedMatchesInPlace(weightsOf(perVertex, 3), false, true);
}

TEST(Skinning, PreparingRefusesOffsetsThatDoNotDescribeTheInfluences)
{
    auto weights = weightsOf({{{0, 1.0f}}, {{0, 0.5f}, {1, 0.5f}}}, 2);
    EXPECT_TRUE(skin::PreparedSkin::prepare(weights).ok());
    weights.offsets = {0, 1, 4};
    EXPECT_FALSE(skin::PreparedSkin::prepare(weights).ok()) << "ends past the influences";
    weights.offsets = {0, 3, 2, 4};
    weights.influences.push_back({0, 1.0f});
    EXPECT_FALSE(skin::PreparedSkin::prepare(weights).ok()) << "decreasing";
    weights.offsets.clear();
    EXPECT_FALSE(skin::PreparedSkin::prepare(weights).ok()) << "no offsets at all";
}

TEST(Skinning, AJobWithPreparedWeightsIsRefusedWhenTheMatricesDoNotCoverThem)
{
    const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}};
    std::vector<glm::vec3> out(2);
    const auto prepared = skin::PreparedSkin::prepare(weightsOf({{{0, 1.0f}}, {{2, 1.0f}}}, 3)).take();
    EXPECT_EQ(prepared.matrixCount(), 3u);
    const std::vector<Mat4> two(2, Mat4(1.0)), three(3, Mat4(1.0));
    skin::SkinningJob job;
    job.positions = positions;
    job.prepared = &prepared;
    job.skinMatrices = two;
    job.outPositions = out;
    EXPECT_TRUE(job.validate().failed()) << "joint 2 of 2";
    job.skinMatrices = three;
    EXPECT_TRUE(job.validate().ok());
    job.positions = std::span(positions).first(1);
    EXPECT_TRUE(job.validate().failed()) << "two weighted vertices for one";
}

TEST(Skinning, OneJointMovesItsVerticesRigidlyByBothMethods)
{
    const std::vector<glm::vec3> positions = {{0, 1, 0}, {1, 2, 3}};
    const auto weights = weightsOf({{{0, 1.0f}}, {{0, 1.0f}}}, 1);
    const Mat4 moved = glm::translate(Mat4(1.0), Vec3(1, 0, 0)) * glm::rotate(Mat4(1.0), glm::radians(90.0), Vec3(0, 0, 1));
    for (auto method : {skin::SkinningMethod::Linear, skin::SkinningMethod::DualQuaternion}) {
        const Skinned s = skinned(method, positions, weights, {moved});
        for (std::size_t v = 0; v < positions.size(); ++v) {
            const glm::vec3 expected(moved * Vec4(Vec3(positions[v]), 1.0));
            EXPECT_NEAR(glm::length(s.positions[v] - expected), 0.0f, 1e-5f);
        }
    }
}

TEST(Skinning, DualQuaternionsKeepATwistedLimbsVolumeWhereLinearBlendingCollapsesIt)
{
    // Halfway between a joint at rest and one twisted 120 degrees about the bone (X).
    const std::vector<glm::vec3> positions = {{0, 1, 0}};
    const auto weights = weightsOf({{{0, 0.5f}, {1, 0.5f}}}, 2);
    const std::vector<Mat4> matrices = {Mat4(1.0), glm::rotate(Mat4(1.0), glm::radians(120.0), Vec3(1, 0, 0))};
    const Skinned linear = skinned(skin::SkinningMethod::Linear, positions, weights, matrices);
    const Skinned dual = skinned(skin::SkinningMethod::DualQuaternion, positions, weights, matrices);
    EXPECT_NEAR(glm::length(linear.positions[0]), 0.5f, 1e-5f) << "the candy wrapper";
    EXPECT_NEAR(glm::length(dual.positions[0]), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::degrees(std::atan2(dual.positions[0].z, dual.positions[0].y)), 60.0f, 1e-3f) << "half the twist";
}

TEST(Skinning, AJobThatDoesNotFitIsRefusedBeforeItRuns)
{
    const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}};
    std::vector<glm::vec3> out(2);
    const std::vector<Mat4> one = {Mat4(1.0)};
    const auto bad = weightsOf({{{0, 1.0f}}, {{3, 1.0f}}}, 1);
    skin::SkinningJob job;
    job.positions = positions;
    job.weights = &bad;
    job.skinMatrices = one;
    job.outPositions = out;
    EXPECT_TRUE(job.validate().failed()) << "joint 3 of 1";
    const auto good = weightsOf({{{0, 1.0f}}, {{0, 1.0f}}}, 1);
    job.weights = &good;
    EXPECT_TRUE(job.validate().ok());
    std::vector<glm::vec3> small(1);
    job.outPositions = small;
    EXPECT_TRUE(job.validate().failed()) << "an output too small";
    job.outPositions = out;
    job.skinMatrices = {};
    EXPECT_TRUE(job.validate().failed()) << "no matrices";
    job.weights = nullptr;
    EXPECT_TRUE(job.validate().failed());
}
