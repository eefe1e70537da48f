// Limbs as an animator checks them on the built and evaluated biped (issue
// 22): poles that keep the knees and elbows on their side when the body
// travels away from planted hands and feet, FK/IK controls shown by the blend,
// the switch riding on the wrist and ankle, twist shared linearly along the
// upper arm and thigh, and the IK control's orientation option (the foot
// shape along the foot whatever it is).
#include "EvalTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

const char* const kLimbs[] = {"leg.L", "leg.R", "arm.L", "arm.R"};

model::GuideDocument bipedWith(const std::string& instance, const std::string& option, Value value)
{
    model::GuideDocument guide = test::loadSample("biped");
    for (const auto& i : guide.instances())
        if (i.name == instance)
            guide.instance(i.id)->options[option] = std::move(value);
    return guide;
}

Mat3 rotationAt(const PosedRig& r, const std::string& id) { return r.state().world[r.index(id)].rotation(); }
Mat3 restRotation(const PosedRig& r, const std::string& id)
{
    return eval::Affine::fromMatrix(r.rig.nodes[r.index(id)].worldMatrix).rotation();
}

// Where the knee or elbow faces: the pole side of the upper bone, perpendicular
// to it, carried by the upper IK joint (defined even when the limb is straight).
Vec3 bendSide(const PosedRig& r, const std::string& limb)
{
    const Vec3 root = r.restPosition(limb + "::ik.0"), end = r.restPosition(limb + "::ik.2");
    const Vec3 line = glm::normalize(end - root);
    Vec3 side = r.restPosition(limb + "::ctrls.pole") - root;
    side = glm::normalize(side - line * glm::dot(side, line));
    const Vec3 local = glm::transpose(restRotation(r, limb + "::ik.0")) * side;
    return rotationAt(r, limb + "::ik.0") * local;
}

// How much the knee or elbow faces the body's forward direction, as far as
// the limb's line allows: 1 straight that way, -1 the opposite (flipped).
double facingBody(const PosedRig& r, const std::string& limb, const Vec3& bodyForward)
{
    const double sign = limb.rfind("leg", 0) == 0 ? 1.0 : -1.0; // knees in front, elbows behind
    const Vec3 line = glm::normalize(r.position(limb + "::ik.2") - r.position(limb + "::ik.0"));
    const Vec3 across = glm::normalize(bodyForward - line * glm::dot(bodyForward, line));
    return sign * glm::dot(bendSide(r, limb), across);
}

// The COG 1.5 m forward and turned 90 degrees about Y, hands and feet planted in IK.
Pose travelledPose(PosedRig& r)
{
    Pose pose = r.defaults();
    for (const char* limb : kLimbs)
        pose[r.channel(std::string(limb) + "::ctrls.switch", "ik_blend")] = 1.0;
    pose[r.channel("spine::ctrls.cog", "tz")] = 1.5;
    pose[r.channel("spine::ctrls.cog", "ry")] = 90.0;
    return pose;
}

TEST(Limb, KneesAndElbowsKeepTheirSideWhenTheBodyTravelsWithFeetPlanted)
{
    PosedRig r("biped");
    ASSERT_TRUE(r.ok());
    r.evaluate(travelledPose(r));
    const Vec3 bodyForward = rotationAt(r, "spine::ctrls.cog") * Vec3(0, 0, 1);
    for (const std::string limb : kLimbs) {
        const double facing = facingBody(r, limb, bodyForward);
        EXPECT_GT(facing, 0.9) << limb << ": faces the turned body's way";
        std::printf("follow pole: %s faces the body %.3f\n", limb.c_str(), facing);
        RecordProperty(limb + "_facing_body", std::to_string(facing));
        // The IK end stayed planted.
        EXPECT_LT(glm::length(r.position(limb + "::ik.2") - r.restPosition(limb + "::ik.2")), 1e-6) << limb;
    }
}

