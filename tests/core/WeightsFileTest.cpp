// Skin weight files (io/WeightsFile.h): a round trip keeps every weight and
// joint identity; a damaged, truncated or foreign file is an error, never a
// crash or a silent partial load.
#include "TestSupport.h"

#include "io/WeightsFile.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

std::vector<io::BoundMesh> sample()
{
    io::BoundMesh mesh;
    mesh.model = "models/human.fbx";
    mesh.name = "body";
    mesh.vertexCount = 3;
    mesh.fingerprint = 0x1234567890abcdefull;
    mesh.weights.joints = {{4, "L", "skin.limb.0"}, {4, "R", "skin.limb.0"}, {2, "", "skin.spine.1"}};
    mesh.weights.offsets = {0, 1, 3, 4};
    mesh.weights.influences = {{0, 1.0f}, {1, 0.25f}, {2, 0.75f}, {2, 1.0f}};
    return {mesh};
}

} // namespace

TEST(WeightsFile, ARoundTripKeepsEveryWeightAndJoint)
{
    const std::string path = test::temporaryPath("round.weights");
    ASSERT_TRUE(io::saveWeightsFile(path, sample()).ok());
    auto loaded = io::loadWeightsFile(path);
    ASSERT_TRUE(loaded.ok()) << formatAll(loaded.diagnostics());
    ASSERT_EQ(loaded->size(), 1u);
    const io::BoundMesh& mesh = loaded->front();
    EXPECT_EQ(mesh.model, "models/human.fbx");
    EXPECT_EQ(mesh.name, "body");
    EXPECT_EQ(mesh.vertexCount, 3u);
    EXPECT_EQ(mesh.fingerprint, 0x1234567890abcdefull);
    EXPECT_EQ(mesh.weights.joints, sample().front().weights.joints);
    EXPECT_EQ(mesh.weights.offsets, sample().front().weights.offsets);
    ASSERT_EQ(mesh.weights.influences.size(), 4u);
    EXPECT_EQ(mesh.weights.influences[2].joint, 2u);
    EXPECT_FLOAT_EQ(mesh.weights.influences[2].weight, 0.75f);
    EXPECT_EQ(io::writeWeights(*loaded), io::writeWeights(sample())) << "byte-identical when written again";
}

TEST(WeightsFile, DamagedFilesAreErrorsNamingTheFile)
{
    const std::string good = io::writeWeights(sample());
    auto expectRefused = [](const std::string& bytes, const std::string& why, const std::string& what) {
        auto read = io::readWeights(bytes, "char.weights");
        ASSERT_FALSE(read.ok()) << what;
        const std::string text = formatAll(read.diagnostics());
        EXPECT_NE(text.find("char.weights"), std::string::npos) << text;
        EXPECT_NE(text.find(why), std::string::npos) << what << ": " << text;
    };
    expectRefused("hello", "not a Rigsmith weights file", "foreign");
    std::string flipped = good;
    flipped[30] ^= 0x40;
    expectRefused(flipped, "checksum", "one bit flipped");
    expectRefused(good.substr(0, good.size() - 9) + good.substr(good.size() - 8), "checksum", "a byte missing");
    // Every truncation is refused, none crashes.
    for (std::size_t size = 0; size < good.size(); ++size)
        EXPECT_FALSE(io::readWeights(good.substr(0, size), "char.weights").ok()) << size;
    EXPECT_FALSE(io::loadWeightsFile(test::temporaryPath("missing.weights")).ok());
}
