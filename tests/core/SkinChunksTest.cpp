// Skin chunk files (io/SkinChunks.h, issue 20): every field survives a round
// trip byte for byte; a chunk exported in a pose carries both poses; a
// damaged, truncated or foreign file is an error naming the file and the byte
// where it breaks, never a crash or a partial load.
#include "TestSupport.h"

#include "io/SkinChunks.h"
#include "rigging/RigBuilder.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cstring>

using namespace rs;

namespace {

// A posed chunk of two triangles over four vertices (three exported) with every field set.
skin::SkinChunk sampleChunk()
{
    skin::SkinChunk c;
    c.mesh = "body";
    c.model = "models/hero.fbx";
    c.tool = "rigsmith 0.1.0";
    c.user = "ana";
    c.exportedAtMicroseconds = 1714571112123456;
    c.totalVertexCount = 4;
    c.fingerprint = 0xfeedfacecafebeefull;
    c.method = skin::SkinningMethod::DualQuaternion;
    c.inBindPose = false;
    c.vertexIds = {0, 1, 3};
    c.positions = {{0, 1, 0}, {1, 1, 0}, {0, 2, 0}};
    c.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    c.bindPositions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    c.bindNormals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    c.weights.joints = {{1, "", "skin.root"}, {4, "L", "skin.limb.0"}};
    c.weights.parents = {-1, 0};
    c.weights.offsets = {0, 1, 3, 4};
    c.weights.influences = {{0, 1.0f}, {0, 0.25f}, {1, 0.75f}, {1, 1.0f}};
    skin::ChunkJoint root{c.weights.joints[0], "root_jnt", Mat4(1.0), Mat4(1.0), Mat4(1.0)};
    skin::ChunkJoint arm{c.weights.joints[1], "arm_L_jnt", glm::translate(Mat4(1.0), Vec3(0, 1, 0)), glm::translate(Mat4(1.0), Vec3(0, 1, 0)),
                         Mat4(1.0)};
    c.joints = {root, arm};
    c.triangles = {0, 1, 2};
    c.neighbourOffsets = {0, 2, 4, 5};
    c.neighbours = {1, 3, 0, 2, 0};
    return c;
}

::testing::AssertionResult refusedSaying(const std::string& bytes, const std::string& expected)
{
    auto read = io::readSkinChunks(bytes, "hero.rschunks");
    if (read.ok())
        return ::testing::AssertionFailure() << "accepted";
    const std::string text = formatAll(read.diagnostics());
    if (text.find("hero.rschunks: error: ") != 0 || text.find(expected) == std::string::npos)
        return ::testing::AssertionFailure() << text;
    return ::testing::AssertionSuccess();
}

// `bytes` with its checksum made right again (a damaged file whose checksum was rewritten).
std::string resealed(std::string bytes)
{
    const std::uint64_t sum = io::skinChunksChecksum(bytes.data(), bytes.size() - 8);
    std::memcpy(bytes.data() + bytes.size() - 8, &sum, 8);
    return bytes;
}

} // namespace

