// Mikan's vehicle templates as an animator checks them on the built and
// evaluated vehicle sample (issue 22 item 7): wheels that roll d / radius as
// the vehicle travels d metres (the world control carries them without
// rolling; the path they take: WheelRollTest.cpp), a manual spin on top, a
// door sliding on its rail within its limits, a rear roller shutter sliding up
// its curved track (rig.slide on a curve; SlideTest checks the curve itself),
// a camera that aims at its target and rolls, and world.default's spaces.
#include "EvalTestSupport.h"
#include "io/RigDump.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

constexpr double kRadius = 0.35; // the sample's wheels: axis guide to ground guide
const char* const kWheels[] = {"wheel_front.L", "wheel_front.R", "wheel_back.L", "wheel_back.R"};

Vec3 axisAt(const PosedRig& r, const std::string& id, int column)
{
    return glm::normalize(r.state().world[r.index(id)].rotation()[column]);
}

// How far the tyre (its rolling skin joint) has turned about its axle (X),
// radians: its up axis (Y, at rest world +Y) turned towards forward (+Z).
double rollOf(const PosedRig& r, const std::string& wheel)
{
    const Vec3 up = axisAt(r, wheel + "::skin.spin", 1);
    return std::atan2(up.z, up.y);
}

void set(Pose& pose, const PosedRig& r, const std::string& id, const std::string& channel, double value)
{
    pose[r.channel(id, channel)] = value;
}

TEST(VehicleTemplates, SampleBuildsEveryPartWithoutDiagnostics)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.rig.diagnostics.empty()) << formatAll(r.rig.diagnostics);
    for (const char* id : {"world::ctrls.world", "world::ctrls.move", "world::skin.root", "body::ctrls.xform", "door::ctrls.slide",
                           "panel::skin.xform", "camera::ctrls.camera", "camera::ctrls.target", "camera::camera"})
        EXPECT_TRUE(r.rig.findPath(id)) << id;
    for (const std::string wheel : kWheels)
        for (const char* tag : {"::ctrls.bank", "::ctrls.wheel", "::ctrls.spin", "::skin.wheel", "::skin.spin"})
            EXPECT_TRUE(r.rig.findPath(wheel + tag)) << wheel << tag;
    // The right wheels mirror the left ones.
    const Vec3 left = r.restPosition("wheel_front.L::skin.spin"), right = r.restPosition("wheel_front.R::skin.spin");
    EXPECT_NEAR(left.x, 0.8, 1e-9);
    EXPECT_NEAR(right.x, -left.x, 1e-9);
    EXPECT_NEAR(right.z, left.z, 1e-9);
}

TEST(VehicleTemplates, WheelsRollDistanceOverRadiusAsTheVehicleMovesForward)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    for (const char* control : {"world::ctrls.move", "body::ctrls.xform"}) {
        SCOPED_TRACE(control);
        for (double d : {0.3, -0.5, 1.2}) {
            Pose pose = r.defaults();
            set(pose, r, control, "tz", d);
            r.evaluate(pose);
            for (const std::string wheel : kWheels) {
                EXPECT_NEAR(r.position(wheel + "::skin.spin").z - r.restPosition(wheel + "::skin.spin").z, d, 1e-9) << wheel;
                const double expected = std::remainder(d / kRadius, 2.0 * M_PI);
                EXPECT_NEAR(rollOf(r, wheel), expected, 1e-9) << wheel << " after " << d << " m";
                // The hub (skin.wheel) travels without rolling.
                EXPECT_NEAR(axisAt(r, wheel + "::skin.wheel", 1).y, 1.0, 1e-9) << wheel;
            }
        }
    }
    // Moving sideways does not roll the wheels.
    Pose pose = r.defaults();
    set(pose, r, "world::ctrls.move", "tx", 0.7);
    r.evaluate(pose);
    for (const std::string wheel : kWheels)
        EXPECT_NEAR(rollOf(r, wheel), 0.0, 1e-9) << wheel;
}

