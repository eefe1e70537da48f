// The neck as an animator checks it on the built and evaluated biped (issue 22
// item 4): a spline neck that bends smoothly to the head, a head whose
// orientation follows the neck, the chest or the world (space) and whose
// position follows the neck, the chest or the world (point_space).
#include "EvalTestSupport.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <string>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

// Space labels, as neck.head's manifest lists them.
constexpr double kNeck = 0.0, kChest = 1.0, kWorld = 3.0;

double turnDegrees(const PosedRig& r, const std::string& id, const Mat3& rest)
{
    const Mat3 now = r.state().world[r.index(id)].rotation();
    const Mat3 relative = glm::transpose(rest) * now;
    return glm::degrees(std::acos(std::clamp((relative[0][0] + relative[1][1] + relative[2][2] - 1.0) / 2.0, -1.0, 1.0)));
}

Mat3 restRotation(PosedRig& r, const std::string& id)
{
    r.evaluate(r.defaults());
    return r.state().world[r.index(id)].rotation();
}

TEST(NeckRig, HeadKeepsWorldOrientationInWorldSpace)
{
    PosedRig r("biped");
    ASSERT_TRUE(r.ok());
    const Mat3 rest = restRotation(r, "neck::skin.head");
    const Vec3 restAt = r.restPosition("neck::skin.head");
    Pose pose = r.defaults();
    pose[r.channel("spine::ctrls.ik_chest", "rx")] = 30.0; // the chest bows
    pose[r.channel("spine::ctrls.cog", "ry")] = 45.0;      // and the body turns
    pose[r.channel("neck::ctrls.head", "space")] = kWorld;
    r.evaluate(pose);
    EXPECT_LT(turnDegrees(r, "neck::skin.head", rest), 1e-6);
    EXPECT_GT(glm::length(r.position("neck::skin.head") - restAt), 0.05) << "it still rides on the neck";
    // In neck space it turns with the body.
    pose[r.channel("neck::ctrls.head", "space")] = kNeck;
    r.evaluate(pose);
    EXPECT_GT(turnDegrees(r, "neck::skin.head", rest), 40.0);
}

TEST(NeckRig, HeadFollowsTheChestInChestSpace)
{
    PosedRig r("biped");
    ASSERT_TRUE(r.ok());
    const Mat3 rest = restRotation(r, "neck::skin.head");
    Pose pose = r.defaults();
    pose[r.channel("neck::ctrls.fk.0", "rz")] = 25.0; // the neck bends
    pose[r.channel("neck::ctrls.head", "space")] = kChest;
    r.evaluate(pose);
    EXPECT_LT(turnDegrees(r, "neck::skin.head", rest), 1e-6);
    pose[r.channel("neck::ctrls.head", "space")] = kNeck;
    r.evaluate(pose);
    EXPECT_NEAR(turnDegrees(r, "neck::skin.head", rest), 25.0, 0.5);
}

TEST(NeckRig, HeadStaysPutInWorldPointSpaceAndTheNeckReachesIt)
{
    PosedRig r("biped");
    ASSERT_TRUE(r.ok());
    const Vec3 head = r.restPosition("neck::skin.head");
    Pose pose = r.defaults();
    pose[r.channel("neck::ctrls.head", "point_space")] = kWorld;
    pose[r.channel("spine::ctrls.ik_chest", "tz")] = 0.06; // the chest leans forward
    r.evaluate(pose);
    EXPECT_LT(glm::length(r.position("neck::skin.head") - head), 1e-6);
    // The neck still starts on the chest and ends at the head: the spline
    // carries its joints between them.
    EXPECT_GT(r.position("neck::skin.0").z - r.restPosition("neck::skin.0").z, 0.05);
    EXPECT_LT(glm::length(r.position("neck::drv.2") - head), 1e-6);
    // In neck space (the default) the head goes with the chest.
    pose[r.channel("neck::ctrls.head", "point_space")] = kNeck;
    r.evaluate(pose);
    EXPECT_GT(r.position("neck::skin.head").z - head.z, 0.05);
}

TEST(NeckRig, SplineNeckBendsSmoothlyTowardsTheHead)
{
    PosedRig r("biped");
    ASSERT_TRUE(r.ok());
    const Vec3 head = r.restPosition("neck::ctrls.head");
    const Pose pose = r.moveTo(r.defaults(), "neck::ctrls.head", head + Vec3(0.0, 0.0, 0.04), "neck::ctrls.head"); // pushed forward
    r.evaluate(pose);
    const double base = r.position("neck::skin.0").z - r.restPosition("neck::skin.0").z;
    const double middle = r.position("neck::skin.1").z - r.restPosition("neck::skin.1").z;
    const double top = r.position("neck::skin.head").z - r.restPosition("neck::skin.head").z;
    EXPECT_NEAR(base, 0.0, 1e-9);
    EXPECT_GT(middle, 0.002);
    EXPECT_LT(middle, top);
    EXPECT_NEAR(top, 0.04, 1e-9);
}

TEST(NeckRig, FkNeckWhenTheSplineIsOff)
{
    model::GuideDocument guide = test::loadSample("biped");
    guide.instance(guide.instanceNamed("neck")->id)->options["spline"] = false;
    PosedRig r(guide);
    ASSERT_TRUE(r.ok());
    EXPECT_FALSE(r.rig.findPath("neck::drv.0"));
    const Vec3 head = r.restPosition("neck::ctrls.head");
    r.evaluate(r.moveTo(r.defaults(), "neck::ctrls.head", head + Vec3(0.0, 0.0, 0.04), "neck::ctrls.head"));
    EXPECT_LT(glm::length(r.position("neck::skin.1") - r.restPosition("neck::skin.1")), 1e-9);
}

} // namespace
} // namespace rs
