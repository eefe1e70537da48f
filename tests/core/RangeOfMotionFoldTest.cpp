// The range of motion never folds a chain back on itself (issue 22 item 7),
// on the vehicle with its shutter's tweakers: a tweaker's or spline
// controller's quarter-of-the-rig nominal move is cut back so that, at every
// exported frame (on the way to a peak too), no deform joint passes its skin
// parent or comes within a quarter of its rest distance of it, along the rest
// direction in the parent's frame (a slat passing the one before it: the track
// folded; the antenna's tip folding back behind the joint before it and out
// again between two sampled steps), and no slat turns over from one frame to
// the next (a cusp in the track, where a slat's aim is undefined, turns it
// half round in one frame).
#include "core/TestSupport.h"
#include "eval/PoseTools.h"
#include "eval/RigProgram.h"
#include "io/RangeOfMotion.h"
#include "model/Skeleton.h"
#include "rigging/RigBuilder.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace rs;

namespace {

constexpr int kSlats = 4;         // the shutter's sliders
constexpr int kFramesPerKey = 10; // at the export's 30 fps

double turnDegrees(const Mat3& from, const Mat3& to)
{
    const Mat3 turn = glm::transpose(from) * to;
    return glm::degrees(std::acos(std::clamp(0.5 * (turn[0][0] + turn[1][1] + turn[2][2] - 1.0), -1.0, 1.0)));
}

Mat3 unitAxes(Mat3 m)
{
    for (int c = 0; c < 3; ++c)
        m[c] = glm::normalize(m[c]);
    return m;
}

} // namespace

TEST(RangeOfMotion, NoFrameFoldsTheVehiclesChainsOrTurnsAShutterSlatOver)
{
    model::GuideDocument guide = test::loadSample("vehicle");
    guide.instance(guide.instanceNamed("shutter")->id)->options["tweakers"] = Value(true);
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    auto program = eval::RigProgram::compile(rig);
    ASSERT_TRUE(program);
    const auto skeleton = model::extractSkeleton(rig);
    ASSERT_TRUE(skeleton);
    const eval::Pose start = eval::poseFromValues(rig, program->channels(), {});
    const auto plan = io::planRangeOfMotion(rig, *program, start);
    eval::Posing posing(rig, *program);
    std::vector<model::RigNodeIndex> slats;
    for (int i = 0; i < kSlats; ++i)
        slats.push_back(*rig.findPath("shutter::skin." + std::to_string(i)));

    int tweakers = 0, checked = 0;
    for (const auto& part : plan.parts) {
        const std::string& path = rig.nodes[part.control].path;
        SCOPED_TRACE(path);
        tweakers += path.rfind("shutter::ctrls.tweak", 0) == 0;
        for (std::size_t k = part.firstKey; k < part.lastKey; ++k) {
            const eval::Pose& from = plan.keys[k];
            const eval::Pose& to = plan.keys[k + 1];
            std::vector<Mat3> previous;
            for (auto s : slats)
                previous.push_back(unitAxes(posing.evaluate(from).world[s].linear));
            for (int f = 1; f <= kFramesPerKey; ++f) {
                eval::Pose p = from;
                for (std::size_t c = 0; c < p.size(); ++c)
                    p[c] = from[c] + (to[c] - from[c]) * double(f) / kFramesPerKey;
                const auto& state = posing.evaluate(p);
                for (const auto& joint : skeleton->joints) {
                    const Vec3 rest = translationOf(joint.bindLocal);
                    if (joint.parent < 0 || glm::length(rest) < 1e-3)
                        continue;
                    const eval::Affine& parent = state.world[skeleton->joints[std::size_t(joint.parent)].node];
                    const Vec3 local = glm::inverse(parent.linear) * (state.world[joint.node].translation - parent.translation);
                    EXPECT_GT(glm::dot(local, glm::normalize(rest)), 0.25 * glm::length(rest))
                        << joint.name << " folds onto its parent in frame " << f << " after key " << k;
                    ++checked;
                }
                for (int i = 0; i < kSlats; ++i) {
                    const Mat3 current = unitAxes(state.world[slats[std::size_t(i)]].linear);
                    EXPECT_LT(turnDegrees(previous[std::size_t(i)], current), 90.0)
                        << "slat " << i << " turns over in frame " << f << " after key " << k;
                    previous[std::size_t(i)] = current;
                }
            }
        }
    }
    EXPECT_GT(checked, 10000);
    EXPECT_EQ(tweakers, kSlats) << "the tweakers on the slats' guides are exercised (those ahead move no slat at rest)";
}
