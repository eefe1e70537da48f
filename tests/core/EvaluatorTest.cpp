// The evaluation engine on the bundled samples: rest reproduction, IK reach,
// stretch and soft IK, global and segment scale, spline IK, reverse foot,
// and a golden evaluation of every channel moved. Compile checks, plain
// constraints and Euler angles: EvaluatorCompileTest.cpp.
#include "EvalTestSupport.h"
#include "eval/IkSolver.h"

#include <gtest/gtest.h>

#include <random>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

// The rest shoulder, the rest wrist and the full reach of a limb's IK chain.
struct Reach {
    Vec3 root, end;
    double length = 0.0;
};
Reach reachOf(const PosedRig& r, const std::string& limb)
{
    const Vec3 root = r.restPosition(limb + "::ik.0"), mid = r.restPosition(limb + "::ik.1"), end = r.restPosition(limb + "::ik.2");
    return {root, end, glm::length(mid - root) + glm::length(end - mid)};
}

class SampleEvaluation : public ::testing::TestWithParam<std::string> {};

TEST_P(SampleEvaluation, DefaultPoseReproducesTheRestPose)
{
    PosedRig r(GetParam());
    ASSERT_TRUE(r.ok());
    const auto& state = r.evaluate(r.defaults());
    for (model::RigNodeIndex i = 0; i < r.rig.nodes.size(); ++i)
        EXPECT_LT(maxAbsDifference(state.worldMatrix(i), r.rig.nodes[i].worldMatrix), 1e-9) << r.rig.nodes[i].path;
}

TEST_P(SampleEvaluation, GlobalScaleScalesEverySkinJointAboutTheWorldControl)
{
    PosedRig r(GetParam());
    Pose pose = r.defaults();
    for (const char* c : {"sx", "sy", "sz"})
        pose[r.channel("world::ctrls.world", c)] = 2.0;
    const auto& state = r.evaluate(pose);
    for (model::RigNodeIndex i = 0; i < r.rig.nodes.size(); ++i) {
        if (r.rig.nodes[i].domain() != "skin")
            continue;
        EXPECT_LT(glm::length(translationOf(state.worldMatrix(i)) - 2.0 * translationOf(r.rig.nodes[i].worldMatrix)), 1e-9)
            << r.rig.nodes[i].path;
    }
}

// Every channel moved at once: the world transforms every constraint solves,
// compared with the golden evaluation (changes to a solver show up here).
TEST_P(SampleEvaluation, ASweptPoseEvaluatesAsTheGolden)
{
    PosedRig r(GetParam());
    ASSERT_TRUE(r.ok());
    const auto& state = r.evaluate(test::sweepPose(r.program->channels()));
    test::expectMatchesGolden(test::worldDump(r.rig, state), "Evaluator/" + GetParam() + "/swept.yml");
}

INSTANTIATE_TEST_SUITE_P(Samples, SampleEvaluation, ::testing::Values("biped", "quadruped", "prop", "vehicle", "robot", "claw", "cart", "strider"));

TEST(Evaluator, IkReachesEveryReachableTarget)
{
    PosedRig r("biped");
    for (const char* limb : {"arm.L", "leg.R"}) {
        const std::string id(limb);
        Pose pose = r.defaults();
        pose[r.channel(id + "::ctrls.switch", "ik_blend")] = 1.0;
        pose[r.channel(id + "::ctrls.ik", "stretch")] = 0.0;
        const auto [root, end, reach] = reachOf(r, id);
        std::mt19937 random(7);
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        for (int trial = 0; trial < 50; ++trial) {
            Vec3 direction(unit(random), unit(random), unit(random));
            if (glm::length(direction) < 0.1) continue;
            const Vec3 target = root + glm::normalize(direction) * reach * (0.25 + 0.74 * (unit(random) + 1.0) / 2.0);
            pose = r.moveTo(pose, id + "::ctrls.ik", target, id + "::ik.2");
            const auto& state = r.evaluate(pose);
            EXPECT_LT(glm::length(translationOf(state.worldMatrix(r.index(id + "::ik.2"))) - target), 1e-5) << limb << " " << trial;
            EXPECT_LT(glm::length(translationOf(state.worldMatrix(r.index(id + "::skin.limb.2"))) - target), 1e-5);
            // Segment lengths never change without stretch.
            EXPECT_NEAR(glm::length(r.position(id + "::ik.1") - r.position(id + "::ik.0")),
                        glm::length(r.restPosition(id + "::ik.1") - root), 1e-9);
        }
    }
}