TEST(VehicleTemplates, AWheelsOwnControlRollsItAndItsSpinAndAutoRotateChannelsAdjustTheRoll)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    const std::string wheel = "wheel_back.R";
    Pose pose = r.defaults();
    set(pose, r, wheel + "::ctrls.wheel", "tz", 0.2);
    r.evaluate(pose);
    EXPECT_NEAR(rollOf(r, wheel), 0.2 / kRadius, 1e-9);
    EXPECT_NEAR(rollOf(r, "wheel_back.L"), 0.0, 1e-9) << "the other wheels stay";
    set(pose, r, wheel + "::ctrls.spin", "rx", 30.0);
    r.evaluate(pose);
    EXPECT_NEAR(rollOf(r, wheel), 0.2 / kRadius + glm::radians(30.0), 1e-9) << "the manual spin adds to the roll";
    // The wheel rolls along its path: auto_rotate scales what it rolls from
    // then on, and changing it alone turns nothing.
    set(pose, r, wheel + "::ctrls.wheel", "auto_rotate", 0.5);
    r.evaluate(pose);
    EXPECT_NEAR(rollOf(r, wheel), 0.2 / kRadius + glm::radians(30.0), 1e-9) << "auto_rotate alone turns nothing";
    set(pose, r, wheel + "::ctrls.wheel", "tz", 0.4);
    r.evaluate(pose);
    EXPECT_NEAR(rollOf(r, wheel), 0.3 / kRadius + glm::radians(30.0), 1e-9) << "auto_rotate scales the automatic roll";
    set(pose, r, wheel + "::ctrls.wheel", "auto_rotate", 0.0);
    set(pose, r, wheel + "::ctrls.wheel", "tz", 0.6);
    r.evaluate(pose);
    EXPECT_NEAR(rollOf(r, wheel), 0.3 / kRadius + glm::radians(30.0), 1e-9) << "0: it slides without rolling";
}

TEST(VehicleTemplates, TheBankControlsScaleFlattensTheWheelOntoTheGroundAsItRolls)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    const std::string wheel = "wheel_front.L";
    const double ground = r.restPosition(wheel + "::ctrls.bank").y;
    Pose pose = r.defaults();
    set(pose, r, wheel + "::ctrls.bank", "sy", 0.6);
    set(pose, r, "world::ctrls.move", "tz", 0.4);
    r.evaluate(pose);
    EXPECT_NEAR(r.position(wheel + "::skin.spin").y - ground, 0.6 * kRadius, 1e-9) << "the centre comes down";
    // The rolled tyre stays flattened: whichever way it has turned, its frame
    // maps the unit circle about the axle onto an ellipse 0.6 as tall as it is long.
    const Mat3 linear = r.state().world[r.index(wheel + "::skin.spin")].linear;
    for (double a = 0.0; a < 6.3; a += 0.5) {
        const Vec3 rim = linear * Vec3(0.0, std::cos(a), std::sin(a));
        EXPECT_NEAR(rim.y * rim.y / 0.36 + rim.z * rim.z, 1.0, 1e-9) << a;
    }
}

TEST(VehicleTemplates, TheWorldControlCarriesTheVehicleWithoutRollingItsWheels)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    set(pose, r, "world::ctrls.world", "tz", 3.0);
    set(pose, r, "world::ctrls.world", "ry", 90.0);
    r.evaluate(pose);
    for (const std::string wheel : kWheels) {
        // Turned with the world: the tyre's up axis is still world up, not rolled.
        EXPECT_NEAR(axisAt(r, wheel + "::skin.spin", 1).y, 1.0, 1e-9) << wheel;
    }
    // Then driving forward in the turned world (+Z of the world control is now +X) rolls them.
    set(pose, r, "world::ctrls.move", "tz", 0.35);
    r.evaluate(pose);
    for (const std::string wheel : kWheels) {
        const Vec3 up = axisAt(r, wheel + "::skin.spin", 1);
        EXPECT_NEAR(std::atan2(up.x, up.y), 1.0, 1e-9) << wheel << ": one radian forward";
    }
}

