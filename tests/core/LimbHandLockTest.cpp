// An arm's reverse lock (issue 22; option `reverse_lock` of arm.limb, off by
// default) as an animator checks it on the built and evaluated biped: a hand
// planted in IK rolls about the knuckles with the tip staying put, rocks back
// on the wrist, rolls onto the fingertips past the break and banks onto one
// edge; the right hand mirrors the left; off, the arm is today's; an
// incremental rebuild makes what a full build makes.
#include "EvalTestSupport.h"
#include "IncrementalCheck.h"
#include "io/RigDump.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

model::GuideDocument bipedWithLockedHands(bool on = true)
{
    model::GuideDocument guide = test::loadSample("biped");
    for (const auto& i : guide.instances())
        if (i.name == "arm")
            guide.instance(i.id)->options["reverse_lock"] = Value(on);
    return guide;
}

// Where a point that sits at `restPoint` at rest is carried by `joint` now.
Vec3 carried(const PosedRig& r, const std::string& joint, const Vec3& restPoint)
{
    const model::RigNodeIndex n = r.index(joint);
    return (r.state().world[n] * eval::Affine::fromMatrix(r.rig.nodes[n].worldMatrix).inverse()).apply(restPoint);
}

// Both hands planted in IK, moved and turned a little off their rest place.
Pose plantedPose(PosedRig& r)
{
    Pose pose = r.defaults();
    for (const std::string arm : {"arm.L", "arm.R"}) {
        pose[r.channel(arm + "::ctrls.switch", "ik_blend")] = 1.0;
        pose[r.channel(arm + "::ctrls.ik", "ty")] = -0.1;
        pose[r.channel(arm + "::ctrls.ik", "tz")] = 0.05;
        pose[r.channel(arm + "::ctrls.ik", "ry")] = arm.back() == 'L' ? 20.0 : -20.0;
    }
    return pose;
}

TEST(LimbHandLock, RollingTheHandAboutTheKnucklesKeepsTheTipPlanted)
{
    PosedRig r(bipedWithLockedHands());
    ASSERT_TRUE(r.ok());
    for (const std::string arm : {"arm.L", "arm.R"}) {
        Pose pose = plantedPose(r);
        r.evaluate(pose);
        const std::string wrist = arm + "::blend.2", ik = arm + "::ctrls.ik";
        const Vec3 tipRest = r.restPosition(arm + "::rfoot.ball"), toeRest = r.restPosition(arm + "::rfoot.toe");
        const Vec3 tip = carried(r, wrist, tipRest), fingertips = carried(r, wrist, toeRest), wristAt = r.position(wrist);
        for (const double roll : {10.0, 25.0}) { // about the knuckles, below the 30 degree break
            pose[r.channel(ik, "roll")] = roll;
            r.evaluate(pose);
            EXPECT_LT(glm::length(carried(r, wrist, tipRest) - tip), 1e-6) << arm << " roll " << roll;
            EXPECT_GT(glm::length(r.position(wrist) - wristAt), 0.01) << arm << " the wrist lifts";
        }
        // Past the break the hand turns on about the fingertips' pivot (the
        // hand's own fingers ride the wrist: they hang on its hook): the
        // knuckles swing up about it, keeping their distance.
        pose[r.channel(ik, "roll")] = 30.0;
        r.evaluate(pose);
        const Vec3 atBreak = carried(r, wrist, tipRest);
        pose[r.channel(ik, "roll")] = 60.0;
        r.evaluate(pose);
        const Vec3 knuckles = carried(r, wrist, tipRest);
        EXPECT_NEAR(glm::length(knuckles - fingertips), glm::length(atBreak - fingertips), 1e-6) << arm << " about the fingertips";
        EXPECT_NEAR(glm::length(knuckles - fingertips), glm::length(toeRest - tipRest), 1e-6) << arm;
        EXPECT_GT(knuckles.y, tip.y + 0.01) << arm << " the knuckles lift off the ground under the palm";
        pose[r.channel(ik, "roll")] = -20.0; // back on the heel of the hand: the wrist stays
        r.evaluate(pose);
        EXPECT_LT(glm::length(r.position(wrist) - wristAt), 1e-6) << arm << " heel";
        EXPECT_GT(glm::length(carried(r, wrist, tipRest) - tip), 0.01) << arm << " the knuckles lift";
        pose[r.channel(ik, "roll")] = 0.0;
        const Vec3 innerRest = r.restPosition(arm + "::rfoot.bank_int"), outerRest = r.restPosition(arm + "::rfoot.bank_ext");
        r.evaluate(pose);
        const Vec3 inner = carried(r, wrist, innerRest), outer = carried(r, wrist, outerRest);
        for (const double bank : {20.0, -20.0}) { // onto one edge, then the other
            pose[r.channel(ik, "bank")] = bank;
            r.evaluate(pose);
            const double in = glm::length(carried(r, wrist, innerRest) - inner), out = glm::length(carried(r, wrist, outerRest) - outer);
            EXPECT_LT(std::min(in, out), 1e-6) << arm << " bank " << bank;
            EXPECT_GT(std::max(in, out), 0.01) << arm << " bank " << bank << " lifts the other edge";
        }
    }
}