// With the pole in world space the pole stays where the body left it. In this
// move (1.5 m forward, turned 90 degrees to the left) the left knee and elbow
// still roughly face the body's way (0.88 and 0.99), but the right knee turns
// backwards (-0.52) and the right elbow flips to the front (-0.99): what the
// template's help for pv_space: world warns about.
TEST(Limb, AWorldSpacePoleStaysBehindSoTheRightKneeAndElbowFlip)
{
    model::GuideDocument guide = bipedWith("leg", "pv_space", std::string("world"));
    for (const auto& i : guide.instances())
        if (i.name == "arm")
            guide.instance(i.id)->options["pv_space"] = std::string("world");
    PosedRig r(guide);
    ASSERT_TRUE(r.ok());
    r.evaluate(travelledPose(r));
    const Vec3 bodyForward = rotationAt(r, "spine::ctrls.cog") * Vec3(0, 0, 1);
    for (const std::string limb : kLimbs) {
        const double facing = facingBody(r, limb, bodyForward);
        std::printf("world pole: %s faces the body %.3f\n", limb.c_str(), facing);
        RecordProperty(limb + "_facing_body", std::to_string(facing));
        if (limb.back() == 'R')
            EXPECT_LT(facing, 0.0) << limb << " flipped";
        else
            EXPECT_GT(facing, 0.5) << limb;
    }
}

TEST(Limb, ThePoleSpaceSwitchOffersFollowIkAndTheRigSpacesAndDefaultsToFollow)
{
    PosedRig r("biped");
    const auto* space = r.rig.nodes[r.index("leg.L::ctrls.pole")].attribute("space");
    ASSERT_NE(space, nullptr);
    EXPECT_EQ(space->labels, (std::vector<std::string>{"follow", "ik", "world", "root", "cog"}));
    EXPECT_EQ(space->value, 0.0);
    // In "ik" the pole rides with the IK control alone.
    Pose pose = r.defaults();
    pose[r.channel("leg.L::ctrls.pole", "space")] = 1.0;
    pose[r.channel("leg.L::ctrls.ik", "tx")] = 0.2;
    r.evaluate(pose);
    EXPECT_NEAR(glm::length(r.position("leg.L::ctrls.pole") - r.restPosition("leg.L::ctrls.pole") - Vec3(0.2, 0, 0)), 0.0, 1e-9);
}

TEST(Limb, IkFkVisibilityFollowsTheBlend)
{
    PosedRig r("biped");
    for (const std::string limb : kLimbs) {
        const std::vector<std::string> fk = {"::ctrls.fk.0", "::ctrls.fk.1", "::ctrls.fk.2"};
        const std::vector<std::string> ik = {"::ctrls.ik", "::ctrls.pole"};
        for (double blend : {0.0, 0.5, 1.0}) {
            Pose pose = r.defaults();
            pose[r.channel(limb + "::ctrls.switch", "ik_blend")] = blend;
            const auto& state = r.evaluate(pose);
            for (const auto& id : fk)
                EXPECT_EQ(state.isVisible(r.index(limb + id)), blend < 1.0) << limb << id << " at " << blend;
            for (const auto& id : ik)
                EXPECT_EQ(state.isVisible(r.index(limb + id)), blend > 0.0) << limb << id << " at " << blend;
            EXPECT_TRUE(state.isVisible(r.index(limb + "::ctrls.switch")));
            if (limb.rfind("leg", 0) == 0) {
                EXPECT_EQ(state.isVisible(r.index(limb + "::ctrls.fk.ball")), blend < 1.0) << limb << " toe at " << blend;
            }
        }
    }
}

TEST(Limb, PickwalkSkipsTheControlsTheBlendHides)
{
    PosedRig r("biped");
    Pose pose = r.defaults();
    pose[r.channel("arm.L::ctrls.switch", "ik_blend")] = 1.0;
    const auto& state = r.evaluate(pose);
    const auto fk0 = r.index("arm.L::ctrls.fk.0");
    const auto shown = &state.visible;
    // From the clavicle, Down reaches a shown child, never a hidden FK control.
    const auto down = eval::pickwalk(r.rig, r.index("arm.L::ctrls.clavicle"), eval::WalkDirection::Down, shown);
    EXPECT_NE(down, fk0);
    EXPECT_TRUE(state.isVisible(down));
    pose[r.channel("arm.L::ctrls.switch", "ik_blend")] = 0.0;
    const auto& fkState = r.evaluate(pose);
    EXPECT_EQ(eval::pickwalk(r.rig, r.index("arm.L::ctrls.clavicle"), eval::WalkDirection::Down, &fkState.visible), fk0);
}

