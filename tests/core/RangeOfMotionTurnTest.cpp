// The range of motion never pops (issue 22 item 7): no deform joint of any
// sample turns more than kMostDegreesPerFrame in one frame, measured twice:
//  - the rig evaluated at every frame of the planned range (channels linear
//    between keys, as the exporter samples them): the motion the clip stands
//    for, each joint's rotation in its skin parent's frame (what a track holds);
//  - the exported clip as a player plays it: each joint track's local rotation
//    interpolated as the track says, from one whole frame to the next through
//    every sample written between them.
// Before the planner checked the way between two peaks and measured turns in
// the parents' frames, the vehicle antenna's tweak.4 turned sk_antenna9 104
// degrees in a frame, and the claw's dewclaws and talons 98 to 168 (their aim
// targets, moved half a metre for a 10 cm finger, passing through the
// phalanges, and the world-held dewclaw target with the hand swept past it).
//
// Why 60 degrees: the planner's widest nominal move is a hinge's 90 degrees
// over a key interval (10 frames at 30 fps), 9 degrees a frame; a joint the
// rig amplifies (an aim chain, a spline's tip) may turn a few times its
// control, still far under 60. A joint turning more than 90 degrees between
// two frames is played the short way round by every engine (so what plays is
// not what was evaluated), and over 60 degrees, a sixth of a turn in 33 ms, is
// a solver giving way (an aim target passing through its joint or up vector,
// a chain folding), not a motion a rigger checks skinning with. The planner
// cuts its peaks at 45 degrees a frame (io/RangeOfMotion.h), so this bound
// holds with a margin where a peak is cut at the edge of a flip.
#include "core/TestSupport.h"
#include "eval/RigProgram.h"
#include "io/RangeOfMotion.h"
#include "io/RigExport.h"
#include "model/Skeleton.h"
#include "rigging/RigBuilder.h"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

using namespace rs;