TEST(Evaluator, QuadrupedHindLegIkReachesWithItsFourJointChain)
{
    PosedRig r("quadruped");
    for (const std::string limb : {"hind_leg.L", "hind_leg.R"}) {
        Pose pose = r.defaults();
        pose[r.channel(limb + "::ctrls.switch", "ik_blend")] = 1.0;
        pose[r.channel(limb + "::ctrls.ik", "stretch")] = 0.0;
        const Vec3 end = r.restPosition(limb + "::ik.3");
        std::vector<double> lengths;
        for (int i = 0; i < 3; ++i)
            lengths.push_back(glm::length(r.restPosition(limb + "::ik." + std::to_string(i + 1)) -
                                          r.restPosition(limb + "::ik." + std::to_string(i))));
        for (const Vec3& offset : {Vec3(0.0, 0.1, 0.05), Vec3(0.02, 0.15, -0.05), Vec3(-0.03, 0.05, 0.1)}) {
            pose = r.moveTo(pose, limb + "::ctrls.ik", end + offset, limb + "::ik.3");
            r.evaluate(pose);
            EXPECT_LT(glm::length(r.position(limb + "::ik.3") - (end + offset)), 1e-5) << limb;
            for (int i = 0; i < 3; ++i) // rigid segments: the hock and fetlock keep their lengths
                EXPECT_NEAR(glm::length(r.position(limb + "::ik." + std::to_string(i + 1)) -
                                        r.position(limb + "::ik." + std::to_string(i))),
                            lengths[i], 1e-9);
        }
    }
}

TEST(Evaluator, TailSplineFollowsItsLastControl)
{
    PosedRig r("quadruped");
    Pose pose = r.defaults();
    pose[r.channel("tail::ctrls.spline.0", "stretch")] = 1.0;
    const Vec3 tip = r.restPosition("tail::drv.7");
    pose = r.moveTo(pose, "tail::ctrls.spline.3", r.restPosition("tail::ctrls.spline.3") + Vec3(0.0, 0.3, 0.0),
                    "tail::ctrls.spline.3");
    r.evaluate(pose);
    EXPECT_GT(r.position("tail::drv.7").y, tip.y + 0.2);             // the tip follows the control up
    EXPECT_LT(glm::length(r.position("tail::drv.0") - r.restPosition("tail::drv.0")), 1e-9); // the base stays
}

TEST(Evaluator, TailSplineFkControlsTurnEachJointWhereTheCurveCarriesIt)
{
    model::GuideDocument guide = test::loadSample("quadruped");
    guide.instance(guide.instanceNamed("tail")->id)->options["fk"] = true;
    PosedRig r(guide);
    ASSERT_TRUE(r.ok());
    Pose pose = r.moveTo(r.defaults(), "tail::ctrls.spline.3", r.restPosition("tail::ctrls.spline.3") + Vec3(0.0, 0.3, 0.0),
                         "tail::ctrls.spline.3");
    r.evaluate(pose);
    const Vec3 at = r.position("tail::skin.3");
    const Mat3 bent = r.state().world[r.index("tail::skin.3")].rotation();
    EXPECT_LT(glm::length(at - r.position("tail::drv.3")), 1e-9) << "the skin joint rides on the curve";
    pose[r.channel("tail::ctrls.fk.3", "rz")] = 30.0;
    r.evaluate(pose);
    EXPECT_LT(glm::length(r.position("tail::skin.3") - at), 1e-9) << "the FK control turns the joint in place";
    const Vec3 x = r.state().world[r.index("tail::skin.3")].rotation()[0];
    EXPECT_NEAR(glm::degrees(std::acos(std::clamp(glm::dot(x, bent[0]), -1.0, 1.0))), 30.0, 1e-6);
    EXPECT_LT(glm::length(r.position("tail::skin.4") - r.position("tail::drv.4")), 1e-9) << "the next joint stays on the curve";
}

