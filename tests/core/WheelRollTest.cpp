// wheel.legacy's roll along the path the wheel takes (model::RollMode::Path,
// the default `roll: path`), as an animator checks it on the built and
// evaluated vehicle sample: driving, turning, coming back, scrubbing, tools
// evaluating trial poses, rebuilding, the editor's drags. The stateless
// `roll: axis` for comparison. Exports, keyed clips and the range of motion:
// WheelRollExportTest.cpp.
#include "EvalTestSupport.h"
#include "WheelRollSupport.h"
#include "edit/GuideEdits.h"
#include "session/Session.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>

namespace rs {
namespace {

using namespace test::wheelroll;

TEST(WheelRoll, DrivingOneMetreForwardInAHundredStepsTurnsEachWheelOneOverRadius)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    drive(r, pose, "tz", 1.0, 100);
    for (const std::string wheel : kWheels)
        EXPECT_NEAR(rollOf(r, wheel), 1.0 / kRadius, 1e-6) << wheel;
}

// A wheel need not stand on a floor: a side wheel against a wall (a roller
// coaster's side-friction wheel, a wall-climbing robot's) rolls on the wall
// it touches, across its own rest up, not across the rig's Y.
TEST(WheelRoll, AWheelAgainstAWallRollsAlongItAsTheVehicleTravels)
{
    model::GuideDocument guide = test::loadSample("vehicle");
    model::TemplateInstance& front = *guide.instance(guide.instanceNamed("wheel_front")->id);
    ASSERT_EQ(front.joints.size(), 3u);
    front.joints[2].local.translate = Vec3(kRadius, 0.0, 0.0); // the contact beside the centre, not below it
    PosedRig r(guide);
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    const std::string spin = "wheel_front.L::skin.spin";
    const Mat3 rest = r.rig.nodes[r.index(spin)].worldMatrix;
    ASSERT_NEAR(std::abs(glm::normalize(rest[0]).y), 1.0, 1e-9) << "the wheel's axle stands upright: it lies against the wall";
    drive(r, pose, "tz", 0.6, 30);
    const Mat3 posed = r.state().world[r.index(spin)].rotation();
    // The tyre turned about its axle by travel / radius.
    const double turned = std::acos(std::clamp(glm::dot(glm::normalize(rest[2]), glm::normalize(posed[2])), -1.0, 1.0));
    EXPECT_NEAR(turned, 0.6 / kRadius, 1e-6);
    EXPECT_NEAR(glm::dot(glm::normalize(rest[0]), glm::normalize(posed[0])), 1.0, 1e-9) << "about its axle only";
    // The floor wheels behind roll as before.
    EXPECT_NEAR(rollOf(r, "wheel_back.L"), 0.6 / kRadius, 1e-6);
}

// Steering (turning the wheel control about its up) turns the wheel in place
// without rolling it; driving on, the steered wheel rolls by the travel along
// its new heading (the part across it is the tyre's slip).
TEST(WheelRoll, SteeringTurnsTheWheelWithoutRollingItAndItThenRollsAlongItsHeading)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    auto rollInWheel = [&](const std::string& wheel) { // the tyre's turn in its (steered) control's frame
        const Mat3 control = r.state().world[r.index(wheel + "::ctrls.wheel")].rotation();
        const Vec3 up = glm::transpose(control) * glm::normalize(r.state().world[r.index(wheel + "::skin.spin")].rotation()[1]);
        return std::atan2(up.z, up.y);
    };
    const double steer = glm::radians(30.0);
    for (const std::string side : {"wheel_front.L", "wheel_front.R"}) {
        const int ry = r.channel(side + "::ctrls.wheel", "ry");
        for (int i = 1; i <= 10; ++i) { // the animator steers over ten frames
            pose[ry] = 30.0 * i / 10;
            r.evaluate(pose);
        }
    }
    for (const std::string side : {"wheel_front.L", "wheel_front.R"}) {
        EXPECT_NEAR(rollInWheel(side), 0.0, 1e-9) << side << " steering alone rolls nothing";
        const Mat3 heading = r.state().world[r.index(side + "::ctrls.wheel")].rotation();
        EXPECT_NEAR(std::abs(glm::normalize(heading[2]).z), std::cos(steer), 1e-9) << side << " is steered";
    }
    drive(r, pose, "tz", 1.0, 100);
    for (const std::string side : {"wheel_front.L", "wheel_front.R"})
        EXPECT_NEAR(rollInWheel(side), std::cos(steer) / kRadius, 1e-6) << side;
    for (const std::string side : {"wheel_back.L", "wheel_back.R"})
        EXPECT_NEAR(rollOf(r, side), 1.0 / kRadius, 1e-6) << side << " (not steered)";
}

