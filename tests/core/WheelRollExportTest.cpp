// wheel.legacy's path roll in what leaves the editor: exports roll the
// wheels along the clip in time order (two exports byte-identical), a keyed
// clip rolls them along the path between sparse keys, and the range of
// motion is evaluated in time order where its samples are refined.
#include "EvalTestSupport.h"
#include "WheelRollSupport.h"
#include "io/ExportScene.h"
#include "io/RangeOfMotion.h"
#include "io/RigExport.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

namespace rs {
namespace {

using namespace test::wheelroll;

std::string fileBytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(WheelRoll, ExportsRollAlongTheClipInTimeOrderAndAreByteIdentical)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    const model::GuideDocument guide = test::loadSample("vehicle");
    // Keyed: 1 m forward in 100 keys, then a quarter turn in 100 keys.
    io::KeyedClip drive{"drive", {}, {}};
    const NodeKey body = r.rig.nodes[r.index(kBody)].key;
    for (int k = 0; k <= 200; ++k) {
        drive.times.push_back(k / 30.0);
        drive.poses.push_back({{body, {{"tz", std::min(k, 100) / 100.0}, {"ry", std::max(k - 100, 0) * 0.9}}}});
    }
    const std::vector<io::KeyedClip> clips{drive};
    io::ExportOptions options;
    options.guide = &guide;
    options.rangeOfMotion = true;
    options.keyedClips = &clips;
    auto prepared = io::prepareExport(r.rig, options);
    ASSERT_TRUE(prepared.scene) << formatAll(prepared.report);
    const io::ExportClip& clip = prepared.scene->clips.back();
    ASSERT_EQ(clip.name, "drive");
    const std::string spin = r.rig.nodes[r.index("wheel_front.R::skin.spin")].name;
    const io::ExportTrack* track = nullptr;
    for (const auto& t : clip.tracks)
        if (!t.controller && prepared.scene->joints[std::size_t(t.node)].name == spin) track = &t;
    ASSERT_NE(track, nullptr) << spin << " does not roll in the clip";
    auto angleAt = [&](std::size_t key) { // about the hub's X
        const Quat q = track->rotations[key];
        return 2.0 * std::atan2(q.x, q.w);
    };
    EXPECT_LT(turnError(angleAt(100), 1.0 / kRadius), 1e-6) << "1 m forward";
    const double side = r.restPosition("wheel_front.R::mch.roll").x - r.restPosition(kBody).x;
    EXPECT_LT(turnError(angleAt(200), (1.0 - side * glm::half_pi<double>()) / kRadius), 1e-3) << "then its arc of the turn";

    const std::string first = test::temporaryPath("wheel-roll-1.glb"), second = test::temporaryPath("wheel-roll-2.glb");
    ASSERT_FALSE(hasErrors(io::exportRig(r.rig, first, options)));
    ASSERT_FALSE(hasErrors(io::exportRig(r.rig, second, options)));
    const std::string bytes = fileBytes(first);
    EXPECT_GT(bytes.size(), 1000u);
    EXPECT_TRUE(bytes == fileBytes(second)) << "two exports of the same clips differ";
}

// Two keys 5 m apart (longer than a wheel's circumference, the teleport
// distance): the export rolls the wheels along the frames between the keys,
// as playing the clip in the editor would, not by one skipped jump.
TEST(WheelRoll, AKeyedClipRollsTheWheelsAlongThePathBetweenSparseKeys)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    const model::GuideDocument guide = test::loadSample("vehicle");
    const NodeKey body = r.rig.nodes[r.index(kBody)].key;
    io::KeyedClip drive{"drive", {0.0, 2.0}, {{{body, {{"tz", 0.0}}}}, {{body, {{"tz", 5.0}}}}}};
    const std::vector<io::KeyedClip> clips{drive};
    io::ExportOptions options;
    options.guide = &guide;
    options.keyedClips = &clips;
    auto prepared = io::prepareExport(r.rig, options);
    ASSERT_TRUE(prepared.scene) << formatAll(prepared.report);
    const io::ExportClip& clip = prepared.scene->clips.back();
    ASSERT_EQ(clip.times.size(), 2u) << "the authored keys stay the keys";
    const std::string spin = r.rig.nodes[r.index("wheel_front.L::skin.spin")].name;
    const io::ExportTrack* track = nullptr;
    for (const auto& t : clip.tracks)
        if (!t.controller && !t.camera && prepared.scene->joints[std::size_t(t.node)].name == spin) track = &t;
    ASSERT_NE(track, nullptr) << spin << " does not roll in the clip";
    const Quat q = glm::normalize(glm::conjugate(track->rotations.front()) * track->rotations.back());
    EXPECT_LT(turnError(2.0 * std::atan2(q.x, q.w), 5.0 / kRadius), 1e-3) << "5 m rolled";
}

