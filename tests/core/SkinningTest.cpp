// CPU skinning (skin/Skinning.h): linear blend and dual-quaternion skinning of
// bind positions and normals by skin matrices; a job is validated before it runs.
#include "skin/Skinning.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

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

} // namespace

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
