// The cart sample (resources/samples/cart.yml) as an animator checks it: a
// mine cart on straight rails along +Z, a game prop at a fixed scale
// (world.prop do_scale off, a chassis and a tub that do not scale). Its wheels
// roll only as the chassis is pushed along the rails (wheel.legacy hook world:
// the move control places the cart on the track without rolling them); the
// front axle measures its displacement along the rails (roll axis), the back
// axle the path it takes (roll path), with a roll_jump of 1.5 m that a
// runaway cart's step of a frame stays under and a snap along the track does not.
// Where a test shows what an option changes, it builds the cart with that
// option at its default beside it (test::sampleWith).
#include "EvalTestSupport.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

constexpr double kRadius = 0.15; // the cart's wheels: axis guide to ground guide
const char* const kFront[] = {"wheel_front.L", "wheel_front.R"};
const char* const kBack[] = {"wheel_back.L", "wheel_back.R"};
const char* const kWheels[] = {"wheel_front.L", "wheel_front.R", "wheel_back.L", "wheel_back.R"};
const std::string kChassis = "chassis::ctrls.xform";
const std::string kMove = "world::ctrls.move";

// How far the tyre has turned about its axle, radians in (-pi, pi]: its up
// axis (at rest +Y) turned towards forward (+Z). The cart does not turn here.
double rollOf(const PosedRig& r, const std::string& wheel)
{
    const Vec3 up = glm::normalize(r.state().world[r.index(wheel + "::skin.spin")].rotation()[1]);
    return std::atan2(up.z, up.y);
}

// `actual` and `expected` as turns of a wheel: the same up to whole turns.
double turnError(double actual, double expected) { return std::abs(std::remainder(actual - expected, glm::two_pi<double>())); }

// Moves `control`'s `channel` from its value in `pose` to `to` in `steps` evaluations (frames).
void push(PosedRig& r, Pose& pose, const std::string& control, const std::string& channel, double to, int steps)
{
    const int c = r.channel(control, channel);
    const double from = pose[c];
    for (int i = 1; i <= steps; ++i) {
        pose[c] = from + (to - from) * i / steps;
        r.evaluate(pose);
    }
}

TEST(Cart, PushingTheCartOneMetreAlongItsRailsRollsEachWheelOneOverItsRadius)
{
    PosedRig r("cart");
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.rig.diagnostics.empty()) << formatAll(r.rig.diagnostics);
    Pose pose = r.defaults();
    push(r, pose, kChassis, "tz", 1.0, 30); // pushed over 30 frames
    for (const std::string wheel : kWheels) {
        EXPECT_NEAR(r.position(wheel + "::skin.spin").z - r.restPosition(wheel + "::skin.spin").z, 1.0, 1e-9) << wheel;
        EXPECT_LT(turnError(rollOf(r, wheel), 1.0 / kRadius), 1e-9) << wheel << " rolled " << rollOf(r, wheel);
    }
    // Pulled back to where it stood, every wheel is unrolled again.
    push(r, pose, kChassis, "tz", 0.0, 30);
    for (const std::string wheel : kWheels)
        EXPECT_NEAR(rollOf(r, wheel), 0.0, 1e-9) << wheel;
}

// hook world: "what follows the world and move controllers (only the
// vehicle's own controls roll them)". The default (ground) rolls them as the
// move control carries them.
TEST(Cart, TheMoveControlPlacesTheCartOnTheTrackWithoutRollingItsWheelsAndTheChassisRollsThem)
{
    PosedRig r("cart");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    push(r, pose, kMove, "tz", 3.0, 30);
    push(r, pose, "world::ctrls.world", "tz", 0.5, 10);
    for (const std::string wheel : kWheels) {
        EXPECT_NEAR(r.position(wheel + "::skin.spin").z - r.restPosition(wheel + "::skin.spin").z, 3.5, 1e-9) << wheel;
        EXPECT_NEAR(rollOf(r, wheel), 0.0, 1e-9) << wheel << ": carried, not rolled";
    }
    push(r, pose, kChassis, "tz", 0.5, 10); // then pushed along the rails from there
    for (const std::string wheel : kWheels)
        EXPECT_LT(turnError(rollOf(r, wheel), 0.5 / kRadius), 1e-9) << wheel << " rolled " << rollOf(r, wheel);

    PosedRig ground(test::sampleWith("cart", {"wheel_front", "wheel_back"}, "hook", Value(std::string("ground"))));
    ASSERT_TRUE(ground.ok());
    Pose groundPose = ground.defaults();
    push(ground, groundPose, kMove, "tz", 0.5, 10);
    for (const std::string wheel : kWheels)
        EXPECT_LT(turnError(rollOf(ground, wheel), 0.5 / kRadius), 1e-9) << wheel << " (hook ground) rolled " << rollOf(ground, wheel);
}