TEST(Evaluator, TailSplineTweakersShapeTheCurveAtTheirGuideAndChangeNothingAtRest)
{
    PosedRig plain("quadruped");
    model::GuideDocument guide = test::loadSample("quadruped");
    const model::InstanceId tail = guide.instanceNamed("tail")->id;
    guide.instance(tail)->options["tweakers"] = true;
    PosedRig r(guide);
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.rig.diagnostics.empty()) << formatAll(r.rig.diagnostics);
    const auto rest = r.evaluate(r.defaults()).world;
    const auto plainRest = plain.evaluate(plain.defaults()).world;
    for (int i = 0; i < 8; ++i) {
        const std::string skin = "tail::skin." + std::to_string(i);
        EXPECT_LT(glm::length(rest[r.index(skin)].translation - plainRest[plain.index(skin)].translation), 1e-9) << skin;
    }
    Pose pose = r.defaults();
    pose[r.channel("tail::ctrls.tweak.4", "ty")] = 0.1;
    r.evaluate(pose);
    EXPECT_GT(glm::length(r.position("tail::skin.4") - rest[r.index("tail::skin.4")].translation), 0.05) << "the joint there follows";
    EXPECT_LT(glm::length(r.position("tail::skin.0") - rest[r.index("tail::skin.0")].translation), 1e-9) << "the base stays";
    EXPECT_LT(glm::length(r.position("tail::ctrls.spline.2") - rest[r.index("tail::ctrls.spline.2")].translation), 1e-12);

    // A curve point per guide joint: a spline constraint takes at most 16.
    model::GuideDocument longer;
    auto instance = rigging::makeInstance(longer, test::builtinTemplates(), "rig.spline", model::kNoId,
                                          {{"number", Value(20)}, {"tweakers", Value(true)}});
    ASSERT_TRUE(instance.ok()) << formatAll(instance.diagnostics());
    longer.insertInstance(instance.take(), 0);
    const model::Rig refused = rigging::buildRig(longer, test::builtinTemplates());
    EXPECT_NE(formatAll(refused.diagnostics).find("at most 16"), std::string::npos) << formatAll(refused.diagnostics);
}

TEST(Evaluator, IkBendsTowardsThePoleOnBothSides)
{
    PosedRig r("biped");
    for (const std::string limb : {"leg.L", "leg.R", "arm.L", "arm.R"}) {
        Pose pose = r.defaults();
        pose[r.channel(limb + "::ctrls.switch", "ik_blend")] = 1.0;
        const Vec3 root = r.restPosition(limb + "::ik.0"), end = r.restPosition(limb + "::ik.2");
        pose = r.moveTo(pose, limb + "::ctrls.ik", end + (root - end) * 0.3, limb + "::ik.2"); // bend the limb a lot
        r.evaluate(pose);
        const Vec3 knee = r.position(limb + "::ik.1"), target = r.position(limb + "::ik.2");
        const Vec3 pole = r.position(limb + "::ctrls.pole");
        const Vec3 line = glm::normalize(target - root);
        auto away = [&](const Vec3& p) { return (p - root) - line * glm::dot(p - root, line); };
        EXPECT_GT(glm::dot(glm::normalize(away(knee)), glm::normalize(away(pole))), 0.99) << limb;
        EXPECT_GT(glm::length(away(knee)), 0.1) << limb;
    }
}

TEST(Evaluator, IkStretchesBeyondReachOnlyWhenStretchIsOn)
{
    PosedRig r("biped");
    Pose pose = r.defaults();
    pose[r.channel("arm.L::ctrls.switch", "ik_blend")] = 1.0;
    const auto [root, wrist, reach] = reachOf(r, "arm.L");
    const Vec3 target = root + glm::normalize(wrist - root) * reach * 1.3;
    pose = r.moveTo(pose, "arm.L::ctrls.ik", target, "arm.L::ik.2");
    pose[r.channel("arm.L::ctrls.ik", "stretch")] = 1.0;
    r.evaluate(pose);
    EXPECT_LT(glm::length(r.position("arm.L::ik.2") - target), 1e-5);
    pose[r.channel("arm.L::ctrls.ik", "stretch")] = 0.0;
    r.evaluate(pose);
    EXPECT_NEAR(glm::length(r.position("arm.L::ik.2") - root), reach, 1e-9); // fully extended, short of the target
}

TEST(Evaluator, SoftIkEasesTheLastPartOfTheReach)
{
    PosedRig r("biped");
    Pose pose = r.defaults();
    pose[r.channel("arm.L::ctrls.switch", "ik_blend")] = 1.0;
    pose[r.channel("arm.L::ctrls.ik", "stretch")] = 0.0;
    pose[r.channel("arm.L::ctrls.ik", "soft_ik")] = 0.05; // a 5 cm soft zone
    const auto [root, wrist, reach] = reachOf(r, "arm.L");
    pose = r.moveTo(pose, "arm.L::ctrls.ik", root + glm::normalize(wrist - root) * reach, "arm.L::ik.2");
    r.evaluate(pose);
    const double reached = glm::length(r.position("arm.L::ik.2") - root);
    EXPECT_LT(reached, reach - 1e-4);                    // never snaps straight
    EXPECT_GT(reached, reach - 0.05);                    // but gets most of the way
    EXPECT_NEAR(reached, eval::softReach(reach, reach, 0.05), 1e-9);
}

