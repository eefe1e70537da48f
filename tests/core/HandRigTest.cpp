// The hand as an animator checks it on the built and evaluated biped (issue 22
// item 5): the hand master's fist, curl, spread and cup drive every finger of
// the hand on both sides; each finger spreads at its knuckle; the thumb is
// opposed; the hand's controls do not overlap.
#include "EvalTestSupport.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

const std::vector<std::string> kFingers = {"thumb", "index", "middle", "ring", "pinky"};
const std::vector<std::string> kSides = {"L", "R"};

Vec3 xAxis(const PosedRig& r, const std::string& id) { return glm::normalize(r.state().world[r.index(id)].rotation()[0]); }

double angleDegrees(const Vec3& a, const Vec3& b) { return glm::degrees(std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0))); }

// How much more each phalanx of a finger bends against the one before it than
// at rest (the base, skin.0, then skin.1 ... skin.3), in degrees.
std::vector<double> extraBends(PosedRig& r, const Pose& posed, const std::string& finger)
{
    const int phalanges = finger.rfind("thumb", 0) == 0 ? 3 : 4;
    auto bends = [&](const Pose& pose) {
        r.evaluate(pose);
        std::vector<double> out;
        for (int i = 1; i < phalanges; ++i)
            out.push_back(angleDegrees(xAxis(r, finger + "::skin." + std::to_string(i - 1)), xAxis(r, finger + "::skin." + std::to_string(i))));
        return out;
    };
    const std::vector<double> rest = bends(r.defaults()), now = bends(posed);
    std::vector<double> out;
    for (std::size_t i = 0; i < rest.size(); ++i)
        out.push_back(now[i] - rest[i]);
    return out;
}

TEST(HandRig, FistCurlsEveryFinger)
{
    PosedRig r("biped");
    ASSERT_TRUE(r.ok());
    for (const std::string& side : kSides) {
        Pose pose = r.defaults();
        pose[r.channel("hand." + side + "::ctrls.hand", "fist")] = 1.0;
        for (const std::string& name : kFingers) {
            const std::string finger = name + "." + side;
            const std::vector<double> bends = extraBends(r, pose, finger);
            ASSERT_FALSE(bends.empty());
            // The first phalanx turns against the metacarpal (thumb: 0.6 of 90 degrees).
            for (std::size_t i = 0; i < bends.size(); ++i)
                EXPECT_NEAR(bends[i], name == "thumb" ? 54.0 : 90.0, 1.0) << finger << " phalanx " << i + 1;
            // ...and the tip closes towards the palm: it comes nearer the base.
            r.evaluate(r.defaults());
            const std::string last = finger + "::skin." + std::to_string(name == "thumb" ? 2 : 3);
            const double open = glm::length(r.position(last) - r.position(finger + "::skin.0"));
            r.evaluate(pose);
            EXPECT_LT(glm::length(r.position(last) - r.position(finger + "::skin.0")), open - 0.005) << finger;
        }
    }
}

TEST(HandRig, CurlBendsEveryFingerByTheSameAngle)
{
    PosedRig r("biped");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    pose[r.channel("hand.R::ctrls.hand", "curl")] = 30.0;
    for (const std::string& name : kFingers)
        for (double bend : extraBends(r, pose, name + ".R"))
            EXPECT_NEAR(bend, 30.0, 0.5) << name;
    // The other hand stays open.
    for (double bend : extraBends(r, pose, "index.L"))
        EXPECT_NEAR(bend, 0.0, 1e-9);
}

TEST(HandRig, SpreadFansTheFingersOutFromTheMiddle)
{
    PosedRig r("biped");
    ASSERT_TRUE(r.ok());
    for (const std::string& side : kSides) {
        auto tipGap = [&](const std::string& a, const std::string& b) {
            return glm::length(r.position(a + "." + side + "::skin.3") - r.position(b + "." + side + "::skin.3"));
        };
        r.evaluate(r.defaults());
        const double indexMiddle = tipGap("index", "middle"), ringPinky = tipGap("ring", "pinky"), indexPinky = tipGap("index", "pinky");
        const Vec3 base = r.position("index." + side + "::skin.1");
        Pose pose = r.defaults();
        pose[r.channel("hand." + side + "::ctrls.hand", "spread")] = 20.0;
        r.evaluate(pose);
        EXPECT_GT(tipGap("index", "middle"), indexMiddle + 0.003) << side;
        EXPECT_GT(tipGap("ring", "pinky"), ringPinky + 0.003) << side;
        EXPECT_GT(tipGap("index", "pinky"), indexPinky + 0.01) << side;
        // The fingers turn at the knuckle: the knuckle stays where it was.
        EXPECT_LT(glm::length(r.position("index." + side + "::skin.1") - base), 1e-9) << side;
        // Negative spread closes them.
        pose[r.channel("hand." + side + "::ctrls.hand", "spread")] = -10.0;
        r.evaluate(pose);
        EXPECT_LT(tipGap("index", "pinky"), indexPinky - 0.005) << side;
    }
}