TEST(VehicleTemplates, TheDoorSlidesAlongItsRailWithinItsLimits)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    const int slide = r.channel("door::ctrls.slide", "tz");
    const auto& layout = r.program->channels();
    EXPECT_TRUE(layout[std::size_t(slide)].limited);
    EXPECT_DOUBLE_EQ(layout.clamp(slide, 2.0), 0.7) << "no further than its limit_max, short of the rail's end (0.8 m)";
    EXPECT_DOUBLE_EQ(layout.clamp(slide, -0.3), 0.0) << "no further back than its start";
    // do_translate on: a plug door comes out of its frame before it slides (only the slide is limited).
    EXPECT_FALSE(layout[std::size_t(r.channel("door::ctrls.slide", "tx"))].locked);
    EXPECT_FALSE(layout[std::size_t(r.channel("door::ctrls.slide", "ty"))].locked);
    // The driver's seat (do_translate off) only slides, back by limit_max and forward by limit_min (negative:
    // ahead of its first guide).
    const int seat = r.channel("seat::ctrls.slide", "tz");
    EXPECT_DOUBLE_EQ(layout.clamp(seat, 1.0), 0.15);
    EXPECT_DOUBLE_EQ(layout.clamp(seat, -1.0), -0.1);
    EXPECT_TRUE(layout[std::size_t(r.channel("seat::ctrls.slide", "tx"))].locked);
    EXPECT_TRUE(layout[std::size_t(r.channel("seat::ctrls.slide", "ty"))].locked);

    Pose pose = r.defaults();
    pose[slide] = layout.clamp(slide, 0.5);
    r.evaluate(pose);
    EXPECT_FALSE(r.rig.findPath("door::skin.slide")) << "do_skin off: the rail carries no bone, the panel on it does";
    const Vec3 moved = r.position("door::ctrls.slide") - r.restPosition("door::ctrls.slide");
    EXPECT_NEAR(moved.z, -0.5, 1e-9) << "the rail runs back from its first guide";
    EXPECT_NEAR(moved.x, 0.0, 1e-9);
    EXPECT_NEAR(moved.y, 0.0, 1e-9);
    const Vec3 panel = r.position("panel::skin.xform") - r.restPosition("panel::skin.xform");
    EXPECT_LT(glm::length(panel - moved), 1e-9) << "the door panel hung on the rail rides on the slide";
    // The door rides on the body.
    set(pose, r, "body::ctrls.xform", "ty", 0.1);
    r.evaluate(pose);
    EXPECT_NEAR(r.position("panel::skin.xform").y - r.restPosition("panel::skin.xform").y, 0.1, 1e-9);
}

TEST(VehicleTemplates, TheRearShutterSlidesUpItsCurvedTrackIntoTheRoof)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    const int slide = r.channel("shutter::ctrls.spline.0", "slide");
    const auto& layout = r.program->channels();
    const double open = layout.clamp(slide, 10.0);
    EXPECT_NEAR(open, 0.5903, 1e-3) << "as far as the track's guides go past the top slat";
    EXPECT_DOUBLE_EQ(layout.clamp(slide, -1.0), 0.0) << "closed at rest";
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(r.restPosition("shutter::skin." + std::to_string(i)).z, -2.15, 1e-9) << "closed: the slats hang down the back";
    // sliders 4: a fourth slat rides in the track; closed, it sits where the track turns into the roof.
    EXPECT_NEAR(r.restPosition("shutter::skin.3").z, -2.10, 1e-9);
    EXPECT_GT(r.restPosition("shutter::skin.3").y, r.restPosition("shutter::skin.2").y);
    Pose pose = r.defaults();
    pose[slide] = open;
    r.evaluate(pose);
    for (int i = 0; i < 4; ++i) {
        const Vec3 slat = r.position("shutter::skin." + std::to_string(i));
        EXPECT_GT(slat.y, 0.99) << "open: slat " << i << " is up under the roof";
        EXPECT_GT(slat.z, -2.0) << "open: slat " << i << " has gone forward along the roof";
    }
    // Open, it still rides on the body.
    const Vec3 before = r.position("shutter::skin.1");
    set(pose, r, "body::ctrls.xform", "ty", 0.1);
    r.evaluate(pose);
    EXPECT_LT(glm::length(r.position("shutter::skin.1") - before - Vec3(0.0, 0.1, 0.0)), 1e-9);
}

