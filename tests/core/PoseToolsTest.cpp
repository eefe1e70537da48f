// Pose tools and pickwalk on the biped: mirror/flip symmetry, FK/IK matching,
// space switching without jumps, resets, the undoable pose edit, and the
// animator's arrow-key walks.
#include "EvalTestSupport.h"
#include "edit/GuideEdits.h"
#include "io/GuideFile.h"

#include <gtest/gtest.h>

#include <random>

namespace rs {
namespace {

using eval::Pose;
using eval::WalkDirection;
using test::PosedRig;

Mat4 reflected(const Mat4& m)
{
    const Mat4 mirror = glm::scale(Mat4(1.0), Vec3(-1.0, 1.0, 1.0));
    return mirror * m * mirror;
}

// Random rotations (and some translation) on every animatable left-side control.
Pose randomLeftPose(const PosedRig& r, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> angle(-35.0, 35.0), offset(-0.05, 0.05), custom(0.0, 1.0);
    Pose pose = r.defaults();
    const auto& layout = r.program->channels();
    for (std::size_t i = 0; i < layout.size(); ++i) {
        const auto& c = layout[i];
        const std::string& id = r.rig.nodes[c.node].path;
        if (c.locked || id.find(".L::") == std::string::npos || c.isEnum())
            continue;
        if (c.transform >= 0 && c.transform < 3) pose[i] = offset(random);
        else if (c.transform >= 3 && c.transform < 6) pose[i] = angle(random);
        else if (c.transform < 0) pose[i] = layout.clamp(int(i), c.min + (c.max - c.min) * custom(random));
    }
    return pose;
}

TEST(PoseTools, MirroredBipedPoseIsSymmetricWithinAMicrometre)
{
    PosedRig r("biped");
    std::vector<model::RigNodeIndex> left;
    for (model::RigNodeIndex i : r.rig.sets.at("controllers"))
        if (r.rig.nodes[i].path.find(".L::") != std::string::npos)
            left.push_back(i);
    ASSERT_GT(left.size(), 30u);
    const Pose pose = r.posing->mirror(randomLeftPose(r, 11), left);
    const auto& state = r.evaluate(pose);
    int pairs = 0;
    for (model::RigNodeIndex i = 0; i < r.rig.nodes.size(); ++i) {
        const auto& node = r.rig.nodes[i];
        if (node.twin == model::kNoNode || node.path.find(".L::") == std::string::npos)
            continue;
        ++pairs;
        EXPECT_LT(maxAbsDifference(state.worldMatrix(node.twin), reflected(state.worldMatrix(i))), 1e-6) << node.path;
    }
    EXPECT_GT(pairs, 100);
}

TEST(PoseTools, FlipSwapsTheSidesAndTwiceGivesThePoseBack)
{
    PosedRig r("biped");
    const Pose pose = randomLeftPose(r, 5);
    const auto& controllers = r.rig.sets.at("controllers");
    const Pose flipped = r.posing->flip(pose, controllers);
    const Mat4 leftHand = r.evaluate(pose).worldMatrix(r.index("arm.L::skin.limb.2"));
    EXPECT_LT(maxAbsDifference(r.evaluate(flipped).worldMatrix(r.index("arm.R::skin.limb.2")), reflected(leftHand)), 1e-6);
    const Pose back = r.posing->flip(flipped, controllers);
    for (std::size_t i = 0; i < pose.size(); ++i)
        EXPECT_NEAR(back[i], pose[i], 1e-9) << r.program->channels()[i].name;
}

TEST(PoseTools, IkToFkAndFkToIkMatchWithinTenMicrometres)
{
    PosedRig r("biped");
    for (const std::string limb : {"arm.L", "leg.R"}) {
        // An IK pose, matched onto FK: the blended chain must not move.
        Pose pose = r.defaults();
        pose[r.channel(limb + "::ctrls.switch", "ik_blend")] = 1.0;
        const Vec3 wrist = r.restPosition(limb + "::ik.2");
        pose = r.moveTo(pose, limb + "::ctrls.ik", wrist + Vec3(0.05, 0.1, 0.08), limb + "::ik.2");
        pose[r.channel(limb + "::ctrls.ik", "rz")] = 25.0;
        std::vector<Mat4> before;
        r.evaluate(pose);
        for (int i = 0; i < 3; ++i) before.push_back(r.state().worldMatrix(r.index(limb + "::blend." + std::to_string(i))));
        auto fk = r.posing->ikToFk(pose, r.index(limb + "::ctrls.switch"));
        ASSERT_TRUE(fk) << formatAll(fk.diagnostics());
        EXPECT_EQ((*fk)[r.channel(limb + "::ctrls.switch", "ik_blend")], 0.0);
        r.evaluate(*fk);
        for (int i = 0; i < 3; ++i)
            EXPECT_LT(maxAbsDifference(r.state().worldMatrix(r.index(limb + "::blend." + std::to_string(i))), before[i]), 1e-5)
                << limb << " FK " << i;
        // And back: the FK pose matched onto IK.
        auto ik = r.posing->fkToIk(*fk, r.index(limb + "::ctrls.fk.1"));
        ASSERT_TRUE(ik) << formatAll(ik.diagnostics());
        r.evaluate(*ik);
        for (int i = 0; i < 3; ++i)
            EXPECT_LT(maxAbsDifference(r.state().worldMatrix(r.index(limb + "::blend." + std::to_string(i))), before[i]), 1e-5)
                << limb << " IK " << i;
    }
    const model::RigNodeIndex head = r.index("neck::ctrls.head");
    const auto refused = r.posing->ikToFk(r.defaults(), head);
    ASSERT_FALSE(refused);
    ASSERT_EQ(refused.diagnostics().size(), 1u);
    EXPECT_EQ(refused.diagnostics().front().message, "'neck::ctrls.head' is not on an FK/IK limb to match");
    EXPECT_EQ(refused.diagnostics().front().subject, Subject::ofNode(r.rig.nodes[head].key)) << "names the head control";
    EXPECT_FALSE(r.posing->fkToIk(r.defaults(), model::RigNodeIndex(r.rig.nodes.size()))) << "a node past the rig is refused";
}

TEST(PoseTools, SpaceSwitchWithMatchingKeepsTheHeadWhereItIs)
{
    PosedRig r("biped");
    Pose pose = r.defaults();
    pose[r.channel("neck::ctrls.fk.0", "rz")] = 30.0;
    pose[r.channel("spine::ctrls.fk.2", "rx")] = -20.0;
    pose[r.channel("neck::ctrls.head", "ry")] = 15.0;
    const int space = r.channel("neck::ctrls.head", "space");
    const Mat4 before = r.evaluate(pose).worldMatrix(r.index("neck::skin.head"));
    for (double target : {3.0, 2.0, 1.0, 0.0}) {
        pose = r.posing->switchSpace(pose, space, target, true);
        EXPECT_EQ(pose[space], target);
        EXPECT_LT(maxAbsDifference(r.evaluate(pose).worldMatrix(r.index("neck::skin.head")), before), 1e-9) << target;
    }
    // Without matching the head takes the new space's orientation and jumps.
    const Pose jumped = r.posing->switchSpace(pose, space, 3.0, false);
    EXPECT_GT(maxAbsDifference(r.evaluate(jumped).worldMatrix(r.index("neck::skin.head")), before), 0.01);
}

TEST(PoseTools, IkControlInCogSpaceFollowsTheCogAfterAMatchedSwitch)
{
    PosedRig r("biped");
    Pose pose = r.defaults();
    pose[r.channel("spine::ctrls.cog", "tx")] = 0.1;
    pose[r.channel("spine::ctrls.cog", "ry")] = 20.0;
    const int space = r.channel("arm.L::ctrls.ik", "space");
    EXPECT_EQ(pose[space], 0.0); // world by default
    const Mat4 before = r.evaluate(pose).worldMatrix(r.index("arm.L::ctrls.ik"));
    pose = r.posing->switchSpace(pose, space, 2.0, true); // cog, matched
    EXPECT_LT(maxAbsDifference(r.evaluate(pose).worldMatrix(r.index("arm.L::ctrls.ik")), before), 1e-9);
    pose[r.channel("spine::ctrls.cog", "ty")] = -0.2; // the cog drops: the hand goes with it
    r.evaluate(pose);
    EXPECT_NEAR(r.position("arm.L::ctrls.ik").y, translationOf(before).y - 0.2, 1e-9);
}

TEST(PoseTools, RotateOrderChangesKeepTheOrientationWhenMatched)
{
    PosedRig r("biped");
    Pose pose = r.defaults();
    const std::string hand = "arm.L::ctrls.fk.2";
    pose[r.channel(hand, "rx")] = 30.0;
    pose[r.channel(hand, "ry")] = -50.0;
    pose[r.channel(hand, "rz")] = 70.0;
    const int order = r.channel(hand, "ro");
    EXPECT_EQ(pose[order], 0.0); // xyz by default
    EXPECT_EQ(r.program->channels()[order].labels->at(5), "zyx");
    const Mat4 before = r.evaluate(pose).worldMatrix(r.index(hand));
    for (double o : {1.0, 2.0, 3.0, 4.0, 5.0}) {
        const Pose switched = r.posing->switchSpace(pose, order, o, true);
        EXPECT_EQ(switched[order], o);
        EXPECT_LT(maxAbsDifference(r.evaluate(switched).worldMatrix(r.index(hand)), before), 1e-9) << o;
        EXPECT_GT(std::abs(switched[r.channel(hand, "rx")] - 30.0), 1e-3) << o; // other angles, same orientation
    }
    const Pose unmatched = r.posing->switchSpace(pose, order, 5.0, false);
    EXPECT_GT(maxAbsDifference(r.evaluate(unmatched).worldMatrix(r.index(hand)), before), 0.01);
}

TEST(PoseTools, ResetRestoresDefaultsAndKeepsLockedChannels)
{
    PosedRig r("biped");
    Pose pose = randomLeftPose(r, 2);
    const auto hand = r.index("arm.L::ctrls.fk.2");
    const Pose one = r.posing->reset(pose, {hand});
    const int first = r.program->channels().firstOf(hand);
    for (int i = first; i < first + r.program->channels().countOf(hand); ++i)
        EXPECT_EQ(one[i], r.program->channels()[i].defaultValue);
    EXPECT_NE(one, r.defaults());
    EXPECT_EQ(r.posing->reset(pose, {}), r.defaults());
    // The pole's rotation is locked: no tool writes it.
    EXPECT_TRUE(r.program->channels()[r.channel("arm.L::ctrls.pole", "rx")].locked);
    EXPECT_TRUE(r.program->channels()[r.channel("arm.L::ctrls.switch", "tx")].locked);
}

TEST(PoseTools, PoseEditsAreUndoableAndSavedWithTheGuide)
{
    PosedRig r("biped");
    model::GuideDocument guide = test::loadSample("biped");
    edit::History history(guide);
    Pose pose = r.defaults();
    pose[r.channel("arm.L::ctrls.fk.0", "rz")] = 45.0;
    ASSERT_TRUE(test::succeeded(
        edit::setPose(history, eval::valuesFromPose(r.rig, r.program->channels(), pose, model::testPose(guide.overrides)), "Rotate c_arm1_L")));
    EXPECT_EQ(history.undoText(), "Rotate c_arm1_L");
    EXPECT_EQ(model::testPose(guide.overrides).at(r.rig.nodes[r.index("arm.L::ctrls.fk.0")].key).at("rz"), 45.0);
    EXPECT_TRUE(edit::setPose(history, model::testPose(guide.overrides), "nothing").failed()); // refused: no empty step
    const auto reread = io::readGuideText(io::writeGuideText(guide), "pose.yml");
    ASSERT_TRUE(reread.ok());
    EXPECT_EQ(reread->overrides, guide.overrides);
    EXPECT_EQ(eval::poseFromValues(r.rig, r.program->channels(), model::testPose(reread->overrides)), pose);
    history.undo();
    EXPECT_TRUE(model::testPose(guide.overrides).empty());
}

TEST(PoseTools, PosedRigCarriesTheGuidePoseForDumpsAndExports)
{
    PosedRig r("biped");
    model::PoseValues values{{r.rig.nodes[r.index("arm.L::ctrls.switch")].key, {{"ik_blend", 0.0}}},
                             {r.rig.nodes[r.index("arm.L::ctrls.fk.0")].key, {{"rz", -50.0}}}};
    auto posed = eval::posedRig(r.rig, values);
    ASSERT_TRUE(posed.ok());
    const auto& state = r.evaluate(eval::poseFromValues(r.rig, r.program->channels(), values));
    const auto hand = r.index("arm.L::skin.limb.2");
    EXPECT_LT(maxAbsDifference(posed->nodes[hand].worldMatrix, state.worldMatrix(hand)), 1e-12);
    EXPECT_GT(glm::length(translationOf(posed->nodes[hand].worldMatrix) - translationOf(r.rig.nodes[hand].worldMatrix)), 0.2);
    const auto parent = posed->nodes[hand].parent;
    EXPECT_LT(maxAbsDifference(posed->nodes[parent].worldMatrix * posed->nodes[hand].localMatrix, posed->nodes[hand].worldMatrix), 1e-9);
}

TEST(Pickwalk, WalksTheBipedControllersAcrossTemplates)
{
    PosedRig r("biped");
    auto walk = [&](const std::string& from, std::initializer_list<WalkDirection> keys) {
        model::RigNodeIndex at = r.index(from);
        for (auto key : keys) at = eval::pickwalk(r.rig, at, key);
        return r.rig.nodes[at].path;
    };
    using enum WalkDirection;
    EXPECT_EQ(walk("arm.L::ctrls.fk.2", {Up}), "arm.L::ctrls.fk.1");
    EXPECT_EQ(walk("arm.L::ctrls.fk.2", {Up, Up, Up}), "arm.L::ctrls.clavicle");
    EXPECT_EQ(walk("arm.L::ctrls.fk.0", {Down, Down}), "arm.L::ctrls.fk.2");
    EXPECT_EQ(walk("arm.L::ctrls.fk.1", {Mirror}), "arm.R::ctrls.fk.1");
    EXPECT_EQ(walk("arm.R::ctrls.fk.1", {Mirror}), "arm.L::ctrls.fk.1");
    EXPECT_EQ(walk("spine::ctrls.cog", {Mirror}), "spine::ctrls.cog"); // centre: stays
    EXPECT_EQ(walk("world::ctrls.world", {Up}), "world::ctrls.world"); // the top: stays
    EXPECT_EQ(walk("spine::ctrls.cog", {Up}), "world::ctrls.fly");     // across templates
    EXPECT_EQ(walk("index.L::ctrls.fk.0", {Up}), "hand.L::ctrls.hand");            // finger to its hand master
    EXPECT_EQ(walk("index.L::ctrls.fk.0", {Up, Up}).rfind("arm.L::ctrls.", 0), 0u); // and on to the arm
    // Siblings wrap: going right through all of them comes back.
    const auto siblings = r.rig.virtualChildren(r.rig.nodes[r.index("index.L::ctrls.fk.0")].virtualParent);
    model::RigNodeIndex at = r.index("index.L::ctrls.fk.0");
    std::vector<std::string> seen;
    for (int i = 0; i < 16 && (i == 0 || at != r.index("index.L::ctrls.fk.0")); ++i) {
        seen.push_back(r.rig.nodes[at].path);
        at = eval::pickwalk(r.rig, at, Right);
    }
    EXPECT_EQ(at, r.index("index.L::ctrls.fk.0"));
    EXPECT_GE(seen.size(), 5u); // thumb, index, middle, ring, pinky under the hand
    EXPECT_EQ(walk("index.L::ctrls.fk.0", {Right, Left}), "index.L::ctrls.fk.0");
}

TEST(Pickwalk, WalksTemplateInstancesInTheOutliner)
{
    model::GuideDocument guide = test::loadSample("biped");
    auto id = [&](const std::string& name) { return guide.instanceNamed(name)->id; };
    auto name = [&](model::InstanceId i) { return guide.instance(i)->name; };
    EXPECT_EQ(name(eval::pickwalk(guide, id("arm"), WalkDirection::Up)), "spine");
    EXPECT_EQ(name(eval::pickwalk(guide, id("arm"), WalkDirection::Down)), "hand");
    EXPECT_EQ(name(eval::pickwalk(guide, id("hand"), WalkDirection::Down)), "thumb");
    EXPECT_EQ(name(eval::pickwalk(guide, id("thumb"), WalkDirection::Right)), "index");
    EXPECT_EQ(name(eval::pickwalk(guide, id("thumb"), WalkDirection::Left)), "pinky"); // wraps
    EXPECT_EQ(name(eval::pickwalk(guide, id("world"), WalkDirection::Up)), "world");
}

} // namespace
} // namespace rs
