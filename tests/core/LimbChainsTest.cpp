// A limb's extra twist chains (issue 22; option `add_chains` of arm.limb,
// leg.limb, quad.leg) as a rigger checks them: one skin joint per twist joint
// and chain, each under its own tweak control, sitting on the twist joints at
// rest and following them through an IK pose and bent segments; a tweak's
// offset moves its joint alone; the right side mirrors the left; the export
// carries them as skin joints; bad names are refused where they are written;
// an incremental rebuild makes what a full build makes.
#include "EvalTestSupport.h"
#include "IncrementalCheck.h"
#include "io/GuideFile.h"
#include "io/RigExport.h"
#include "io/SkinnedMesh.h"
#include "model/Skeleton.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <algorithm>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

const char* const kLimbs[] = {"arm.L", "arm.R", "leg.L", "leg.R"};

model::GuideDocument chainedBiped() { return test::bipedLimbsWith({{"add_chains", Value(std::string("[sleeve, bulge]"))}}); }

Mat4 reflected(const Mat4& m)
{
    const Mat4 mirror = glm::scale(Mat4(1.0), Vec3(-1.0, 1.0, 1.0));
    return mirror * m * mirror;
}

// Every chain joint of the rig with the twist joint it rides ("arm.L::skin.up.sleeve.0" on "arm.L::skin.up.0").
std::vector<std::pair<std::string, std::string>> chainJoints()
{
    std::vector<std::pair<std::string, std::string>> out;
    for (const std::string limb : kLimbs)
        for (const char* chain : {"sleeve", "bulge"})
            for (const char* segment : {"up", "dn"})
                for (int t = 0; t < 2; ++t) {
                    const std::string at = segment + std::string(".") + std::to_string(t);
                    out.push_back({limb + "::skin." + segment + "." + chain + "." + std::to_string(t), limb + "::skin." + at});
                }
    return out;
}

TEST(LimbChains, ChainJointsSitOnTheTwistJointsAndFollowThemThroughAnIkPoseAndBentSegments)
{
    PosedRig r(chainedBiped()); // the biped's limbs are bendy
    ASSERT_TRUE(r.ok());
    const auto joints = chainJoints();
    ASSERT_EQ(joints.size(), 32u); // 4 limbs, 2 chains, 2 segments, 2 twist joints
    for (const auto& [chain, twist] : joints) {
        const auto& node = r.rig.nodes[r.index(chain)];
        EXPECT_EQ(node.kind, model::RigNodeKind::Joint) << chain;
        EXPECT_LT(maxAbsDifference(node.worldMatrix, r.rig.nodes[r.index(twist)].worldMatrix), 1e-12) << chain << " at rest";
    }
    Pose pose = r.defaults();
    for (const std::string limb : kLimbs) {
        pose[r.channel(limb + "::ctrls.switch", "ik_blend")] = 1.0;
        pose = r.moveTo(pose, limb + "::ctrls.ik", r.restPosition(limb + "::ik.2") + Vec3(0.04, 0.15, 0.1), limb + "::ik.2");
        pose[r.channel(limb + "::ctrls.ik", "ry")] = 40.0;
        pose = r.moveTo(pose, limb + "::ctrls.bend.dn", r.restPosition(limb + "::ctrls.bend.dn") + Vec3(0.0, 0.03, 0.02),
                        limb + "::ctrls.bend.dn");
    }
    r.evaluate(pose);
    for (const auto& [chain, twist] : joints) {
        EXPECT_GT(glm::length(r.position(twist) - r.restPosition(twist)), 0.01) << twist << " moved";
        EXPECT_LT(maxAbsDifference(r.state().worldMatrix(r.index(chain)), r.state().worldMatrix(r.index(twist))), 1e-9) << chain;
    }
}

