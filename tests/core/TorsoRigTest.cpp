// The torso as an animator checks it on the built and evaluated biped (issue 22
// item 3): one COG carrying the whole upper body, hips that drive the pelvis and
// the lower spine, a mid control, the chest, squash and stretch keeping the
// volume, and as many spine skin joints as the rigger asks for.
#include "EvalTestSupport.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <string>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

model::GuideDocument withSpineOption(const std::string& option, const Value& value)
{
    model::GuideDocument guide = test::loadSample("biped");
    guide.instance(guide.instanceNamed("spine")->id)->options[option] = value;
    return guide;
}

std::string skin(int i) { return "spine::skin." + std::to_string(i); }

// The scale of a node across its length (its local Y axis's length).
double across(const PosedRig& r, const std::string& id) { return glm::length(r.state().world[r.index(id)].linear[1]); }

TEST(TorsoRig, CogMovesTheWholeUpperBody)
{
    PosedRig r("biped");
    ASSERT_TRUE(r.ok());
    const Vec3 cog = r.restPosition("spine::ctrls.cog");
    // 1.5 m forward and a quarter turn to the left.
    Pose pose = r.defaults();
    pose[r.channel("spine::ctrls.cog", "tz")] = 1.5;
    pose[r.channel("spine::ctrls.cog", "ry")] = 90.0;
    r.evaluate(pose);
    const Mat4 moved = glm::translate(Mat4(1.0), cog + Vec3(0.0, 0.0, 1.5)) * glm::rotate(Mat4(1.0), glm::radians(90.0), Vec3(0, 1, 0)) *
                       glm::translate(Mat4(1.0), -cog);
    for (const std::string id : {"spine::skin.0", "spine::skin.1", "spine::skin.2", "spine::skin.3", "spine::skin.4", "neck::skin.0",
                                 "neck::skin.head", "spine::ctrls.hips", "spine::ctrls.ik_mid", "spine::ctrls.ik_chest"})
        EXPECT_LT(glm::length(r.position(id) - Vec3(moved * Vec4(r.restPosition(id), 1.0))), 1e-6) << id;
    // Only one COG: nothing else of the torso sits where it does.
    int atCog = 0;
    for (const model::RigNode& n : r.rig.nodes)
        if (n.kind == model::RigNodeKind::Controller && n.path.rfind("spine::", 0) == 0 &&
            glm::length(translationOf(n.worldMatrix) - cog) < 1e-6 && n.path != "spine::ctrls.fk.0")
            ++atCog;
    EXPECT_EQ(atCog, 2) << "the COG and the hips (and the first FK control) share the hips' pivot";
}

TEST(TorsoRig, HipsDriveThePelvisAndTheLowerSpine)
{
    PosedRig r("biped");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    pose[r.channel("spine::ctrls.hips", "tz")] = -0.1; // the hips back
    r.evaluate(pose);
    EXPECT_NEAR(r.position(skin(0)).z - r.restPosition(skin(0)).z, -0.1, 1e-9); // the pelvis
    EXPECT_LT(r.position(skin(1)).z - r.restPosition(skin(1)).z, -0.03);        // the lower spine
    EXPECT_LT(glm::length(r.position(skin(4)) - r.restPosition(skin(4))), 1e-6); // the chest stays
    // Tilting the hips turns the pelvis and bends the lower spine with it.
    pose = r.defaults();
    pose[r.channel("spine::ctrls.hips", "rx")] = 25.0;
    r.evaluate(pose);
    const Vec3 restUp = glm::normalize(r.restPosition(skin(1)) - r.restPosition(skin(0)));
    const Vec3 up = glm::normalize(r.position(skin(1)) - r.position(skin(0)));
    EXPECT_GT(glm::degrees(std::acos(glm::dot(up, restUp))), 5.0);
    EXPECT_LT(glm::length(r.position(skin(4)) - r.restPosition(skin(4))), 1e-6);
}

TEST(TorsoRig, MidControlBendsTheMiddleOfTheSpine)
{
    PosedRig r("biped");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    pose[r.channel("spine::ctrls.ik_mid", "tz")] = 0.08;
    r.evaluate(pose);
    EXPECT_GT(r.position(skin(2)).z - r.restPosition(skin(2)).z, 0.05);
    EXPECT_LT(glm::length(r.position(skin(0)) - r.restPosition(skin(0))), 1e-9);
    EXPECT_LT(glm::length(r.position(skin(4)) - r.restPosition(skin(4))), 1e-6);
    // The mid sits halfway up the spine and follows the hips and the chest halfway.
    const Vec3 mid = r.restPosition("spine::ctrls.ik_mid");
    EXPECT_NEAR(mid.y, 0.5 * (r.restPosition(skin(0)).y + r.restPosition(skin(4)).y), 0.01);
    pose = r.defaults();
    pose[r.channel("spine::ctrls.ik_chest", "ty")] = 0.1;
    r.evaluate(pose);
    EXPECT_NEAR(r.position("spine::ctrls.ik_mid").y - mid.y, 0.05, 1e-9);
}

