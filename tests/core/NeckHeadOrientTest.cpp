// neck.head's head_orient as an animator checks it: by default the head
// controller is axis-aligned, so ry turns the head left and right as on the
// COG and the chest; `joint` keeps the head joint's frame (the rig before the
// option), `copy` the head guide's. Only the controller's channels change: the
// rig rests and moves as before (a group in the head joint's frame under the
// controller carries the head, the spline's end, the hooks and the head space).
#include "EvalTestSupport.h"
#include "IncrementalCheck.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <string>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

const std::string kHead = "neck::ctrls.head";
const std::string kHeadJoint = "neck::skin.head";

model::GuideDocument withHeadOrient(const std::string& sample, const std::string& orient)
{
    return test::sampleWith(sample, {"neck"}, "head_orient", Value(orient));
}

Mat4 evaluated(PosedRig& r, const Pose& pose, const std::string& id) { return r.evaluate(pose).worldMatrix(r.index(id)); }

Mat3 rotationAbout(const Vec3& axis, double degrees) { return glm::mat3_cast(glm::angleAxis(glm::radians(degrees), axis)); }

// Every joint (skin, driven, deformation) of `a` and `b` in the last evaluation, as far apart as the farthest.
double jointsApart(const PosedRig& a, const PosedRig& b)
{
    double apart = 0.0;
    for (std::size_t i = 0; i < a.rig.nodes.size(); ++i) {
        const model::RigNode& node = a.rig.nodes[i];
        if (node.kind != model::RigNodeKind::Joint)
            continue;
        const Mat4 there = b.state().worldMatrix(b.index(node.path));
        apart = std::max(apart, maxAbsDifference(a.state().worldMatrix(model::RigNodeIndex(i)), there));
    }
    return apart;
}

TEST(NeckRig, RyTurnsTheHeadLeftAndRightAboutWorldUpByDefault)
{
    for (const std::string sample : {"biped", "face"}) {
        PosedRig r(sample);
        ASSERT_TRUE(r.ok()) << sample;
        const Mat4 rest = evaluated(r, r.defaults(), kHeadJoint);
        // The head's own forward and up: the world's +Z and +Y at rest, in its frame.
        const Vec3 forward = glm::transpose(Mat3(rest)) * Vec3(0, 0, 1), up = glm::transpose(Mat3(rest)) * Vec3(0, 1, 0);
        Pose pose = r.defaults();
        pose[r.channel(kHead, "ry")] = 30.0;
        const Mat4 turned = evaluated(r, pose, kHeadJoint);
        EXPECT_LT(glm::length(Mat3(turned) * forward - rotationAbout(Vec3(0, 1, 0), 30.0) * Vec3(0, 0, 1)), 1e-9)
            << sample << ": the head looks 30 degrees to its left";
        EXPECT_LT(glm::length(Mat3(turned) * up - Vec3(0, 1, 0)), 1e-9) << sample << ": and does not tilt";
        EXPECT_LT(glm::length(Vec3(turned[3]) - Vec3(rest[3])), 1e-9) << sample;
        // rx nods it about the side axis (forward goes down), as on the chest.
        pose = r.defaults();
        pose[r.channel(kHead, "rx")] = 20.0;
        EXPECT_LT(Vec3(Mat3(evaluated(r, pose, kHeadJoint)) * forward).y, -0.3) << sample << ": a positive rx nods down";
    }
}

TEST(NeckRig, HeadOrientJointKeepsTheHeadJointsFrameAndItsChannels)
{
    PosedRig joint(withHeadOrient("biped", "joint"));
    PosedRig world("biped");
    ASSERT_TRUE(joint.ok() && world.ok());
    EXPECT_FALSE(joint.rig.findPath("neck::mch.follow.head")) << "the controller drives the head itself, as before";
    EXPECT_TRUE(world.rig.findPath("neck::mch.follow.head"));
    const Mat4 rest = joint.rig.nodes[joint.index(kHeadJoint)].worldMatrix;
    EXPECT_LT(maxAbsDifference(joint.rig.nodes[joint.index(kHead)].worldMatrix, rest), 1e-12);
    EXPECT_LT(maxAbsDifference(Mat4(Mat3(world.rig.nodes[world.index(kHead)].worldMatrix)), Mat4(1.0)), 1e-12);
    // rx turns the head about its own X (up the neck): today's pose.
    Pose pose = joint.defaults();
    pose[joint.channel(kHead, "rx")] = 30.0;
    const Mat4 turned = evaluated(joint, pose, kHeadJoint);
    EXPECT_LT(maxAbsDifference(Mat4(Mat3(turned)), Mat4(Mat3(rest) * rotationAbout(Vec3(1, 0, 0), 30.0))), 1e-9);
    EXPECT_LT(glm::length(Vec3(turned[3]) - Vec3(rest[3])), 1e-9);
    // The biped's head joint has X straight up: the same turn is ry on the default controller, and every joint agrees.
    Pose ry = world.defaults();
    ry[world.channel(kHead, "ry")] = 30.0;
    world.evaluate(ry);
    EXPECT_LT(jointsApart(joint, world), 1e-9);
}