TEST(WheelRoll, DrivingTurningAndDrivingOnRollsEachWheelItsOwnPathLength)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    drive(r, pose, "tz", 1.0, 100);
    drive(r, pose, "ry", 90.0, 100); // a turn in place, about the body control: +Z heads to +X
    drive(r, pose, "tx", 1.0, 100);  // 1 m on the new heading
    // Turning in place, a wheel d metres to the side of the pivot rolls d x
    // the turn (backwards on the inside of the turn, forwards outside), so
    // the two sides differ and their mean is the body's own 2 m.
    const Vec3 pivot = r.restPosition(kBody);
    double mean = 0.0;
    for (const std::string wheel : kWheels) {
        const double side = r.restPosition(wheel + "::mch.roll").x - pivot.x;
        const double expected = (2.0 - side * glm::half_pi<double>()) / kRadius;
        const double error = std::remainder(rollOf(r, wheel) - expected, glm::two_pi<double>());
        EXPECT_LT(std::abs(error), 1e-3) << wheel << " rolled " << rollOf(r, wheel) << " (whole turns aside)";
        mean += (expected + error) / 4.0; // whole turns counted
    }
    EXPECT_NEAR(mean, 2.0 / kRadius, 1e-3) << "the vehicle travelled 2 m";

    // The stateless roll (roll: axis) only sees where the wheel is now, along
    // the way it faces: the first metre, now across the wheel, counts for nothing.
    PosedRig axis(vehicleWith("roll", Value(std::string("axis"))));
    ASSERT_TRUE(axis.ok());
    axis.evaluate(pose);
    const double side = axis.restPosition("wheel_front.L::mch.roll").x - pivot.x;
    const Vec3 centre = axis.position("wheel_front.L::mch.roll") - axis.restPosition("wheel_front.L::mch.roll");
    EXPECT_NEAR(rollOf(axis, "wheel_front.L"), std::remainder(centre.x / kRadius, glm::two_pi<double>()), 1e-9);
    EXPECT_GT(turnError(rollOf(axis, "wheel_front.L"), (2.0 - side * glm::half_pi<double>()) / kRadius), 0.1);
}

TEST(WheelRoll, GoingOutAndComingBackAlongTheSameLineEndsUnrolled)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    drive(r, pose, "tz", 1.5, 50);
    EXPECT_GT(std::abs(rollOf(r, "wheel_back.R")), 0.5);
    drive(r, pose, "tz", 0.0, 70);
    for (const std::string wheel : kWheels)
        EXPECT_NEAR(rollOf(r, wheel), 0.0, 1e-9) << wheel;
}

TEST(WheelRoll, AJumpLongerThanTheJumpDistanceDoesNotRoll)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    drive(r, pose, "tz", 0.5, 10);
    // A scrub to 5 m (more than a circumference, 2.2 m): moved, not rolled.
    pose[r.channel(kBody, "tz")] = 5.5;
    r.evaluate(pose);
    EXPECT_NEAR(r.position("wheel_front.L::mch.roll").z - r.restPosition("wheel_front.L::mch.roll").z, 5.5, 1e-9);
    for (const std::string wheel : kWheels)
        EXPECT_NEAR(rollOf(r, wheel), 0.5 / kRadius, 1e-9) << wheel;
    // From there small steps roll again.
    drive(r, pose, "tz", 5.8, 3);
    EXPECT_NEAR(rollOf(r, "wheel_front.L"), 0.8 / kRadius, 1e-9);

    // roll_jump raises the limit: the same scrub rolls.
    PosedRig far(vehicleWith("roll_jump", Value(10.0)));
    ASSERT_TRUE(far.ok());
    Pose farPose = far.defaults();
    farPose[far.channel(kBody, "tz")] = 5.0;
    far.evaluate(farPose);
    EXPECT_LT(turnError(rollOf(far, "wheel_front.L"), 5.0 / kRadius), 1e-9);
}

TEST(WheelRoll, ANewStateRollsNothingOnItsFirstEvaluationAndAxisModeIsStateless)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    pose[r.channel(kBody, "tz")] = 1.0;
    eval::EvalState state = r.program->makeState();
    r.program->evaluate(pose, state);
    EXPECT_NEAR(rollOf(state, r, "wheel_front.L"), 0.0, 1e-12) << "no previous position: nothing to roll";
    r.program->evaluate(pose, state);
    EXPECT_NEAR(rollOf(state, r, "wheel_front.L"), 0.0, 1e-12) << "the same pose again: it has not moved";

    PosedRig axis(vehicleWith("roll", Value(std::string("axis"))));
    ASSERT_TRUE(axis.ok());
    eval::EvalState fresh = axis.program->makeState();
    axis.program->evaluate(pose, fresh);
    EXPECT_NEAR(rollOf(fresh, axis, "wheel_front.L"), 1.0 / kRadius, 1e-9)
        << "axis: the pose alone gives the roll";
}

TEST(WheelRoll, ToolsEvaluateTrialPosesFromTheDisplayedRollWithoutAdvancingIt)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    drive(r, pose, "tz", 0.6, 20);
    const eval::EvalState& displayed = r.state();
    eval::Posing tool(r.rig, *r.program);
    tool.follow(&displayed);
    // A trial pose a step further rolls from the displayed wheel, every time alike.
    Pose trial = pose;
    trial[r.channel(kBody, "tz")] = 0.7;
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(rollOf(tool.evaluate(trial), r, "wheel_back.L"), 0.7 / kRadius, 1e-9) << i;
    // Placing the spin control (under the roll) where it is changes nothing.
    const auto spin = r.index("wheel_back.L::ctrls.spin");
    const Pose placed = tool.placeAt(pose, spin, displayed.worldMatrix(spin));
    EXPECT_NEAR(placed[r.channel("wheel_back.L::ctrls.spin", "rx")], 0.0, 1e-6);
    EXPECT_NEAR(rollOf(r, "wheel_back.L"), 0.6 / kRadius, 1e-9) << "the displayed state did not move";
}

