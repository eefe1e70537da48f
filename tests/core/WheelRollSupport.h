#pragma once
// The vehicle sample's wheels for the wheel roll tests (WheelRollTest,
// WheelRollExportTest): their radius and names, how far a tyre has turned,
// turns compared up to whole turns, driving the body, and the sample with an
// option set on both wheel instances.
#include "EvalTestSupport.h"
#include "TestSupport.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <string>

namespace rs::test::wheelroll {

using eval::Pose;
using test::PosedRig;

inline constexpr double kRadius = 0.35; // the sample's wheels
inline const char* const kWheels[] = {"wheel_front.L", "wheel_front.R", "wheel_back.L", "wheel_back.R"};
inline const std::string kBody = "body::ctrls.xform";

// How far the tyre has turned about its axle, radians in (-pi, pi]: its up
// axis in the body's frame (the body only turns about Y here) turned towards
// the body's forward.
inline double rollOf(const eval::EvalState& state, const model::Rig& rig, const std::string& wheel)
{
    const Mat3 body = state.world[*rig.findPath(kBody)].rotation();
    const Vec3 up = glm::transpose(body) * glm::normalize(state.world[*rig.findPath(wheel + "::skin.spin")].rotation()[1]);
    return std::atan2(up.z, up.y);
}
inline double rollOf(const eval::EvalState& state, const PosedRig& r, const std::string& wheel) { return rollOf(state, r.rig, wheel); }
inline double rollOf(const PosedRig& r, const std::string& wheel) { return rollOf(r.state(), r, wheel); }

// `actual` and `expected` as turns of a wheel: the same up to whole turns.
inline double turnError(double actual, double expected) { return std::abs(std::remainder(actual - expected, glm::two_pi<double>())); }

// Moves the body's channel `channel` from its value in `pose` to `to` in `steps` evaluations.
inline void drive(PosedRig& r, Pose& pose, const std::string& channel, double to, int steps)
{
    const int c = r.channel(kBody, channel);
    const double from = pose[c];
    for (int i = 1; i <= steps; ++i) {
        pose[c] = from + (to - from) * i / steps;
        r.evaluate(pose);
    }
}

inline model::GuideDocument vehicleWith(const std::string& option, Value value)
{
    return test::sampleWith("vehicle", {"wheel_front", "wheel_back"}, option, value);
}

} // namespace rs::test::wheelroll