TEST(NeckRig, HeadOrientChangesNothingAtRest)
{
    model::GuideDocument copyGuide = withHeadOrient("biped", "copy");
    const model::JointId headGuide = 10; // the neck's head guide joint in the sample
    copyGuide.instance(copyGuide.instanceNamed("neck")->id)->joint(headGuide)->local.rotateDegrees = Vec3(0.0, 25.0, 10.0);
    model::GuideDocument jointGuide = copyGuide;
    jointGuide.instance(jointGuide.instanceNamed("neck")->id)->options["head_orient"] = Value(std::string("joint"));
    for (const auto& [what, guide] : {std::pair{"world", withHeadOrient("biped", "world")}, std::pair{"copy", copyGuide}}) {
        PosedRig r(guide);
        PosedRig before(what == std::string("copy") ? jointGuide : withHeadOrient("biped", "joint"));
        ASSERT_TRUE(r.ok() && before.ok()) << what;
        std::size_t compared = 0;
        for (const model::RigNode& node : before.rig.nodes) {
            if (node.path == kHead || node.path == "neck::roots.head")
                continue; // the controller and its offset take the new frame
            EXPECT_LT(maxAbsDifference(r.rig.nodes[r.index(node.path)].worldMatrix, node.worldMatrix), 1e-12) << what << " " << node.path;
            ++compared;
        }
        EXPECT_GT(compared, 100u);
        r.evaluate(r.defaults());
        before.evaluate(before.defaults());
        EXPECT_LT(jointsApart(before, r), 1e-12) << what << ": evaluated at rest";
    }
    PosedRig copy(copyGuide);
    const Mat3 guideRotation = eval::Affine::fromMatrix(copyGuide.jointWorldMatrix(headGuide)).rotation();
    EXPECT_LT(maxAbsDifference(Mat4(Mat3(copy.rig.nodes[copy.index(kHead)].worldMatrix)), Mat4(guideRotation)), 1e-12);
}

TEST(NeckRig, HeadOrientLeavesTheSpacesTheSplineAndRigidityAsTheyWere)
{
    // The rigid neck (both rigidities 1) reads the head's axis: it must be the head joint's, whatever the controller's.
    const auto rigid = [](const std::string& orient) {
        model::GuideDocument guide = withHeadOrient("biped", orient);
        auto& options = guide.instance(guide.instanceNamed("neck")->id)->options;
        options["rigidity"] = Value(true);
        options["rigidity_up"] = Value(1.0);
        return guide;
    };
    PosedRig world(rigid("world")), joint(rigid("joint"));
    ASSERT_TRUE(world.ok() && joint.ok());
    // The body moves, the head in world space and point space: it stays put and keeps its world orientation.
    const auto bodyMoves = [](PosedRig& r) {
        Pose pose = r.defaults();
        pose[r.channel("spine::ctrls.ik_chest", "rx")] = 30.0;
        pose[r.channel("spine::ctrls.cog", "ry")] = 45.0;
        pose[r.channel("neck::ctrls.fk.0", "rz")] = 15.0;
        pose[r.channel(kHead, "space")] = 3.0;       // world
        pose[r.channel(kHead, "point_space")] = 3.0; // world
        return pose;
    };
    const Mat4 rest = evaluated(world, world.defaults(), kHeadJoint);
    EXPECT_LT(maxAbsDifference(evaluated(world, bodyMoves(world), kHeadJoint), rest), 1e-9) << "held still in world";
    joint.evaluate(bodyMoves(joint));
    EXPECT_LT(jointsApart(joint, world), 1e-9) << "as before";
    // The head turned about a slanted world axis and pushed forward: the same neck bend either way.
    const Vec3 axis = glm::normalize(Vec3(0.3, 1.0, 0.2));
    const auto headMoves = [&](PosedRig& r) {
        const Vec3 at = r.restPosition(kHead) + Vec3(0.0, -0.01, 0.04);
        return r.moveTo(test::turned(r, r.defaults(), kHead, axis, 35.0), kHead, at, kHead);
    };
    world.evaluate(headMoves(world));
    joint.evaluate(headMoves(joint));
    EXPECT_GT(glm::length(world.position("neck::skin.1") - world.restPosition("neck::skin.1")), 1e-3) << "the neck bent";
    EXPECT_LT(jointsApart(joint, world), 1e-9);
}

TEST(NeckRig, HeadOrientBuildsIncrementallyAsInFull)
{
    model::GuideDocument guide = test::loadSample("face");
    rigging::BuildCache cache;
    test::buildAndCompare(guide, cache, "world");
    for (const std::string orient : {"joint", "copy", "world"}) {
        guide.instance(guide.instanceNamed("neck")->id)->options["head_orient"] = Value(orient);
        test::buildAndCompare(guide, cache, orient);
    }
}

} // namespace
} // namespace rs
