// The robot sample (resources/samples/robot.yml), checked the way an animator
// would on the built and evaluated rig: rigid limbs (no twist or blend joints,
// no stretch), level feet riding the cog without foot roll, wrists that yaw
// about the up axis, a claw and a pincer that close on each other in a
// fist, antennas that turn as mirror images, a hose that is skin joints only,
// and a skin skeleton of its own.
#include "EvalTestSupport.h"

#include "model/Skeleton.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

Vec3 axisAt(const PosedRig& r, const std::string& id, int column)
{
    return glm::normalize(r.state().world[r.index(id)].rotation()[column]);
}

std::size_t countPrefixed(const model::Rig& rig, const std::string& prefix)
{
    std::size_t n = 0;
    for (const auto& node : rig.nodes)
        n += node.path.rfind(prefix, 0) == 0 ? 1 : 0;
    return n;
}

TEST(Robot, SampleBuildsWithoutDiagnostics)
{
    PosedRig r("robot");
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.rig.diagnostics.empty()) << formatAll(r.rig.diagnostics);
}

TEST(Robot, RigidLimbsHaveOneSkinJointPerPartAndDoNotStretch)
{
    PosedRig r("robot");
    ASSERT_TRUE(r.ok());
    for (const char* side : {"L", "R"}) {
        const std::string arm = std::string("arm.") + side + "::", leg = std::string("leg.") + side + "::";
        for (const std::string& limb : {arm, leg}) {
            EXPECT_EQ(countPrefixed(r.rig, limb + "skin.up."), 0u) << limb << " no twist joints";
            EXPECT_EQ(countPrefixed(r.rig, limb + "skin.dn."), 0u) << limb;
            EXPECT_EQ(countPrefixed(r.rig, limb + "skin.mid."), 0u) << limb << " no blend joints at the bends";
        }
        EXPECT_FALSE(r.rig.findPath(arm + "ctrls.clavicle")) << "the shoulder is bolted on";
        EXPECT_TRUE(r.rig.findPath(leg + "ctrls.pelvis")) << "a hip block above each leg";
    }
    // The arms are animated FK by default.
    const Pose rest = r.defaults();
    EXPECT_EQ(rest[r.channel("arm.L::ctrls.switch", "ik_blend")], 0.0);
    // The IK foot pulled 0.5 m below the ground: the leg reaches straight down and no further.
    Pose pose = rest;
    r.evaluate(pose);
    const Vec3 hip = r.position("leg.L::blend.0"), ankle = r.position("leg.L::blend.2");
    const double length = glm::length(r.position("leg.L::blend.1") - hip) + glm::length(ankle - r.position("leg.L::blend.1"));
    pose[r.channel("leg.L::ctrls.ik", "ty")] -= 0.5;
    r.evaluate(pose);
    EXPECT_NEAR(glm::length(r.position("leg.L::blend.2") - r.position("leg.L::blend.0")), length, 1e-6) << "no stretch";
}

TEST(Robot, TheFeetAreLevel)
{
    PosedRig r("robot");
    ASSERT_TRUE(r.ok());
    r.evaluate(r.defaults());
    for (const char* side : {"L", "R"}) {
        const Vec3 up = axisAt(r, std::string("leg.") + side + "::blend.2", 1);
        EXPECT_GT(std::abs(up.y), 1.0 - 1e-9) << side << ": the ankle's Y axis is vertical (effector_plane ground)";
    }
}