TEST(Limb, TheSwitchControlStaysAtTheLimbEndWhenTheLimbIsPosed)
{
    PosedRig r("biped");
    for (const std::string limb : kLimbs) {
        const Vec3 restOffset = r.restPosition(limb + "::ctrls.switch") - r.restPosition(limb + "::blend.2");
        for (double blend : {0.0, 1.0}) {
            Pose pose = r.defaults();
            pose[r.channel(limb + "::ctrls.switch", "ik_blend")] = blend;
            pose[r.channel(limb + "::ctrls.fk.0", "rz")] = 35.0;
            pose[r.channel(limb + "::ctrls.fk.1", "rz")] = 40.0;
            pose = r.moveTo(pose, limb + "::ctrls.ik", r.restPosition(limb + "::ik.2") + Vec3(0.1, 0.15, 0.1), limb + "::ik.2");
            r.evaluate(pose);
            const Vec3 end = r.position(limb + "::blend.2");
            EXPECT_GT(glm::length(end - r.restPosition(limb + "::blend.2")), 0.05) << limb << " moved";
            EXPECT_NEAR(glm::length(r.position(limb + "::ctrls.switch") - end), glm::length(restOffset), 1e-9)
                << limb << " at blend " << blend;
            const Mat3 relative = glm::transpose(rotationAt(r, limb + "::blend.2")) * rotationAt(r, limb + "::ctrls.switch");
            const Mat3 restRelative = glm::transpose(restRotation(r, limb + "::blend.2")) * restRotation(r, limb + "::ctrls.switch");
            EXPECT_LT(maxAbsDifference(Mat4(relative), Mat4(restRelative)), 1e-9) << limb;
        }
    }
}


// How far `id` turned about `axis` since rest, in degrees.
double twistDegrees(const PosedRig& r, const std::string& id, const Vec3& axis)
{
    Quat q = glm::quat_cast(rotationAt(r, id) * glm::transpose(restRotation(r, id)));
    if (q.w < 0.0)
        q = -q;
    return glm::degrees(2.0 * std::atan2(glm::dot(Vec3(q.x, q.y, q.z), axis), q.w));
}

// Twist joint `t` of `count` sits (t + 1) / (count + 1) along its segment and
// takes that share of the twist; the segment's start joint takes none, the
// next segment's all of it.
void expectLinearShares(const PosedRig& r, const std::string& limb, const std::string& segment, int start, const Vec3& axis,
                        const std::string& how)
{
    const int count = 2; // the template's default twist_upper / twist_lower
    EXPECT_NEAR(twistDegrees(r, limb + "::skin.limb." + std::to_string(start), axis), 0.0, 0.5) << limb << how;
    for (int t = 0; t < count; ++t)
        EXPECT_NEAR(twistDegrees(r, limb + "::skin." + segment + "." + std::to_string(t), axis), 90.0 * (t + 1) / (count + 1), 0.5)
            << limb << how << " twist joint " << t;
    EXPECT_NEAR(twistDegrees(r, limb + "::skin.limb." + std::to_string(start + 1), axis), 90.0, 0.5) << limb << how;
}

TEST(Limb, TwistJointsShareTheTwistLinearly)
{
    PosedRig r("biped");
    for (const std::string limb : kLimbs) {
        const Vec3 shoulder = r.restPosition(limb + "::blend.0"), elbow = r.restPosition(limb + "::blend.1");
        const Vec3 wrist = r.restPosition(limb + "::blend.2");
        const Vec3 upper = glm::normalize(elbow - shoulder), lower = glm::normalize(wrist - elbow);
        // FK: the upper bone rolled 90 degrees; no roll at the shoulder or hip (non-rolling).
        Pose fk = r.defaults();
        fk[r.channel(limb + "::ctrls.switch", "ik_blend")] = 0.0;
        r.evaluate(test::turned(r, fk, limb + "::ctrls.fk.0", upper, 90.0));
        expectLinearShares(r, limb, "up", 0, upper, " upper, FK");
        // FK and IK: the end turned 90 degrees about the lower bone.
        r.evaluate(test::turned(r, fk, limb + "::ctrls.fk.2", lower, 90.0));
        expectLinearShares(r, limb, "dn", 1, lower, " lower, FK");
        Pose ik = r.defaults();
        ik[r.channel(limb + "::ctrls.switch", "ik_blend")] = 1.0;
        r.evaluate(test::turned(r, ik, limb + "::ctrls.ik", lower, 90.0));
        EXPECT_NEAR(twistDegrees(r, limb + "::skin.dn.0", lower), 30.0, 0.5) << limb << " lower, IK";
        EXPECT_NEAR(twistDegrees(r, limb + "::skin.dn.1", lower), 60.0, 0.5) << limb << " lower, IK";
    }
}