TEST(SkinChunks, ARoundTripKeepsEveryFieldByteForByte)
{
    const std::vector<skin::SkinChunk> chunks = {sampleChunk(), sampleChunk()};
    const std::string path = test::temporaryPath("round.rschunks");
    ASSERT_TRUE(test::succeeded(io::saveSkinChunkFile(path, chunks)));
    auto loaded = io::loadSkinChunkFile(path);
    ASSERT_TRUE(loaded.ok()) << formatAll(loaded.diagnostics());
    ASSERT_EQ(loaded->size(), 2u);
    const skin::SkinChunk& c = loaded->front();
    const skin::SkinChunk s = sampleChunk();
    EXPECT_EQ(c.mesh, s.mesh);
    EXPECT_EQ(c.model, s.model);
    EXPECT_EQ(c.tool, s.tool);
    EXPECT_EQ(c.user, s.user);
    EXPECT_EQ(c.exportedAtMicroseconds, s.exportedAtMicroseconds);
    EXPECT_EQ(c.totalVertexCount, 4u);
    EXPECT_EQ(c.fingerprint, s.fingerprint);
    EXPECT_EQ(c.method, skin::SkinningMethod::DualQuaternion);
    EXPECT_FALSE(c.inBindPose);
    EXPECT_EQ(c.vertexIds, s.vertexIds);
    EXPECT_EQ(c.positions, s.positions);
    EXPECT_EQ(c.bindPositions, s.bindPositions);
    EXPECT_EQ(c.bindNormals, s.bindNormals);
    EXPECT_EQ(c.weights, s.weights);
    ASSERT_EQ(c.joints.size(), 2u);
    EXPECT_EQ(c.joints[1].key, s.joints[1].key);
    EXPECT_EQ(c.joints[1].name, "arm_L_jnt");
    EXPECT_EQ(c.joints[1].world, s.joints[1].world);
    EXPECT_EQ(c.triangles, s.triangles);
    EXPECT_EQ(c.neighbourOffsets, s.neighbourOffsets);
    EXPECT_EQ(c.neighbours, s.neighbours);
    EXPECT_EQ(io::writeSkinChunks(*loaded), io::writeSkinChunks(chunks));
    EXPECT_EQ(skin::formatExportTime(s.exportedAtMicroseconds), "2024-05-01 13:45:12 UTC");

    // Empty arrays everywhere (a chunk of no vertex, no influence): found by fuzz-skinchunks
    // as a copy from no buffer (undefined behaviour even for 0 bytes).
    skin::SkinChunk empty;
    empty.mesh = "nothing";
    empty.neighbourOffsets = {0};
    empty.weights.offsets = {0};
    const std::string bytes = io::writeSkinChunks({empty});
    auto read = io::readSkinChunks(bytes, "empty.rschunks");
    ASSERT_TRUE(read.ok()) << formatAll(read.diagnostics());
    EXPECT_EQ(io::writeSkinChunks(*read), bytes);
}

TEST(SkinChunks, DamagedOrTruncatedFilesAreErrorsNamingTheByte)
{
    const std::string good = io::writeSkinChunks({sampleChunk()});
    EXPECT_TRUE(refusedSaying("PK\x03\x04 a zip", "not a Rigsmith skin chunk file"));
    EXPECT_TRUE(refusedSaying("RSCHUNKS", "ends early at byte 8"));
    std::string flipped = good;
    flipped[40] ^= 0x10;
    EXPECT_TRUE(refusedSaying(flipped, "checksum (the last 8 bytes, at byte " + std::to_string(good.size() - 8) + ")"));
    for (std::size_t size = 0; size < good.size(); ++size)
        EXPECT_FALSE(io::readSkinChunks(good.substr(0, size), "hero.rschunks").ok()) << "truncated to " << size << " bytes";
    // Truncated with the checksum rewritten: the structure check names where it ends.
    EXPECT_TRUE(refusedSaying(resealed(good.substr(0, good.size() - 20) + std::string(8, '\0')), "at byte"));

    // A chunk count far past what the file holds, at byte 12 (magic 8, version 4).
    std::string counted = good;
    const std::uint32_t huge = 0x7fffffff;
    std::memcpy(counted.data() + 12, &huge, 4);
    EXPECT_TRUE(refusedSaying(resealed(counted), "a count of 2147483647 chunks is more than the file holds at byte 12"));

    // A vertex id past the mesh's vertex count, at the byte where the ids start.
    skin::SkinChunk badId = sampleChunk();
    badId.vertexIds = {0, 1, 7};
    const std::string withBadId = io::writeSkinChunks({badId});
    std::uint32_t seven = 7;
    std::size_t at = 0;
    for (std::size_t k = 16; k + 12 <= withBadId.size(); ++k)
        if (std::memcmp(withBadId.data() + k, "\0\0\0\0\1\0\0\0\7\0\0\0", 12) == 0) { // ids 0, 1, 7
            at = k + 8;
            break;
        }
    ASSERT_GT(at, 0u);
    EXPECT_EQ(std::memcmp(withBadId.data() + at, &seven, 4), 0);
    EXPECT_TRUE(refusedSaying(withBadId, "chunk 0 ('body'): vertex id 7 is not below the mesh's vertex count 4 at byte " + std::to_string(at)));

    skin::SkinChunk cycle = sampleChunk();
    cycle.weights.parents = {1, 0};
    EXPECT_TRUE(refusedSaying(io::writeSkinChunks({cycle}), "parents form a cycle"));
    skin::SkinChunk badWeight = sampleChunk();
    badWeight.weights.influences[1].weight = 3.0f;
    EXPECT_TRUE(refusedSaying(io::writeSkinChunks({badWeight}), "a weight is outside [0, 1] at byte"));
    skin::SkinChunk badCorner = sampleChunk();
    badCorner.triangles = {0, 1, 3};
    EXPECT_TRUE(refusedSaying(io::writeSkinChunks({badCorner}), "a triangle corner 3 is not one of the 3 exported vertices"));
    EXPECT_TRUE(refusedSaying(resealed(good.substr(0, good.size() - 8) + "xx" + good.substr(good.size() - 8)), "unexpected bytes after the last chunk"));
    EXPECT_FALSE(io::loadSkinChunkFile(test::temporaryPath("missing.rschunks")).ok());
}