TEST(TorsoRig, SquashAndStretchKeepTheVolume)
{
    PosedRig r("biped");
    ASSERT_TRUE(r.ok());
    auto spineLength = [&] {
        double length = 0.0;
        for (int i = 1; i < 5; ++i)
            length += glm::length(r.position("spine::ik." + std::to_string(i)) - r.position("spine::ik." + std::to_string(i - 1)));
        return length;
    };
    r.evaluate(r.defaults());
    const double rest = spineLength();
    for (double lift : {0.15, -0.1}) { // a stretch, then a squash
        Pose pose = r.defaults();
        pose[r.channel("spine::ctrls.ik_chest", "ty")] = lift;
        r.evaluate(pose);
        EXPECT_NEAR(across(r, skin(2)), 1.0, 1e-9) << "volume 0 (the option's default) keeps the thickness";
        pose[r.channel("spine::ctrls.ik_chest", "volume")] = 1.0;
        r.evaluate(pose);
        const double s = spineLength() / rest;
        EXPECT_GT(std::abs(s - 1.0), 0.1);
        for (int i = 1; i < 4; ++i)
            EXPECT_NEAR(across(r, skin(i)), 1.0 / std::sqrt(s), 0.01) << "lift " << lift << ", " << skin(i);
        // The chest, the neck and the arms keep their size.
        EXPECT_NEAR(across(r, skin(4)), 1.0, 1e-9);
        EXPECT_NEAR(across(r, "neck::skin.0"), 1.0, 1e-9);
        EXPECT_NEAR(across(r, "arm.L::skin.clavicle"), 1.0, 1e-9);
    }
    // The option turns it on by default.
    PosedRig on(withSpineOption("volume", true));
    ASSERT_TRUE(on.ok());
    Pose pose = on.defaults();
    pose[on.channel("spine::ctrls.ik_chest", "ty")] = 0.15;
    on.evaluate(pose);
    EXPECT_LT(across(on, skin(2)), 0.95);
}

TEST(TorsoRig, SkinJointCountIsIndependentOfTheControls)
{
    PosedRig five("biped");
    PosedRig r(withSpineOption("skin_joints", 8LL));
    ASSERT_TRUE(five.ok());
    ASSERT_TRUE(r.ok());
    auto count = [](const model::Rig& rig, model::RigNodeKind kind) {
        return std::count_if(rig.nodes.begin(), rig.nodes.end(),
                             [&](const model::RigNode& n) { return n.kind == kind && n.path.rfind("spine::", 0) == 0; });
    };
    EXPECT_EQ(count(r.rig, model::RigNodeKind::Controller), count(five.rig, model::RigNodeKind::Controller));
    for (int i = 0; i <= 8; ++i)
        EXPECT_TRUE(r.rig.findPath(skin(i))) << i;
    EXPECT_FALSE(r.rig.findPath(skin(9)));
    // Spread evenly from the hips to the chest.
    const double step = glm::length(r.restPosition(skin(2)) - r.restPosition(skin(1)));
    for (int i = 1; i <= 8; ++i)
        EXPECT_NEAR(glm::length(r.restPosition(skin(i)) - r.restPosition(skin(i - 1))), step, 0.002) << i;
    EXPECT_LT(glm::length(r.restPosition(skin(8)) - five.restPosition(skin(4))), 1e-9);
    // They follow the IK torso: the top one rides with the chest...
    Pose pose = r.defaults();
    pose[r.channel("spine::ctrls.ik_chest", "tz")] = 0.1;
    r.evaluate(pose);
    EXPECT_LT(glm::length(r.position(skin(8)) - (r.restPosition(skin(8)) + Vec3(0.0, 0.0, 0.1))), 1e-6);
    EXPECT_GT(r.position(skin(5)).z - r.restPosition(skin(5)).z, 0.03);
    // ...and the FK spine.
    pose = r.defaults();
    pose[r.channel("spine::ctrls.cog", "ik_blend")] = 0.0;
    pose[r.channel("spine::ctrls.fk.1", "rz")] = 20.0;
    r.evaluate(pose);
    EXPECT_LT(glm::length(r.position(skin(1)) - r.restPosition(skin(1))), 0.01);
    EXPECT_GT(glm::length(r.position(skin(8)) - r.restPosition(skin(8))), 0.08);
}

} // namespace
} // namespace rs