TEST(WheelRoll, ARebuildKeepsTheRollWithoutRollingForTheEdit)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    drive(r, pose, "tz", 0.6, 20);
    // The body's guide moves 10 cm forward: the rebuilt wheels sit further on.
    model::GuideDocument guide = test::loadSample("vehicle");
    guide.instance(guide.instanceNamed("body")->id)->joints.front().local.translate.z += 0.1;
    PosedRig rebuilt(guide);
    ASSERT_TRUE(rebuilt.ok());
    eval::EvalState state = rebuilt.program->makeState();
    rebuilt.program->carryPaths(*r.program, r.state(), state);
    rebuilt.program->evaluate(pose, state);
    for (const std::string wheel : kWheels)
        EXPECT_NEAR(rollOf(state, rebuilt, wheel), 0.6 / kRadius, 1e-9) << wheel;
    pose[rebuilt.channel(kBody, "tz")] = 0.8;
    rebuilt.program->evaluate(pose, state);
    EXPECT_NEAR(rollOf(state, rebuilt, "wheel_front.R"), 0.8 / kRadius, 1e-9) << "and rolls on from there";
}

// The session keeps the roll as values when its program goes, so a rig edit
// that fails to compile does not lose it: the next good program takes it.
TEST(WheelRoll, TheRollOutlivesTheProgramThatRolledItAndSkipsWheelsThatAreGone)
{
    std::vector<std::pair<NodeKey, double>> rolled;
    Pose pose;
    {
        PosedRig r("vehicle");
        ASSERT_TRUE(r.ok());
        pose = r.defaults();
        drive(r, pose, "tz", 0.6, 20);
        rolled = r.program->rolledPaths(r.state());
    } // the program and its state are gone
    ASSERT_EQ(rolled.size(), std::size(kWheels));
    // The next good rig has lost one wheel (its instance removed).
    model::GuideDocument guide = test::loadSample("vehicle");
    ASSERT_TRUE(guide.takeInstance(guide.instanceNamed("wheel_back")->id));
    PosedRig rebuilt(guide);
    ASSERT_TRUE(rebuilt.ok());
    eval::EvalState state = rebuilt.program->makeState();
    rebuilt.program->carryPaths(rolled, state);
    rebuilt.program->evaluate(pose, state);
    EXPECT_EQ(rebuilt.rig.findPath("wheel_back.L::skin.spin"), std::nullopt);
    for (const std::string wheel : {"wheel_front.L", "wheel_front.R"})
        EXPECT_NEAR(rollOf(state, rebuilt, wheel), 0.6 / kRadius, 1e-9) << wheel;
}

TEST(WheelRoll, TheEditorRollsTheWheelsAsTheBodyIsDraggedAndKeepsTheRollAcrossARebuild)
{
    session::Session s(std::make_shared<templates::TemplateRegistry>(test::builtinTemplates()));
    s.replaceDocument(test::loadSample("vehicle"));
    s.build();
    const model::RigNodeIndex body = *s.rig()->findPath(kBody);
    const Mat4 rest = s.rig()->nodes[body].worldMatrix;
    s.beginDrag(body);
    for (int i = 1; i <= 10; ++i) { // the gizmo drags the body 60 cm forward
        Mat4 world = rest;
        world[3].z += 0.06 * i;
        s.dragTo(body, world);
    }
    s.endDrag(body, "move body");
    for (const std::string wheel : kWheels)
        EXPECT_NEAR(rollOf(*s.evaluation(), *s.rig(), wheel), 0.6 / kRadius, 1e-9) << wheel;

    // A guide edit moves the body's guide 5 cm forward: the live rebuild keeps
    // the roll, and moving the wheels with the guide does not roll them.
    const model::JointId joint = s.document().instanceNamed("body")->joints.front().id;
    Transform moved = s.document().joint(joint)->local;
    moved.translate.z += 0.05;
    ASSERT_TRUE(test::succeeded(edit::setJointTransform(s.history(), joint, moved)));
    EXPECT_NEAR(translationOf(s.evaluation()->worldMatrix(*s.rig()->findPath(kBody))).z - translationOf(rest).z, 0.65, 1e-9);
    for (const std::string wheel : kWheels)
        EXPECT_NEAR(rollOf(*s.evaluation(), *s.rig(), wheel), 0.6 / kRadius, 1e-9) << wheel;
    // Undoing the drag brings the body back 60 cm: the wheels unroll.
    s.history().undo();
    s.history().undo();
    for (const std::string wheel : kWheels)
        EXPECT_NEAR(rollOf(*s.evaluation(), *s.rig(), wheel), 0.0, 1e-9) << wheel;
}

} // namespace
} // namespace rs
