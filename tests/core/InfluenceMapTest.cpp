// Missing influences on import (skin/InfluenceMap.h, issue 20 item 4): a chunk
// influence lands on the rig's skin joint of its identity or name; one the rig
// does not have is mapped by a name map, re-homed on its nearest matched
// ancestor (create), or reported with the meshes that use it (stop).
#include "TestSupport.h"

#include "skin/InfluenceMap.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

// The rig: root_jnt > spine_jnt > arm_L_jnt.
struct Rig {
    std::vector<skin::SkinBone> bones;
    std::vector<std::string> names{"root_jnt", "spine_jnt", "arm_L_jnt"};
    Rig()
    {
        bones.resize(3);
        bones[0].key = {1, "", "skin.root"};
        bones[1].key = {1, "", "skin.spine"};
        bones[1].parent = 0;
        bones[2].key = {2, "L", "skin.arm"};
        bones[2].parent = 1;
    }
};

// A two-vertex chunk. Influences: root (same key), spine (another key, same
// name), elbow_old (parent spine), hand_L_jnt (parent elbow_old), unused_jnt.
// Vertex 0: root 0.5, spine 0.5; vertex 1: elbow_old 0.25, hand_L_jnt 0.75.
skin::SkinChunk chunk(const std::string& mesh)
{
    skin::SkinChunk c;
    c.mesh = mesh;
    c.weights.joints = {{1, "", "skin.root"}, {7, "", "skin.spine"}, {7, "", "skin.elbow"}, {7, "", "skin.hand"}, {7, "", "skin.x"}};
    c.weights.parents = {-1, 0, 1, 2, 0};
    c.weights.offsets = {0, 2, 4};
    c.weights.influences = {{0, 0.5f}, {1, 0.5f}, {2, 0.25f}, {3, 0.75f}};
    for (const char* name : {"root_jnt", "spine_jnt", "elbow_old", "hand_L_jnt", "unused_jnt"})
        c.joints.push_back({{}, name});
    for (std::size_t j = 0; j < c.joints.size(); ++j)
        c.joints[j].key = c.weights.joints[j];
    return c;
}

std::vector<model::Influence> weightsOf(const skin::SkinChunk& c, std::size_t v)
{
    return {c.weights.begin(v), c.weights.end(v)};
}

} // namespace

TEST(InfluenceMap, StopListsEveryMissingInfluenceWithTheMeshesThatUseIt)
{
    const Rig rig;
    auto resolved = skin::resolveInfluences({chunk("body"), chunk("shirt")}, rig.bones, rig.names, {});
    ASSERT_FALSE(resolved.ok());
    const std::string all = formatAll(resolved.diagnostics());
    EXPECT_NE(all.find("influence 'elbow_old' (weighting meshes 'body', 'shirt') is not a skin joint of the rig"), std::string::npos) << all;
    EXPECT_NE(all.find("influence 'hand_L_jnt' (weighting meshes 'body', 'shirt')"), std::string::npos) << all;
    EXPECT_EQ(all.find("unused_jnt"), std::string::npos) << "an influence without weight is never missing: " << all;
}

TEST(InfluenceMap, CreateReHomesAMissingInfluenceOnItsNearestMatchedAncestor)
{
    const Rig rig;
    skin::InfluenceMapOptions options;
    options.missing = skin::MissingInfluences::Create;
    auto resolved = skin::resolveInfluences({chunk("body")}, rig.bones, rig.names, options);
    ASSERT_TRUE(resolved.ok()) << formatAll(resolved.diagnostics());
    EXPECT_EQ(resolved->count(skin::InfluenceMatch::How::Identity), 1u);
    EXPECT_EQ(resolved->count(skin::InfluenceMatch::How::Name), 1u);
    EXPECT_EQ(resolved->count(skin::InfluenceMatch::How::Created), 2u);
    EXPECT_NE(formatAll(resolved.diagnostics()).find("influence 'hand_L_jnt' is not a skin joint of the rig; its weights go to its ancestor 'spine_jnt'"),
              std::string::npos);
    const auto chunks = skin::applyInfluences({chunk("body")}, *resolved, rig.bones, rig.names);
    EXPECT_EQ(chunks[0].weights.joints.size(), 3u);
    EXPECT_EQ(chunks[0].joints[2].name, "arm_L_jnt");
    EXPECT_EQ(weightsOf(chunks[0], 0), (std::vector<model::Influence>{{0, 0.5f}, {1, 0.5f}}));
    EXPECT_EQ(weightsOf(chunks[0], 1), (std::vector<model::Influence>{{1, 1.0f}})) << "elbow and hand both land on the spine";
}

TEST(InfluenceMap, AMapSendsMissingInfluencesToTheNamedJointsAndRefusesAnUnknownTarget)
{
    const Rig rig;
    skin::InfluenceMapOptions options;
    options.missing = skin::MissingInfluences::Map;
    options.names = {{"elbow_old", "arm_L_jnt"}, {"hand_L_jnt", "arm_L_jnt"}, {"spine_jnt", "root_jnt"}};
    auto resolved = skin::resolveInfluences({chunk("body")}, rig.bones, rig.names, options);
    ASSERT_TRUE(resolved.ok()) << formatAll(resolved.diagnostics());
    EXPECT_EQ(resolved->count(skin::InfluenceMatch::How::Mapped), 2u);
    EXPECT_NE(formatAll(resolved.diagnostics()).find("entry for 'spine_jnt' is not needed"), std::string::npos);
    const auto chunks = skin::applyInfluences({chunk("body")}, *resolved, rig.bones, rig.names);
    EXPECT_EQ(weightsOf(chunks[0], 1), (std::vector<model::Influence>{{2, 1.0f}}));

    options.names = {{"elbow_old", "arm_L_jnt"}};
    auto partial = skin::resolveInfluences({chunk("body")}, rig.bones, rig.names, options);
    ASSERT_FALSE(partial.ok());
    EXPECT_NE(formatAll(partial.diagnostics()).find("'hand_L_jnt' (weighting mesh 'body') is not a skin joint of the rig and the name map does not name it"),
              std::string::npos);
    options.names = {{"elbow_old", "elbow_L_jnt"}, {"hand_L_jnt", "arm_L_jnt"}};
    auto unknown = skin::resolveInfluences({chunk("body")}, rig.bones, rig.names, options);
    ASSERT_FALSE(unknown.ok());
    EXPECT_NE(formatAll(unknown.diagnostics()).find("sends 'elbow_old' to 'elbow_L_jnt', which is not a skin joint of the rig"), std::string::npos);
}

TEST(InfluenceMap, AChunkAlreadyOnTheRigsJointsIsLeftBitForBit)
{
    const Rig rig;
    skin::SkinChunk c;
    c.mesh = "body";
    for (std::size_t b = 0; b < rig.bones.size(); ++b) {
        c.weights.joints.push_back(rig.bones[b].key);
        c.weights.parents.push_back(rig.bones[b].parent);
        c.joints.push_back({rig.bones[b].key, rig.names[b]});
    }
    c.weights.offsets = {0, 2};
    c.weights.influences = {{2, 0.3f}, {1, 0.7f}};
    auto resolved = skin::resolveInfluences({c}, rig.bones, rig.names, {});
    ASSERT_TRUE(resolved.ok()) << formatAll(resolved.diagnostics());
    const auto chunks = skin::applyInfluences({c}, *resolved, rig.bones, rig.names);
    EXPECT_EQ(chunks[0].weights, c.weights);
}