namespace {

constexpr double kMostDegreesPerFrame = 60.0;

double turnDegrees(const Quat& a, const Quat& b)
{
    return glm::degrees(2.0 * std::acos(std::clamp(std::abs(glm::dot(glm::normalize(a), glm::normalize(b))), 0.0, 1.0)));
}

struct Worst {
    double degrees = 0.0;
    std::string where;
};

// The largest turn of a joint's track in one frame of `clip`: from frame f to
// f + 1 through the samples written strictly between them.
Worst worstTurnPerFrame(const io::ExportScene& scene, const io::ExportClip& clip)
{
    Worst worst;
    const double fps = clip.framesPerSecond;
    const long long frames = std::llround(clip.times.back() * fps);
    for (const auto& track : clip.tracks) {
        if (!track.isJoint() || !(track.animated & io::kRotationChannel))
            continue;
        std::size_t s = 0; // the first sample after the frame being measured
        for (long long f = 0; f < frames; ++f) {
            const double from = double(f) / fps, to = double(f + 1) / fps;
            std::vector<double> times{from};
            while (s < clip.times.size() && clip.times[s] <= from + 1e-9)
                ++s;
            for (std::size_t k = s; k < clip.times.size() && clip.times[k] < to - 1e-9; ++k)
                times.push_back(clip.times[k]);
            times.push_back(to);
            double turned = 0.0;
            for (std::size_t i = 1; i < times.size(); ++i)
                turned += turnDegrees(io::trackRotationAt(track, clip.times, times[i - 1]),
                                      io::trackRotationAt(track, clip.times, times[i]));
            if (turned > worst.degrees) {
                std::ostringstream where;
                where << scene.joints[std::size_t(track.node)].name << " in " << clip.name << " frame " << f;
                for (const auto& marker : clip.markers)
                    if (from >= marker.start - 1e-9 && to <= marker.end + 1e-9)
                        where << " (" << marker.control << ")";
                worst = {turned, where.str()};
            }
        }
    }
    return worst;
}

Mat3 unitAxes(Mat3 m)
{
    for (int c = 0; c < 3; ++c)
        m[c] = glm::normalize(m[c]);
    return m;
}

double turnDegrees(const Mat3& from, const Mat3& to)
{
    const Mat3 turn = glm::transpose(from) * to;
    return glm::degrees(std::acos(std::clamp(0.5 * (turn[0][0] + turn[1][1] + turn[2][2] - 1.0), -1.0, 1.0)));
}

// The largest turn of a deform joint's local rotation (in its skin parent's
// frame) from one frame of the planned range of motion to the next, the rig
// evaluated at every frame (channels linear between keys, as the exporter
// samples them): the motion the clip stands for.
Worst worstEvaluatedTurn(const model::Rig& rig, const eval::RigProgram& program, const io::RangeOfMotionPlan& plan)
{
    const auto skeleton = model::extractSkeleton(rig);
    Worst worst;
    if (!skeleton || plan.keys.empty())
        return worst;
    const int step = io::framesPerKey(30.0);
    eval::EvalState state = program.makeState();
    auto locals = [&](const eval::Pose& pose) {
        program.evaluate(pose, state);
        std::vector<Mat3> out;
        for (const auto& joint : skeleton->joints) {
            if (joint.node == model::kNoNode || (joint.parent >= 0 && skeleton->joints[std::size_t(joint.parent)].node == model::kNoNode)) {
                out.push_back(Mat3(1.0)); // not driven by the rig: never turns
                continue;
            }
            const Mat3 world = unitAxes(state.world[joint.node].linear);
            out.push_back(joint.parent < 0 ? world
                                           : glm::transpose(unitAxes(state.world[skeleton->joints[std::size_t(joint.parent)].node].linear)) * world);
        }
        return out;
    };
    std::vector<Mat3> previous = locals(plan.keys[0]);
    for (std::size_t k = 0; k + 1 < plan.keys.size(); ++k)
        for (int f = 1; f <= step; ++f) {
            eval::Pose pose = plan.keys[k];
            for (std::size_t c = 0; c < pose.size(); ++c)
                if (program.channels()[c].transform != eval::kRotateOrderChannel && !program.channels()[c].isEnum())
                    pose[c] += (plan.keys[k + 1][c] - plan.keys[k][c]) * double(f) / double(step);
            std::vector<Mat3> current = locals(pose);
            for (std::size_t j = 0; j < current.size(); ++j)
                if (const double turned = turnDegrees(previous[j], current[j]); turned > worst.degrees) {
                    std::ostringstream where;
                    where << skeleton->joints[j].name << " in frame " << f << " after key " << k;
                    for (const auto& part : plan.parts)
                        if (k >= part.firstKey && k < part.lastKey)
                            where << " (" << rig.nodes[part.control].path << ")";
                    worst = {turned, where.str()};
                }
            previous = std::move(current);
        }
    return worst;
}

} // namespace

TEST(RangeOfMotion, NoDeformJointOfAnySampleTurnsMoreThanSixtyDegreesInOneFrame)
{
    for (const std::string name : {"biped", "quadruped", "prop", "face", "vehicle", "robot", "claw", "cart"}) {
        SCOPED_TRACE(name);
        const model::Rig rig = rigging::buildRig(test::loadSample(name), test::builtinTemplates());
        io::ExportOptions options;
        options.rangeOfMotion = true;
        const auto prepared = io::prepareExport(rig, options);
        ASSERT_TRUE(prepared.scene) << formatAll(prepared.report);
        ASSERT_FALSE(prepared.scene->clips.empty());
        auto program = eval::RigProgram::compile(rig);
        ASSERT_TRUE(program);
        const Worst evaluated = worstEvaluatedTurn(rig, *program, io::planRangeOfMotion(rig, *program, program->channels().defaults()));
        EXPECT_LT(evaluated.degrees, kMostDegreesPerFrame) << "evaluated: " << evaluated.where;
        for (const auto& clip : prepared.scene->clips) {
            const Worst worst = worstTurnPerFrame(*prepared.scene, clip);
            EXPECT_LT(worst.degrees, kMostDegreesPerFrame) << worst.where;
        }
    }
}