// roll_jump 1.5 m on the back axle (roll path): a cart running away down the
// mine at 25 m/s travels 1.04 m a frame at 24 fps, more than its wheels'
// circumference (0.94 m, the default limit), and still rolls them; a snap of
// 5 m along the track (re-placing the cart) moves them without rolling them.
// The front axle (roll axis) rolls by where it is, whatever came before.
TEST(Cart, ARunawayCartsStepOfAFrameRollsTheBackWheelsAndASnapAlongTheTrackDoesNot)
{
    PosedRig r("cart");
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    push(r, pose, kChassis, "tz", 0.1, 2);
    push(r, pose, kChassis, "tz", 1.3, 1); // a step of 1.2 m in one frame
    for (const std::string wheel : kWheels)
        EXPECT_LT(turnError(rollOf(r, wheel), 1.3 / kRadius), 1e-9) << wheel << " rolled " << rollOf(r, wheel);
    push(r, pose, kChassis, "tz", 6.3, 1); // a snap of 5 m
    for (const std::string wheel : kBack)
        EXPECT_LT(turnError(rollOf(r, wheel), 1.3 / kRadius), 1e-9) << wheel << ": moved, not rolled";
    for (const std::string wheel : kFront)
        EXPECT_LT(turnError(rollOf(r, wheel), 6.3 / kRadius), 1e-9) << wheel << ": its displacement along the rails";
    push(r, pose, kChassis, "tz", 6.5, 4); // from there the back wheels roll again
    for (const std::string wheel : kBack)
        EXPECT_LT(turnError(rollOf(r, wheel), 1.5 / kRadius), 1e-9) << wheel << " rolled " << rollOf(r, wheel);

    // At the default roll_jump (one circumference) the runaway step is a jump.
    PosedRig circumference(test::sampleWith("cart", {"wheel_back"}, "roll_jump", Value(0.0)));
    ASSERT_TRUE(circumference.ok());
    Pose defaultPose = circumference.defaults();
    push(circumference, defaultPose, kChassis, "tz", 0.1, 2);
    push(circumference, defaultPose, kChassis, "tz", 1.3, 1);
    for (const std::string wheel : kBack)
        EXPECT_LT(turnError(rollOf(circumference, wheel), 0.1 / kRadius), 1e-9) << wheel << " (roll_jump 0) rolled " << rollOf(circumference, wheel);
}

// world.prop do_scale off: no scale control under move; the chassis and the
// tub (core.xform do_scale off) keep their scale locked. Only the wheels' bank
// controls scale, which flattens a tyre on the rail, not the cart.
TEST(Cart, AGamePropAtAFixedScaleHasNoScaleControl)
{
    PosedRig r("cart");
    ASSERT_TRUE(r.ok());
    EXPECT_FALSE(r.rig.findPath("world::ctrls.scale"));
    const auto post = r.rig.findPath("world::grps.post");
    ASSERT_TRUE(post);
    EXPECT_EQ(r.rig.nodes[*post].parent, r.index(kMove)) << "the post transform hangs under move";
    const model::GuideDocument guide = test::loadSample("cart");
    int scaled = 0;
    for (const auto& node : r.rig.nodes) {
        if (node.kind != model::RigNodeKind::Controller)
            continue;
        const bool bank = node.key.tag == "ctrls.bank";
        for (const char* axis : {"sx", "sy", "sz"}) {
            const int c = model::channelIndex(axis);
            if (bank) {
                scaled += node.channels.isAnimatable(c);
                continue;
            }
            EXPECT_FALSE(node.channels.isAnimatable(c)) << node.path << " " << axis;
            if (guide.instance(node.key.instance)->templateId == "core.xform") {
                EXPECT_TRUE(node.channels.isLocked(c)) << node.path << " " << axis;
            }
        }
    }
    EXPECT_EQ(scaled, 12) << "the four banks flatten their tyres";

    PosedRig scaling(test::sampleWith("cart", {"world"}, "do_scale", Value(true)));
    ASSERT_TRUE(scaling.ok());
    const auto scale = scaling.rig.findPath("world::ctrls.scale");
    ASSERT_TRUE(scale) << "world.prop's default has one";
    EXPECT_TRUE(scaling.rig.nodes[*scale].channels.isAnimatable(model::channelIndex("sy")));
}

// The largest extent of a node's first control curve (its shape as built, before any pose).
double shapeSpan(const PosedRig& r, const std::string& node)
{
    Vec3 lo(1e300), hi(-1e300);
    for (const Vec3& p : r.rig.nodes[r.index(node)].curves.at(0).points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const Vec3 extent = hi - lo;
    return std::max({extent.x, extent.y, extent.z});
}

TEST(Cart, TheWheelControlsFitItsSmallWheelsAsTheVehiclesFitItsOwn)
{
    // The cart's 0.15 m wheels steer about a pivot 0.1 m inboard, as the vehicle's 0.35 m wheels do: the control
    // circle around each tyre is sized by the wheel's radius, not by that offset, so it rings the tyre alike.
    PosedRig cart("cart"), vehicle("vehicle");
    ASSERT_TRUE(cart.ok());
    ASSERT_TRUE(vehicle.ok());
    const double vehicleRing = shapeSpan(vehicle, "wheel_front.L::ctrls.wheel") / (2.0 * 0.35);
    EXPECT_GT(vehicleRing, 1.0) << "the vehicle's wheel control rings its tyre";
    EXPECT_LT(vehicleRing, 1.3);
    for (const char* wheel : kWheels)
        EXPECT_NEAR(shapeSpan(cart, std::string(wheel) + "::ctrls.wheel") / (2.0 * kRadius), vehicleRing, 1e-6) << wheel;
}

} // namespace
} // namespace rs