// The mech's feet: no foot roll (reverse_lock off: the IK control carries the
// ankle, no roll channels), the IK control in the ankle's levelled frame
// (ik_orient joint with effector_plane ground: X along the foot, Y up) drawn
// as a foot along the foot, riding the cog (ik_space) with the knee following
// the foot (pv_space ik).
TEST(Robot, TheIkFeetRideTheCogWithTheirKneesAndAreLevelFootPlatesWithoutRoll)
{
    PosedRig r("robot");
    ASSERT_TRUE(r.ok());
    for (const char* side : {"L", "R"}) {
        const std::string leg = std::string("leg.") + side + "::";
        const auto& ik = r.rig.nodes[r.index(leg + "ctrls.ik")];
        EXPECT_FALSE(r.rig.findPath(leg + "rfoot.heel")) << "reverse_lock off";
        EXPECT_FALSE(r.program->channels().find(r.index(leg + "ctrls.ik"), "roll").has_value()) << side;
        const Vec3 toes = glm::normalize(r.restPosition(leg + "blend.ball") - r.restPosition(leg + "blend.2"));
        const Vec3 forward = glm::normalize(Vec3(toes.x, 0.0, toes.z));
        EXPECT_LT(glm::length(glm::normalize(Vec3(ik.worldMatrix[1])) - Vec3(0, 1, 0)), 1e-9) << side << ": Y up";
        EXPECT_GT(std::abs(glm::dot(glm::normalize(Vec3(ik.worldMatrix[0])), forward)), 1.0 - 1e-9) << side << ": X along the foot";
        // The foot shape lies flat along the foot (heel to toe), not across it.
        Vec3 low(1e9), high(-1e9);
        for (const auto& curve : ik.curves)
            for (const Vec3& p : curve.points) {
                const Vec3 w(ik.worldMatrix * Vec4(p, 1.0));
                low = glm::min(low, w);
                high = glm::max(high, w);
            }
        EXPECT_GT(high.z - low.z, 2.0 * (high.x - low.x)) << side << ": along the foot";
        EXPECT_LT(high.y - low.y, 1e-6) << side << ": flat";
    }
    Pose pose = r.defaults();
    EXPECT_EQ(pose[r.channel("leg.L::ctrls.ik", "space")], 2.0) << "cog";
    EXPECT_EQ(pose[r.channel("leg.L::ctrls.pole", "space")], 1.0) << "ik";
    pose[r.channel("spine::ctrls.cog", "ty")] = 0.3;
    r.evaluate(pose);
    for (const char* id : {"leg.L::blend.2", "leg.L::ctrls.pole", "leg.R::blend.2"})
        EXPECT_LT(glm::length(r.position(id) - r.restPosition(id) - Vec3(0, 0.3, 0)), 1e-9) << id << " rides the cog";
    // Turning the foot turns the knee with it: the pole follows the IK control.
    pose = test::turned(r, r.defaults(), "leg.L::ctrls.ik", Vec3(0, 1, 0), 30.0);
    r.evaluate(pose);
    const Vec3 ankle = r.restPosition("leg.L::ctrls.ik");
    const Vec3 pole = r.restPosition("leg.L::ctrls.pole") - ankle, turnedPole = r.position("leg.L::ctrls.pole") - ankle;
    EXPECT_NEAR(glm::dot(glm::normalize(Vec3(pole.x, 0, pole.z)), glm::normalize(Vec3(turnedPole.x, 0, turnedPole.z))),
                std::cos(glm::radians(30.0)), 1e-9);
}

// The FK arms: the wrist's Y turned up (effector_plane y), so the FK wrist and
// the IK hand (ik_orient joint) yaw about the world's up; both the FK and the
// IK controls stay shown whatever the blend (ik_fk_visibility off).
TEST(Robot, TheWristsTurnAboutTheUpAxisAndTheArmsShowIkAndFkAtOnce)
{
    PosedRig r("robot");
    ASSERT_TRUE(r.ok());
    for (const char* side : {"L", "R"})
        for (const char* id : {"::blend.2", "::ctrls.fk.2", "::ctrls.ik"}) {
            const std::string node = std::string("arm.") + side + id;
            const Vec3 y = glm::normalize(Vec3(r.rig.nodes[r.index(node)].worldMatrix[1]));
            EXPECT_GT(std::abs(y.y), 1.0 - 1e-9) << node << ": Y vertical";
        }
    for (double blend : {0.0, 1.0}) {
        Pose pose = r.defaults();
        pose[r.channel("arm.L::ctrls.switch", "ik_blend")] = blend;
        const auto& state = r.evaluate(pose);
        for (const char* id : {"arm.L::ctrls.fk.0", "arm.L::ctrls.fk.2", "arm.L::ctrls.ik", "arm.L::ctrls.pole"})
            EXPECT_TRUE(state.isVisible(r.index(id))) << id << " at ik_blend " << blend;
    }
}

TEST(Robot, TheRigidUpperArmRollsWholeWithItsBoneAndHasNoElbowPin)
{
    // A rigid arm plate turns with its bone (non_rolling off): rolled 40 degrees about the bone, the upper arm skin
    // joint rolls the same 40 degrees, keeping its rest offset to the FK control. And no elbow pin (pin off): the
    // arm has no pin control and the IK control no pin attribute.
    PosedRig r("robot");
    ASSERT_TRUE(r.ok());
    for (const char* side : {"L", "R"}) {
        const std::string arm = std::string("arm.") + side;
        Pose pose = r.defaults();
        r.evaluate(pose);
        auto rotation = [&](const std::string& id) { return Mat3(r.state().world[r.index(arm + id)].rotation()); };
        const Mat3 restSkin = rotation("::skin.limb.0");
        const Mat3 offset = glm::transpose(rotation("::ctrls.fk.0")) * restSkin;
        const Vec3 bone = glm::normalize(r.position(arm + "::skin.limb.1") - r.position(arm + "::skin.limb.0"));
        const Vec3 across = glm::normalize(glm::cross(bone, Vec3(0, 1, 0)));
        r.evaluate(test::turned(r, pose, arm + "::ctrls.fk.0", bone, 40.0));
        const Mat3 skin = rotation("::skin.limb.0");
        const Mat3 now = glm::transpose(rotation("::ctrls.fk.0")) * skin;
        for (int c = 0; c < 3; ++c)
            EXPECT_LT(glm::length(now[c] - offset[c]), 1e-9) << arm << ": the skin joint rides its control rigidly";
        const Vec3 turnedAcross = skin * (glm::transpose(restSkin) * across);
        EXPECT_NEAR(glm::degrees(std::acos(std::clamp(glm::dot(turnedAcross, across), -1.0, 1.0))), 40.0, 1e-6)
            << arm << ": rolled with the bone";
        EXPECT_NEAR(glm::dot(turnedAcross, bone), 0.0, 1e-9) << arm << ": about the bone";
        EXPECT_FALSE(r.rig.findPath(arm + "::ctrls.pin").has_value()) << arm;
        EXPECT_FALSE(r.program->channels().find(r.index(arm + "::ctrls.ik"), "pin").has_value()) << arm;
    }
}