// The export's range of motion refines the samples where a node turns far
// between two keys (the wheels do): every whole-frame sample, refined or
// not, must be what evaluating the clip's samples in time order gives.
TEST(WheelRoll, TheRangeOfMotionIsEvaluatedInTimeOrderWhereItsSamplesAreRefined)
{
    PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    io::ExportOptions options;
    options.rangeOfMotion = true;
    auto prepared = io::prepareExport(r.rig, options);
    ASSERT_TRUE(prepared.scene) << formatAll(prepared.report);
    ASSERT_FALSE(prepared.scene->clips.empty());
    const io::ExportClip& clip = prepared.scene->clips.front(); // from the plan's first key, a new state
    ASSERT_TRUE(clip.name == "range_of_motion" || clip.name == "range_of_motion_1") << clip.name;
    const std::string spin = r.rig.nodes[r.index("wheel_front.R::skin.spin")].name;
    const io::ExportTrack* track = nullptr;
    for (const auto& t : clip.tracks)
        if (!t.controller && prepared.scene->joints[std::size_t(t.node)].name == spin) track = &t;
    ASSERT_NE(track, nullptr);

    const io::RangeOfMotionPlan plan = io::planRangeOfMotion(r.rig, *r.program, r.defaults());
    const int step = io::framesPerKey(clip.framesPerSecond);
    const eval::ChannelLayout& layout = r.program->channels();
    eval::EvalState state = r.program->makeState();
    int refined = 0;
    for (std::size_t i = 0; i < clip.times.size(); ++i) {
        const double frame = clip.times[i] * clip.framesPerSecond;
        if (std::abs(frame - std::round(frame)) > 1e-6)
            continue; // half way within a frame: not evaluated, the players' own interpolation
        const auto whole = std::size_t(std::llround(frame));
        const std::size_t k = std::min(whole / std::size_t(step), plan.keys.size() - 1);
        Pose pose = plan.keys[k];
        if (whole % std::size_t(step) != 0) { // a refined sample between keys k and k + 1
            ++refined;
            const double fraction = double(whole % std::size_t(step)) / step;
            for (std::size_t c = 0; c < pose.size(); ++c)
                if (layout[c].transform != eval::kRotateOrderChannel && !layout[c].isEnum())
                    pose[c] += (plan.keys[k + 1][c] - pose[c]) * fraction;
        }
        r.program->evaluate(pose, state);
        const Mat3 hub = state.world[r.index("wheel_front.R::skin.wheel")].rotation();
        const Vec3 up = glm::transpose(hub) * glm::normalize(state.world[r.index("wheel_front.R::skin.spin")].rotation()[1]);
        const Quat q = track->rotations[i];
        EXPECT_LT(turnError(2.0 * std::atan2(q.x, q.w), std::atan2(up.z, up.y)), 1e-6) << "frame " << frame;
    }
    EXPECT_GT(refined, 0) << "no sample was refined: the test checks nothing the keys do not";
}

} // namespace
} // namespace rs
