// The range of motion never folds a chain back on itself (issue 22 item 7):
// the vehicle's roller shutter with tweakers, a tweaker's quarter-of-the-rig
// nominal move cut back so no slat passes the one before it or comes within
// a quarter of its spacing of it, along that slat's aim (the track folding), and no slat turns over from one
// exported frame to the next (a cusp in the track, where a slat's aim is
// undefined, turns it half round in one frame).
#include "core/TestSupport.h"
#include "eval/PoseTools.h"
#include "eval/RigProgram.h"
#include "io/RangeOfMotion.h"
#include "rigging/RigBuilder.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace rs;

namespace {

constexpr int kSlats = 4;          // the shutter's sliders
constexpr double kSpacing = 0.15;  // metres between the slats' guides
constexpr int kFramesPerKey = 10;  // at the export's 30 fps

// The shutter's slats in `pose`: each one's world frame (axes normalised).
std::vector<eval::Affine> slats(eval::Posing& posing, const model::Rig& rig, const eval::Pose& pose)
{
    const auto& state = posing.evaluate(pose);
    std::vector<eval::Affine> out;
    for (int i = 0; i < kSlats; ++i) {
        eval::Affine a = state.world[*rig.findPath("shutter::skin." + std::to_string(i))];
        for (int c = 0; c < 3; ++c)
            a.linear[c] = glm::normalize(a.linear[c]);
        out.push_back(a);
    }
    return out;
}

double turnDegrees(const Mat3& from, const Mat3& to)
{
    const Mat3 turn = glm::transpose(from) * to;
    return glm::degrees(std::acos(std::clamp(0.5 * (turn[0][0] + turn[1][1] + turn[2][2] - 1.0), -1.0, 1.0)));
}

} // namespace

TEST(RangeOfMotion, TheShutterTweakersNeverFoldTheTrackOrTurnASlatOverBetweenFrames)
{
    model::GuideDocument guide = test::loadSample("vehicle");
    guide.instance(guide.instanceNamed("shutter")->id)->options["tweakers"] = Value(true);
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    auto program = eval::RigProgram::compile(rig);
    ASSERT_TRUE(program);
    const eval::Pose start = eval::poseFromValues(rig, program->channels(), {});
    const auto plan = io::planRangeOfMotion(rig, *program, start);
    eval::Posing posing(rig, *program);

    int tweakers = 0;
    for (const auto& part : plan.parts) {
        const std::string& path = rig.nodes[part.control].path;
        if (path.rfind("shutter::", 0) != 0)
            continue;
        SCOPED_TRACE(path);
        tweakers += path.find("tweak") != std::string::npos;
        for (std::size_t k = part.firstKey; k < part.lastKey; ++k) {
            const eval::Pose& from = plan.keys[k];
            const eval::Pose& to = plan.keys[k + 1];
            auto previous = slats(posing, rig, from);
            for (int f = 1; f <= kFramesPerKey; ++f) {
                eval::Pose p = from;
                for (std::size_t c = 0; c < p.size(); ++c)
                    p[c] = from[c] + (to[c] - from[c]) * double(f) / kFramesPerKey;
                const auto current = slats(posing, rig, p);
                for (int i = 0; i < kSlats; ++i) {
                    EXPECT_LT(turnDegrees(previous[std::size_t(i)].linear, current[std::size_t(i)].linear), 90.0)
                        << "slat " << i << " turns over in frame " << f << " after key " << k;
                    if (i == 0)
                        continue;
                    // Ahead of the slat before it, along that slat's aim (x, down the track), by a quarter of the spacing at least.
                    const eval::Affine& before = current[std::size_t(i - 1)];
                    const double ahead = glm::dot(current[std::size_t(i)].translation - before.translation, before.linear[0]);
                    EXPECT_GT(ahead, 0.25 * kSpacing) << "slat " << i << " folds onto slat " << i - 1 << " in frame " << f
                                                      << " after key " << k;
                }
                previous = current;
            }
        }
    }
    EXPECT_EQ(tweakers, kSlats) << "the tweakers on the slats' guides are exercised (those ahead move no slat at rest)";
}