TEST(LimbChains, ATweakOffsetMovesItsChainJointAloneOnTopOfTheTwist)
{
    PosedRig r(chainedBiped());
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    pose[r.channel("arm.L::ctrls.fk.1", "rz")] = 50.0;
    pose[r.channel("arm.L::ctrls.switch", "ik_blend")] = 0.0;
    const auto& before = r.evaluate(pose).world;
    const std::vector<eval::Affine> still(before.begin(), before.end());
    const std::string tweak = "arm.L::ctrls.dn.sleeve.1", joint = "arm.L::skin.dn.sleeve.1", twist = "arm.L::skin.dn.1";
    pose[r.channel(tweak, "ty")] = 0.02; // a bulge: out along the twist joint's Y, turned and swollen
    pose[r.channel(tweak, "rx")] = 20.0;
    pose[r.channel(tweak, "sz")] = 1.5;
    r.evaluate(pose);
    const eval::Affine& twistWorld = r.state().world[r.index(twist)];
    const Mat3 twistRotation = twistWorld.rotation();
    EXPECT_LT(glm::length(r.position(joint) - (twistWorld.translation + twistRotation[1] * 0.02 * twistWorld.scale().y)), 1e-9);
    EXPECT_NEAR(r.state().world[r.index(joint)].scale().z / twistWorld.scale().z, 1.5, 1e-9);
    int moved = 0;
    for (model::RigNodeIndex i = 0; i < r.rig.nodes.size(); ++i)
        if (maxAbsDifference(r.state().world[i].matrix(), still[i].matrix()) > 1e-12) {
            ++moved;
            EXPECT_TRUE(r.rig.nodes[i].path == tweak || r.rig.nodes[i].path == joint) << r.rig.nodes[i].path << " moved";
        }
    EXPECT_EQ(moved, 2);
}

TEST(LimbChains, TheRightChainsAreTheMirrorOfTheLeftAndNamedForTheirSide)
{
    PosedRig r(chainedBiped());
    ASSERT_TRUE(r.ok());
    for (const auto& [chain, twist] : chainJoints()) {
        if (chain.find(".L::") == std::string::npos)
            continue;
        const auto& left = r.rig.nodes[r.index(chain)];
        ASSERT_NE(left.twin, model::kNoNode) << chain;
        EXPECT_LT(maxAbsDifference(r.rig.nodes[left.twin].worldMatrix, reflected(left.worldMatrix)), 1e-12) << chain;
        EXPECT_EQ(left.name.back(), 'L') << left.name;
        EXPECT_EQ(r.rig.nodes[left.twin].name.back(), 'R') << r.rig.nodes[left.twin].name;
    }
    // Named through the naming engine from the token "<chain>_<segment>", numbered from 1.
    for (const char* id : {"arm.L::skin.up.sleeve.0", "arm.R::ctrls.dn.bulge.1"}) {
        const std::string& name = r.rig.nodes[r.index(id)].name;
        const bool up = std::string(id).find(".up.") != std::string::npos;
        EXPECT_NE(name.find(up ? "sleeve_up1" : "bulge_dn2"), std::string::npos) << id << ": " << name;
    }
    EXPECT_NE(r.rig.nodes[r.index("arm.L::skin.up.sleeve.0")].name, r.rig.nodes[r.index("arm.L::ctrls.up.sleeve.0")].name);
    // Pickwalk: the tweaks hang under the switch control.
    EXPECT_EQ(r.rig.nodes[r.index("arm.L::ctrls.up.sleeve.0")].virtualParent, r.index("arm.L::ctrls.switch"));
    EXPECT_EQ(r.rig.nodes[r.index("leg.R::ctrls.dn.bulge.1")].virtualParent, r.index("leg.R::ctrls.switch"));
}

TEST(LimbChains, ExportCarriesTheChainJointsAsSkinJoints)
{
    const model::GuideDocument guide = chainedBiped();
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    ASSERT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    auto skeleton = model::extractSkeleton(rig);
    ASSERT_TRUE(skeleton.ok()) << formatAll(skeleton.diagnostics());
    std::map<std::string, const model::SkeletonJoint*> byPath;
    for (const auto& joint : skeleton->joints)
        byPath[rig.nodes[joint.node].path] = &joint;
    const std::vector<io::SkinnedMesh> meshes{io::proxyMesh(*skeleton, 3000)};
    io::ExportOptions options;
    options.guide = &guide;
    options.meshes = &meshes;
    const std::string path = test::temporaryPath("limb-chains.glb");
    const Diagnostics report = io::exportRig(rig, path, options);
    ASSERT_FALSE(hasErrors(report)) << formatAll(report);
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    for (const auto& [chain, twist] : chainJoints()) {
        ASSERT_TRUE(byPath.count(chain)) << chain << " is a skin joint of the export skeleton";
        const model::SkeletonJoint& joint = *byPath[chain];
        const std::string segmentStart = chain.substr(0, chain.find("::")) + (chain.find("::skin.up.") != std::string::npos
                                                                                   ? "::skin.limb.0" : "::skin.limb.1");
        ASSERT_GE(joint.parent, 0);
        EXPECT_EQ(rig.nodes[skeleton->joints[std::size_t(joint.parent)].node].path, segmentStart) << chain;
        EXPECT_LT(maxAbsDifference(joint.bindWorld, rig.nodes[byPath[twist]->node].worldMatrix), 1e-12) << chain;
        const aiNode* node = scene->mRootNode->FindNode(joint.name.c_str());
        ASSERT_NE(node, nullptr) << joint.name << " in the glTF";
        EXPECT_EQ(std::string(node->mParent->mName.C_Str()), skeleton->joints[std::size_t(joint.parent)].name) << joint.name;
    }
}