TEST(Robot, AFistClosesTheClawAndThePincerOnEachOther)
{
    PosedRig r("robot");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    r.evaluate(pose);
    const Vec3 claw = r.position("claw.L::skin.1"), pincer = r.position("pincer.L::skin.1");
    pose[r.channel("hand.L::ctrls.hand", "fist")] = 1.0;
    r.evaluate(pose);
    const Vec3 clawFist = r.position("claw.L::skin.1"), pincerFist = r.position("pincer.L::skin.1");
    EXPECT_LT(clawFist.y, claw.y - 0.01) << "the claw closes down";
    EXPECT_GT(pincerFist.y, pincer.y + 0.01) << "the pincer closes up, onto it";
    EXPECT_GT(glm::length(claw - pincer), 0.03) << "open at rest";
    EXPECT_LT(glm::length(clawFist - pincerFist), 0.002) << "the jaws meet in a full fist (fist 25 degrees a phalanx on each)";
}

TEST(Robot, ThePincersPhalangesAimYDownTheBoneAndCurlAboutX)
{
    // The pincer is set up in Blender's convention (aim_axis y, up_axis x): each phalanx's Y points at the next
    // joint, a fist turns them about their X, which stays where it was, and their rotate order follows (auto).
    PosedRig r("robot");
    ASSERT_TRUE(r.ok());
    for (const char* side : {"L", "R"}) {
        const std::string pincer = std::string("pincer.") + side + "::skin.";
        Pose pose = r.defaults();
        r.evaluate(pose);
        std::vector<Vec3> restX;
        const std::string ctrls = std::string("pincer.") + side + "::ctrls.fk.";
        for (const char* i : {"0", "1"}) // rotate_order auto: the twist (Y) first, the swing (Z), the curl (X) last
            EXPECT_EQ(r.rig.nodes[r.index(ctrls + i)].channels.rotateOrder, model::RotateOrder::Yzx) << ctrls << i;
        const Vec3 bone = glm::normalize(r.position(pincer + "1") - r.position(pincer + "0"));
        EXPECT_GT(glm::dot(axisAt(r, pincer + "0", 1), bone), 1.0 - 1e-9) << pincer << "0: Y down the bone";
        for (int i = 0; i < 2; ++i)
            restX.push_back(axisAt(r, pincer + std::to_string(i), 0));
        pose[r.channel(std::string("hand.") + side + "::ctrls.hand", "fist")] = 1.0;
        r.evaluate(pose);
        for (int i = 0; i < 2; ++i)
            EXPECT_GT(std::abs(glm::dot(axisAt(r, pincer + std::to_string(i), 0), restX[i])), 1.0 - 1e-9)
                << pincer << i << ": the curl turns about X";
    }
}

TEST(Robot, TheSameValuesTurnBothAntennasAsMirrorImages)
{
    PosedRig r("robot");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    for (const char* side : {"L", "R"}) {
        pose[r.channel(std::string("antenna.") + side + "::ctrls.0", "rx")] = 25.0;
        pose[r.channel(std::string("antenna.") + side + "::ctrls.0", "rz")] = -15.0;
    }
    r.evaluate(pose);
    const Vec3 left = r.position("antenna.L::skin.2"), right = r.position("antenna.R::skin.2");
    EXPECT_GT(glm::length(left - r.restPosition("antenna.L::skin.2")), 0.02);
    EXPECT_LT(glm::length(left - Vec3(-right.x, right.y, right.z)), 1e-9) << "flip_orient";
}

TEST(Robot, TheHoseIsSkinJointsWithoutControlsOnTheSkinSkeletonOfItsOwn)
{
    PosedRig r("robot");
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(countPrefixed(r.rig, "hose::skin."), 4u);
    EXPECT_EQ(countPrefixed(r.rig, "hose::ctrls."), 0u) << "do_ctrl off: the engine's physics moves it";
    // isolate_skin on every instance: every skin joint hangs from a skin joint, the root from the world's joint group.
    std::size_t joints = 0;
    for (const auto& node : r.rig.nodes) {
        if (node.kind != model::RigNodeKind::Joint || node.domain() != "skin")
            continue;
        ++joints;
        const auto& parent = r.rig.nodes[node.parent];
        EXPECT_TRUE((parent.kind == model::RigNodeKind::Joint && parent.domain() == "skin") || parent.path == "world::grps.joint")
            << node.path << " hangs from " << parent.path;
    }
    EXPECT_GT(joints, 30u);
    // The hose follows the chest as its skin joint did.
    Pose pose = r.defaults();
    pose[r.channel("spine::ctrls.cog", "ty")] = 0.2;
    r.evaluate(pose);
    EXPECT_NEAR(r.position("hose::skin.3").y - r.restPosition("hose::skin.3").y, 0.2, 1e-9);
}

} // namespace
} // namespace rs