TEST(VehicleTemplates, TheCameraAimsAtItsTargetAndRollsAboutItsViewAxis)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    auto view = [&] { return -axisAt(r, "camera::camera", 2); };
    auto towardsTarget = [&] {
        return glm::normalize(r.position("camera::ctrls.target") - r.position("camera::camera"));
    };
    Pose pose = r.defaults();
    r.evaluate(pose);
    EXPECT_GT(glm::dot(view(), towardsTarget()), 1.0 - 1e-12) << "at rest it looks at its target";
    set(pose, r, "camera::ctrls.target", "tx", 1.5);
    set(pose, r, "camera::ctrls.target", "ty", 0.4);
    r.evaluate(pose);
    EXPECT_GT(glm::dot(view(), towardsTarget()), 1.0 - 1e-12) << "moving the target aims the camera";
    set(pose, r, "camera::ctrls.camera", "tx", -2.0);
    r.evaluate(pose);
    EXPECT_GT(glm::dot(view(), towardsTarget()), 1.0 - 1e-12) << "moving the camera keeps the aim";

    const Vec3 level = axisAt(r, "camera::camera", 0);
    set(pose, r, "camera::ctrls.camera", "roll", 30.0);
    r.evaluate(pose);
    EXPECT_GT(glm::dot(view(), towardsTarget()), 1.0 - 1e-12) << "the roll keeps the aim";
    EXPECT_NEAR(glm::degrees(std::acos(glm::dot(axisAt(r, "camera::camera", 0), level))), 30.0, 1e-6);
    for (const char* lens : {"focal_length", "horizontal_aperture", "vertical_aperture", "near_clip", "far_clip", "orthographic"})
        r.channel("camera::ctrls.camera", lens);
    EXPECT_DOUBLE_EQ(pose[r.channel("camera::ctrls.camera", "focal_length")], 50.0);
}

TEST(VehicleTemplates, WorldDefaultIsTheGroundTheWheelsRollOnAndItsHookOptionHangsChildrenBesideTheControls)
{
    {   // The sample's world has hook on: its parts hang beside the controls, under a group following move.
        PosedRig r("vehicle");
        ASSERT_TRUE(r.ok());
        EXPECT_TRUE(r.rig.diagnostics.empty()) << formatAll(r.rig.diagnostics);
        const model::RigConstraint* roll = nullptr;
        for (const auto& c : r.rig.constraints)
            if (c.path == "wheel_front.L::cns.roll") roll = &c;
        ASSERT_NE(roll, nullptr);
        ASSERT_EQ(roll->kind(), model::ConstraintKind::Roll);
        EXPECT_EQ(roll->targets, std::vector<model::RigNodeIndex>{r.index("world::ctrls.world")}) << "the ground space: the world control";
        const model::RigNodeIndex hook = r.index("world::hooks.root");
        EXPECT_EQ(r.rig.nodes[r.index("body::roots.xform")].parent, hook);
        EXPECT_NE(r.rig.nodes[hook].parent, r.index("world::ctrls.move")) << "beside the controls";
        Pose pose = r.defaults();
        set(pose, r, "world::ctrls.move", "tz", 0.7);
        r.evaluate(pose);
        EXPECT_NEAR(r.position("body::ctrls.xform").z, 0.7, 1e-9) << "the hook follows the move control";
        EXPECT_NEAR(rollOf(r, "wheel_front.L"), 0.7 / kRadius, 1e-9);
    }
    model::GuideDocument guide = test::loadSample("vehicle");
    guide.instance(guide.instanceNamed("world")->id)->options.erase("hook");
    PosedRig r(guide);
    ASSERT_TRUE(r.ok());
    EXPECT_FALSE(r.rig.findPath("world::hooks.root"));
    EXPECT_EQ(r.rig.nodes[r.index("body::roots.xform")].parent, r.index("world::ctrls.move")) << "hook off: under the move control";
    Pose pose = r.defaults();
    set(pose, r, "world::ctrls.move", "tz", 0.7);
    r.evaluate(pose);
    EXPECT_NEAR(r.position("body::ctrls.xform").z, 0.7, 1e-9);
    EXPECT_NEAR(rollOf(r, "wheel_front.L"), 0.7 / kRadius, 1e-9);
}

TEST(VehicleTemplates, ARollConstraintWithoutAPositiveRadiusIsReportedAndNotEvaluated)
{
    PosedRig built("vehicle");
    ASSERT_TRUE(built.ok());
    model::Rig rig = built.rig;
    for (auto& c : rig.constraints)
        if (c.path == "wheel_front.L::cns.roll") std::get<model::RollConstraint>(c.settings).radius = 0.0;
    auto program = eval::RigProgram::compile(rig);
    ASSERT_TRUE(program.ok()) << formatAll(program.diagnostics());
    EXPECT_NE(formatAll(program.diagnostics()).find("wheel_front.L::cns.roll': its radius must be positive"), std::string::npos)
        << formatAll(program.diagnostics());
    // The dump writes its settings by name.
    const std::string dump = io::writeRigDump(built.rig);
    EXPECT_NE(dump.find("kind: roll"), std::string::npos);
    EXPECT_NE(dump.find("axle: x"), std::string::npos);
    EXPECT_NE(dump.find("radius: 0.35"), std::string::npos);
}

} // namespace
} // namespace rs