TEST(Limb, RollingUpperTwistIsStillAnOptionAndRollsTheShoulderJointFully)
{
    PosedRig r(bipedWith("arm", "non_rolling", false));
    const Vec3 upper = glm::normalize(r.restPosition("arm.L::blend.1") - r.restPosition("arm.L::blend.0"));
    Pose fk = r.defaults();
    fk[r.channel("arm.L::ctrls.switch", "ik_blend")] = 0.0;
    r.evaluate(test::turned(r, fk, "arm.L::ctrls.fk.0", upper, 90.0));
    EXPECT_NEAR(twistDegrees(r, "arm.L::skin.limb.0", upper), 90.0, 0.5);
    EXPECT_NEAR(twistDegrees(r, "arm.L::skin.up.0", upper), 90.0, 0.5); // the candy wrapper the default avoids
}

TEST(Limb, TheIkControlIsWorldOrientedByDefaultOrLikeTheJointOrTheGuide)
{
    PosedRig world("biped");
    for (const std::string limb : kLimbs)
        EXPECT_LT(maxAbsDifference(Mat4(restRotation(world, limb + "::ctrls.ik")), Mat4(1.0)), 1e-9) << limb;
    PosedRig joint(bipedWith("arm", "ik_orient", std::string("joint")));
    for (const std::string limb : {"arm.L", "arm.R"})
        EXPECT_LT(maxAbsDifference(Mat4(restRotation(joint, limb + "::ctrls.ik")), Mat4(restRotation(joint, limb + "::blend.2"))),
                  1e-9) << limb;
    model::GuideDocument guide = bipedWith("arm", "ik_orient", std::string("copy"));
    const model::JointId wrist = 15; // the arm's limb3 guide in the sample
    for (const auto& i : guide.instances())
        if (i.name == "arm")
            guide.instance(i.id)->joint(wrist)->local.rotateDegrees = Vec3(0.0, 30.0, 20.0);
    PosedRig copy(guide);
    const Mat3 guideRotation = eval::Affine::fromMatrix(guide.jointWorldMatrix(wrist)).rotation();
    EXPECT_LT(maxAbsDifference(Mat4(restRotation(copy, "arm.L::ctrls.ik")), Mat4(guideRotation)), 1e-9);
    const Mat3 mirror(Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)); // the R branch is the mirror image
    EXPECT_LT(maxAbsDifference(Mat4(restRotation(copy, "arm.R::ctrls.ik")), Mat4(mirror * guideRotation * mirror)), 1e-9);
}

// A foot's IK control is drawn as a foot along the foot, flat on the sole,
// whatever its orientation: a joint- or guide-oriented control (aimed down the
// shin) does not tip its foot shape over nor lay it across the foot.
std::vector<Vec3> worldCurve(const PosedRig& r, const std::string& id)
{
    const auto& node = r.rig.nodes[r.index(id)];
    std::vector<Vec3> points;
    for (const auto& curve : node.curves)
        for (const Vec3& p : curve.points)
            points.push_back(Vec3(node.worldMatrix * Vec4(p, 1.0)));
    return points;
}

TEST(Limb, TheFootShapeLiesAlongTheFootWhateverTheIkControlsOrientation)
{
    // The biped's legs, and the quadruped's hind legs (quad.leg, joint-oriented in the sample): each foot
    // is straight and level, so its shape is drawn as on a world-oriented control.
    const auto withOrient = [](const std::string& sample, const std::string& instance, const std::string& orient) {
        model::GuideDocument guide = test::loadSample(sample);
        for (const auto& i : guide.instances())
            if (i.name == instance)
                guide.instance(i.id)->options["ik_orient"] = Value(orient);
        return guide;
    };
    for (const auto& [sample, instance] : {std::pair{"biped", "leg"}, std::pair{"quadruped", "hind_leg"}}) {
        PosedRig world(withOrient(sample, instance, "world")), joint(withOrient(sample, instance, "joint"));
        for (const char* side : {".L", ".R"}) {
            const std::string ik = std::string(instance) + side + "::ctrls.ik";
            ASSERT_GT(maxAbsDifference(Mat4(restRotation(joint, ik)), Mat4(restRotation(world, ik))), 0.1) << ik;
            const auto expected = worldCurve(world, ik), actual = worldCurve(joint, ik);
            ASSERT_EQ(actual.size(), expected.size());
            double largest = 0.0;
            for (std::size_t k = 0; k < actual.size(); ++k)
                largest = std::max(largest, glm::length(actual[k] - expected[k]));
            EXPECT_LT(largest, 1e-9) << sample << " " << ik << ": drawn as with ik_orient world";
        }
    }
}

} // namespace
} // namespace rs