TEST(Evaluator, FkBlendFollowsTheFkControlsAndSegmentScaleKeepsChildrenUnscaled)
{
    PosedRig r("biped");
    Pose pose = r.defaults();
    pose[r.channel("arm.L::ctrls.switch", "ik_blend")] = 0.0;
    pose[r.channel("arm.L::ctrls.fk.0", "rz")] = 40.0;
    pose[r.channel("arm.L::ctrls.fk.0", "sx")] = 1.5;
    r.evaluate(pose);
    const Vec3 shoulder = r.position("arm.L::skin.limb.0");
    const double upper = glm::length(r.restPosition("arm.L::ik.1") - r.restPosition("arm.L::ik.0"));
    EXPECT_NEAR(glm::length(r.position("arm.L::skin.limb.1") - shoulder), 1.5 * upper, 1e-9); // the upper arm stretched
    const Vec3 forearmScale = r.state().world[r.index("arm.L::ctrls.fk.1")].scale();
    EXPECT_LT(glm::length(forearmScale - Vec3(1.0)), 1e-9); // the forearm did not
    EXPECT_LT(maxAbsDifference(r.state().worldMatrix(r.index("arm.L::blend.1")),
                               r.state().worldMatrix(r.index("arm.L::ctrls.fk.1"))), 1e-9);
}

TEST(Evaluator, SplineSpineKeepsItsLengthWithoutStretchAndFollowsTheChestWithIt)
{
    PosedRig r("biped");
    Pose pose = r.defaults();
    const Vec3 chest = r.restPosition("spine::ctrls.ik_chest");
    pose = r.moveTo(pose, "spine::ctrls.ik_chest", chest + Vec3(0.0, 0.2, 0.1), "spine::ctrls.ik_chest");
    auto length = [&] {
        double total = 0.0;
        for (int i = 1; i < 5; ++i)
            total += glm::length(r.position("spine::ik." + std::to_string(i)) - r.position("spine::ik." + std::to_string(i - 1)));
        return total;
    };
    double restLength = 0.0;
    for (int i = 1; i < 5; ++i)
        restLength += glm::length(r.restPosition("spine::ik." + std::to_string(i)) - r.restPosition("spine::ik." + std::to_string(i - 1)));
    pose[r.channel("spine::ctrls.ik_chest", "stretch")] = 1.0;
    r.evaluate(pose);
    EXPECT_LT(glm::length(r.position("spine::ik.4") - (chest + Vec3(0.0, 0.2, 0.1))), 1e-6);
    EXPECT_GT(length(), restLength + 0.1);
    pose[r.channel("spine::ctrls.ik_chest", "stretch")] = 0.0;
    r.evaluate(pose);
    EXPECT_NEAR(length(), restLength, 0.01 * restLength); // chords of a curve: within 1 %
}

TEST(Evaluator, FootRollPivotsOnTheBallThenTheToeAndBackOnTheHeel)
{
    PosedRig r("biped");
    Pose pose = r.defaults();
    pose[r.channel("leg.L::ctrls.switch", "ik_blend")] = 1.0;
    const int roll = r.channel("leg.L::ctrls.ik", "roll");
    const Vec3 ball = r.restPosition("leg.L::rfoot.ball"), toe = r.restPosition("leg.L::rfoot.toe"),
               heel = r.restPosition("leg.L::rfoot.heel"), ankle = r.restPosition("leg.L::ik.2");
    pose[roll] = 20.0; // below the break: the heel lifts about the ball
    r.evaluate(pose);
    EXPECT_LT(glm::length(r.position("leg.L::rfoot.ball") - ball), 1e-9);
    EXPECT_GT(r.position("leg.L::ik.2").y, ankle.y + 0.01);
    pose[roll] = 60.0; // past the break: the toe pivot rolls too, the toe tip stays put
    r.evaluate(pose);
    EXPECT_LT(glm::length(r.position("leg.L::rfoot.toe") - toe), 1e-9);
    EXPECT_GT(r.position("leg.L::rfoot.ball").y, ball.y + 0.01);
    pose[roll] = -30.0; // back on the heel
    r.evaluate(pose);
    EXPECT_LT(glm::length(r.position("leg.L::rfoot.heel") - heel), 1e-9);
    EXPECT_GT(r.position("leg.L::rfoot.toe").y, toe.y + 0.01);
}

TEST(Evaluator, PostScaleScalesTheRigBelowTheControls)
{
    PosedRig r("prop");
    Pose pose = r.defaults();
    pose[r.channel("world::grps.post", "post_scale")] = 3.0;
    r.evaluate(pose);
    EXPECT_LT(glm::length(r.position("lid::skin.xform") - 3.0 * r.restPosition("lid::skin.xform")), 1e-9);
    EXPECT_TRUE(r.program->channels()[r.channel("world::grps.post", "post_scale")].locked); // the rigger's, not animators'
}

} // namespace
} // namespace rs