TEST(SkinChunks, AChunkExportedInAPoseCarriesBothPoses)
{
    const model::GuideDocument guide = test::loadSample("biped");
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    const auto bones = skin::skinBones(rig).take();
    model::Rig posed = rig; // every node a metre along +x: every vertex follows
    for (model::RigNode& node : posed.nodes)
        node.worldMatrix = glm::translate(Mat4(1.0), Vec3(1, 0, 0)) * node.worldMatrix;
    model::Mesh mesh;
    mesh.name = "patch";
    mesh.positions = {{0, 1, 0}, {0.1f, 1, 0}, {0, 1.1f, 0}, {0.1f, 1.1f, 0}};
    mesh.indices = {0, 1, 2, 1, 3, 2};
    model::MeshWeights weights;
    for (const skin::SkinBone& bone : bones) {
        weights.joints.push_back(bone.key);
        weights.parents.push_back(bone.parent);
    }
    weights.offsets = {0, 1, 2, 3, 5};
    weights.influences = {{0, 1.0f}, {1, 1.0f}, {2, 1.0f}, {1, 0.5f}, {2, 0.5f}};
    skin::ChunkExportOptions options;
    options.rig = &rig;
    options.posedRig = &posed;
    auto chunk = skin::makeSkinChunk({&mesh, &weights, "patch.obj", {1, 3}}, bones, options);
    ASSERT_TRUE(chunk.ok()) << formatAll(chunk.diagnostics());
    EXPECT_FALSE(chunk->inBindPose);
    EXPECT_EQ(chunk->vertexIds, (std::vector<std::uint32_t>{1, 3}));
    ASSERT_EQ(chunk->positions.size(), 2u);
    EXPECT_NEAR(chunk->positions[1].x, 1.1f, 1e-5);
    EXPECT_EQ(chunk->bindPositions[1], mesh.positions[3]);
    EXPECT_NEAR(chunk->normals[0].z, 1.0f, 1e-5); // computed from the triangles (the mesh has none)
    EXPECT_TRUE(chunk->triangles.empty()) << "no triangle has all three corners exported";
    EXPECT_EQ(chunk->neighbourOffsets.size(), 3u);
    EXPECT_EQ(chunk->joints[1].name, rig.nodes[bones[1].node].name);
    EXPECT_EQ(chunk->joints[1].bind, rig.nodes[bones[1].node].worldMatrix);
    auto back = io::readSkinChunks(io::writeSkinChunks({*chunk}), "patch.rschunks");
    ASSERT_TRUE(back.ok()) << formatAll(back.diagnostics());
    EXPECT_EQ(back->front().weights, chunk->weights);
    EXPECT_FALSE(skin::makeSkinChunk({&mesh, &weights, "", {9}}, bones, options).ok()) << "a vertex the mesh does not have";
}