TEST(HandRig, EachFingerSpreadsAtItsOwnKnuckle)
{
    PosedRig r("biped");
    ASSERT_TRUE(r.ok());
    r.evaluate(r.defaults());
    const Vec3 knuckle = r.position("index.L::skin.1"), tip = r.position("index.L::skin.3");
    const Vec3 middleTip = r.position("middle.L::skin.3");
    Pose pose = r.defaults();
    pose[r.channel("index.L::ctrls.fk.0", "spread")] = 15.0;
    r.evaluate(pose);
    EXPECT_LT(glm::length(r.position("index.L::skin.1") - knuckle), 1e-9);
    // Towards the thumb's side (+Z on the left hand), away from the middle finger.
    EXPECT_GT(r.position("index.L::skin.3").z, tip.z + 0.01);
    EXPECT_NEAR(r.position("index.L::skin.3").y, tip.y, 0.005); // in the palm's plane
    EXPECT_LT(glm::length(r.position("middle.L::skin.3") - middleTip), 1e-9);
}

TEST(HandRig, CupFoldsTheLittleFingerSideMost)
{
    PosedRig r("biped");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    pose[r.channel("hand.L::ctrls.hand", "cup")] = 30.0;
    auto baseTurn = [&](const std::string& finger) {
        r.evaluate(r.defaults());
        const Vec3 rest = xAxis(r, finger + "::skin.0");
        r.evaluate(pose);
        return angleDegrees(rest, xAxis(r, finger + "::skin.0"));
    };
    const double index = baseTurn("index.L"), ring = baseTurn("ring.L"), pinky = baseTurn("pinky.L"), thumb = baseTurn("thumb.L");
    EXPECT_GT(pinky, ring + 2.0);
    EXPECT_GT(ring, index + 2.0);
    EXPECT_GT(pinky, 20.0);
    EXPECT_NEAR(thumb, 30.0, 0.5);
    // The metacarpals fold towards the palm (down, -Y, in the T-pose): the pinky's knuckle drops.
    r.evaluate(r.defaults());
    const double knuckle = r.position("pinky.L::skin.1").y;
    r.evaluate(pose);
    EXPECT_LT(r.position("pinky.L::skin.1").y, knuckle - 0.003);
}

TEST(HandRig, ThumbIsOpposedAndCurlsAcrossThePalm)
{
    PosedRig r("biped");
    ASSERT_TRUE(r.ok());
    r.evaluate(r.defaults());
    // Opposed: the thumb points well away from the index's direction and down from the palm.
    const Vec3 thumb = glm::normalize(r.position("thumb.L::skin.2") - r.position("thumb.L::skin.0"));
    const Vec3 index = glm::normalize(r.position("index.L::skin.3") - r.position("index.L::skin.0"));
    EXPECT_GT(angleDegrees(thumb, index), 45.0);
    EXPECT_LT(thumb.y, -0.3);
    // A fist folds its tip across the palm, towards the little finger's side (-Z).
    const Vec3 tip = r.position("thumb.L::skin.2");
    Pose pose = r.defaults();
    pose[r.channel("hand.L::ctrls.hand", "fist")] = 1.0;
    r.evaluate(pose);
    EXPECT_LT(r.position("thumb.L::skin.2").z, tip.z - 0.01);
}

TEST(HandRig, HandControlsDoNotOverlap)
{
    PosedRig r("biped");
    ASSERT_TRUE(r.ok());
    struct Ball {
        std::string id;
        Vec3 centre;
        double radius;
    };
    std::vector<Ball> balls;
    for (const model::RigNode& node : r.rig.nodes) {
        const std::string& path = node.path;
        const bool hand = path.rfind("hand.L::ctrls", 0) == 0;
        bool finger = false;
        for (const std::string& name : kFingers)
            finger = finger || path.rfind(name + ".L::ctrls", 0) == 0;
        if ((!hand && !finger) || node.curves.empty())
            continue;
        Ball b{path, translationOf(node.worldMatrix), 0.0};
        for (const model::ControllerCurve& curve : node.curves)
            for (const Vec3& p : curve.points)
                b.radius = std::max(b.radius, glm::length(Vec3(node.worldMatrix * Vec4(p, 1.0)) - b.centre));
        balls.push_back(b);
    }
    ASSERT_EQ(balls.size(), 1u + 3u + 4u * 4u); // the master, the thumb's 3, 4 on each finger
    for (std::size_t i = 0; i < balls.size(); ++i)
        for (std::size_t j = i + 1; j < balls.size(); ++j)
            EXPECT_GT(glm::length(balls[i].centre - balls[j].centre), balls[i].radius + balls[j].radius)
                << balls[i].id << " overlaps " << balls[j].id;
}

} // namespace
} // namespace rs