TEST(LimbChains, BadChainNamesAreRefusedWhereTheyAreWritten)
{
    std::string text = io::writeGuideText(test::loadSample("biped"));
    const std::string anchor = "    template: arm.limb\n";
    const std::size_t at = text.find("    options:\n", text.find(anchor));
    ASSERT_NE(at, std::string::npos);
    text.insert(at + 13, "      add_chains: [sleeve, 2nd, sleeve]\n");
    const std::size_t line = std::count(text.begin(), text.begin() + long(at) + 13, '\n') + 1;
    auto read = io::readGuideText(text, "bad.yml");
    ASSERT_FALSE(read.ok());
    const std::string all = formatAll(read.diagnostics());
    const std::string where = "bad.yml:" + std::to_string(line) + ":19: error: option add_chains ";
    EXPECT_NE(all.find(where + "'2nd' is no chain name"), std::string::npos) << all;
    EXPECT_NE(all.find(where + "names 'sleeve' twice"), std::string::npos) << all;
    // Set another way (an edit, the API): the build refuses it, naming the option.
    for (const std::string bad : {"[1st]", "[a, a]", "[sle-eve]", "{a: 1}"}) {
        const model::Rig rig = rigging::buildRig(test::bipedLimbsWith({{"add_chains", Value(bad)}}), test::builtinTemplates());
        EXPECT_TRUE(hasErrors(rig.diagnostics)) << bad;
        EXPECT_NE(formatAll(rig.diagnostics).find("option 'add_chains'"), std::string::npos) << bad << ": " << formatAll(rig.diagnostics);
    }
}

TEST(LimbChains, WithoutTwistJointsAChainWarnsAndAddsNothing)
{
    const model::Rig rig = rigging::buildRig(
        test::bipedLimbsWith({{"add_chains", Value(std::string("[sleeve]"))}, {"twist_upper", Value(0LL)}, {"twist_lower", Value(0LL)}}),
        test::builtinTemplates());
    EXPECT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    int warnings = 0;
    for (const auto& d : rig.diagnostics)
        warnings += d.message.find("add_chains: the limb has no twist joints") != std::string::npos ? 1 : 0;
    EXPECT_EQ(warnings, 4) << formatAll(rig.diagnostics);
    EXPECT_FALSE(rig.findPath("arm.L::skin.up.sleeve.0"));
}

TEST(LimbChains, ChainsRebuildIncrementallyAsAFullBuild)
{
    model::GuideDocument guide = test::bipedLimbsWith({{"add_chains", Value(std::string(""))}});
    rigging::BuildCache cache;
    test::buildAndCompare(guide, cache, "first build");
    for (const auto& i : guide.instances())
        if (i.name == "leg")
            guide.instance(i.id)->options["add_chains"] = Value(std::string("[front]"));
    test::buildAndCompare(guide, cache, "a chain on the legs");
    for (const auto& i : guide.instances())
        if (i.name == "leg")
            guide.instance(i.id)->options["add_chains"] = Value(std::string("[front, back]"));
    test::buildAndCompare(guide, cache, "two chains");
    for (const auto& i : guide.instances())
        if (i.name == "leg")
            guide.instance(i.id)->options["twist_lower"] = Value(3LL);
    test::buildAndCompare(guide, cache, "three lower twist joints");
    for (const auto& i : guide.instances())
        if (i.name == "leg")
            guide.instance(i.id)->options["add_chains"] = Value(std::string(""));
    test::buildAndCompare(guide, cache, "no chain");
}

} // namespace
} // namespace rs