TEST(LimbHandLock, TheHandsPivotsSitAtTheWristTheTipAndBeyondItAcrossTheHand)
{
    PosedRig r(bipedWithLockedHands());
    ASSERT_TRUE(r.ok());
    const Vec3 wrist = r.restPosition("arm.L::blend.2");
    const Vec3 tip = Vec3(test::node(r.rig, "arm.L::rfoot.ball").worldMatrix[3]);
    const double hand = glm::length(tip - wrist);
    EXPECT_NEAR(hand, 0.09, 1e-9) << "the sample's hand tip guide";
    EXPECT_LT(glm::length(r.restPosition("arm.L::rfoot.heel") - wrist), 1e-12);
    EXPECT_LT(glm::length(r.restPosition("arm.L::rfoot.toe") - (tip + (tip - wrist))), 1e-9);
    const Vec3 across = r.restPosition("arm.L::rfoot.bank_ext") - r.restPosition("arm.L::rfoot.bank_int");
    EXPECT_NEAR(glm::length(across), 0.8 * hand, 1e-9);
    EXPECT_NEAR(glm::dot(across, tip - wrist), 0.0, 1e-12);
    // The outer edge is on the elbow's side (behind), the little finger's.
    EXPECT_LT(glm::dot(across, Vec3(0.0, 0.0, 1.0)), -0.05);
    // Roll lifts the wrist up, away from the ground under a palm-down hand.
    Pose pose = plantedPose(r);
    r.evaluate(pose);
    const double before = r.position("arm.L::blend.2").y;
    pose[r.channel("arm.L::ctrls.ik", "roll")] = 20.0;
    r.evaluate(pose);
    EXPECT_GT(r.position("arm.L::blend.2").y, before + 0.01);
    // The hand has no toe joint to tap.
    EXPECT_FALSE(r.program->channels().find(r.index("arm.L::ctrls.ik"), "toe_tap"));
    EXPECT_FALSE(r.rig.findPath("arm.L::rfoot.toe_tap"));
}

TEST(LimbHandLock, TheRightHandRollsAndBanksAsTheMirrorOfTheLeft)
{
    PosedRig r(bipedWithLockedHands());
    ASSERT_TRUE(r.ok());
    Pose pose = plantedPose(r);
    const std::string ik = "arm.L::ctrls.ik";
    pose[r.channel(ik, "roll")] = 45.0;
    pose[r.channel(ik, "bank")] = 15.0;
    pose[r.channel(ik, "heel_twist")] = 10.0;
    pose[r.channel(ik, "toe_twist")] = -12.0;
    const Vec3 planted = r.evaluate(plantedPose(r)).world[r.index("arm.R::blend.2")].translation;
    const auto& state = r.evaluate(r.posing->mirror(pose, {r.index(ik), r.index("arm.L::ctrls.switch")}));
    const Mat4 mirror = glm::scale(Mat4(1.0), Vec3(-1.0, 1.0, 1.0));
    int pairs = 0;
    for (model::RigNodeIndex i = 0; i < r.rig.nodes.size(); ++i) {
        const auto& node = r.rig.nodes[i];
        if (node.twin == model::kNoNode || node.path.rfind("arm.L::", 0) != 0)
            continue;
        ++pairs;
        EXPECT_LT(maxAbsDifference(state.worldMatrix(node.twin), mirror * state.worldMatrix(i) * mirror), 1e-6) << node.path;
    }
    EXPECT_GT(pairs, 30);
    EXPECT_GT(glm::length(r.position("arm.R::blend.2") - planted), 0.03) << "the roll and bank moved the right hand";
}

TEST(LimbHandLock, OffByDefaultTheArmIsTodaysWithNoPivotsOrFootChannels)
{
    model::GuideDocument unset = test::loadSample("biped"); // the sample's arms have it on: the template's default
    for (const auto& i : unset.instances())
        if (i.name == "arm")
            unset.instance(i.id)->options.erase("reverse_lock");
    const model::Rig plain = rigging::buildRig(unset, test::builtinTemplates());
    const model::Rig off = rigging::buildRig(bipedWithLockedHands(false), test::builtinTemplates());
    EXPECT_EQ(io::writeRigDump(plain), io::writeRigDump(off));
    EXPECT_FALSE(plain.findPath("arm.L::rfoot.heel"));
    EXPECT_TRUE(plain.findPath("leg.L::rfoot.heel")) << "legs keep their reverse foot";
    const model::Rig on = rigging::buildRig(bipedWithLockedHands(), test::builtinTemplates());
    EXPECT_FALSE(hasErrors(on.diagnostics)) << formatAll(on.diagnostics);
    EXPECT_TRUE(on.findPath("arm.R::rfoot.heel"));
    for (const auto& d : on.diagnostics)
        EXPECT_EQ(d.message.find("tagged"), std::string::npos) << "an arm without pivot guides places them unwarned: " << d.message;
}

TEST(LimbHandLock, ReverseLockRebuildsIncrementallyAsAFullBuild)
{
    model::GuideDocument guide = bipedWithLockedHands(false);
    rigging::BuildCache cache;
    test::buildAndCompare(guide, cache, "first build");
    for (const auto& i : guide.instances())
        if (i.name == "arm")
            guide.instance(i.id)->options["reverse_lock"] = Value(true);
    test::buildAndCompare(guide, cache, "reverse_lock on the arms");
    for (const auto& i : guide.instances())
        if (i.name == "arm")
            guide.instance(i.id)->options["effector_plane"] = Value(std::string("ground"));
    test::buildAndCompare(guide, cache, "a level hand");
    for (const auto& i : guide.instances())
        if (i.name == "arm")
            guide.instance(i.id)->options["reverse_lock"] = Value(false);
    test::buildAndCompare(guide, cache, "off again");
}

} // namespace
} // namespace rs
