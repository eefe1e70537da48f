// spine.torso's options as an animator checks them on the built and evaluated
// biped (issue 22): where the hips pivot, stretch by translation or by scale,
// skin joints spread by length or by guide segment, and the controls' axes.
#include "EvalTestSupport.h"
#include "IncrementalCheck.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <functional>
#include <string>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

model::GuideDocument withSpineOptions(const std::map<std::string, Value>& options)
{
    model::GuideDocument guide = test::loadSample("biped");
    for (const auto& [name, value] : options)
        guide.instance(guide.instanceNamed("spine")->id)->options[name] = value;
    return guide;
}

std::string skin(std::size_t i) { return "spine::skin." + std::to_string(i); }

// The spine's guide points (the skin joints at rest with one per guide joint).
std::vector<Vec3> spineGuides(const PosedRig& r)
{
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < 5; ++i)
        points.push_back(r.restPosition(skin(i)));
    return points;
}

// The point halfway along a polyline by length.
Vec3 halfway(const std::vector<Vec3>& points)
{
    double total = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i)
        total += glm::length(points[i] - points[i - 1]);
    double left = total / 2.0;
    for (std::size_t i = 1; i < points.size(); ++i) {
        const double span = glm::length(points[i] - points[i - 1]);
        if (left <= span)
            return glm::mix(points[i - 1], points[i], left / span);
        left -= span;
    }
    return points.back();
}

Mat3 worldRotation(const PosedRig& r, const std::string& id) { return r.state().world[r.index(id)].rotation(); }

// Where the pelvis goes when the hips turn 30 degrees forward, and where the
// hips' rotation would take it about `pivot`.
void expectHipsTurnAbout(const std::string& pivots, const std::function<Vec3(const std::vector<Vec3>&)>& pivotOf)
{
    PosedRig r(withSpineOptions({{"pivots", Value(pivots)}}));
    ASSERT_TRUE(r.ok()) << pivots;
    const Vec3 pivot = pivotOf(spineGuides(r));
    EXPECT_LT(glm::length(r.restPosition("spine::ctrls.hips") - pivot), 1e-9) << pivots << ": the hips control sits at its pivot";
    r.evaluate(r.defaults());
    const Mat3 rest = worldRotation(r, "spine::ctrls.hips");
    Pose pose = r.defaults();
    pose[r.channel("spine::ctrls.hips", "rx")] = 30.0;
    r.evaluate(pose);
    const Mat3 turn = worldRotation(r, "spine::ctrls.hips") * glm::transpose(rest);
    const Vec3 pelvis = r.restPosition(skin(0));
    EXPECT_LT(glm::length(r.position(skin(0)) - (pivot + turn * (pelvis - pivot))), 1e-9) << pivots;
    EXPECT_LT(glm::length(r.position(skin(4)) - r.restPosition(skin(4))), 1e-6) << pivots << ": the chest stays";
    EXPECT_LT(glm::length(r.position("leg.L::skin.limb.0") - (pivot + turn * (r.restPosition("leg.L::skin.limb.0") - pivot))), 1e-6)
        << pivots << ": the legs hang on the pelvis";
}

TEST(TorsoRig, PivotsPlaceWhereTheHipsTurn)
{
    expectHipsTurnAbout("legacy", [](const std::vector<Vec3>& g) { return g[0]; });
    expectHipsTurnAbout("spine1", [](const std::vector<Vec3>& g) { return g[1]; });
    expectHipsTurnAbout("centered", [](const std::vector<Vec3>& g) { return halfway(g); });
    PosedRig centered(withSpineOptions({{"pivots", Value(std::string("centered"))}}));
    ASSERT_TRUE(centered.ok());
    EXPECT_GT(glm::length(centered.restPosition("spine::ctrls.hips") - centered.restPosition(skin(0))), 0.2) << "the mid point, not the hips";
}

// The chest pulled 20 cm up.
Pose chestUp(PosedRig& r)
{
    Pose pose = r.defaults();
    pose[r.channel("spine::ctrls.ik_chest", "ty")] = 0.2;
    return pose;
}

TEST(TorsoRig, StretchModeScaleGrowsTheSpineJointsAlongTheSpineAndTranslateKeepsThemAtOne)
{
    for (const long long skinJoints : {0LL, 6LL}) {
        PosedRig translate(withSpineOptions({{"skin_joints", Value(skinJoints)}}));
        PosedRig scale(withSpineOptions({{"skin_joints", Value(skinJoints)}, {"stretch_mode", Value(std::string("scale"))}}));
        ASSERT_TRUE(translate.ok() && scale.ok());
        translate.evaluate(chestUp(translate));
        scale.evaluate(chestUp(scale));
        const std::size_t last = skinJoints > 0 ? std::size_t(skinJoints) : 4;
        const double restSpan = glm::length(translate.restPosition(skin(last)) - translate.restPosition(skin(1)));
        const double span = glm::length(translate.position(skin(last)) - translate.position(skin(1)));
        ASSERT_GT(span / restSpan, 1.2) << "the spine stretches";
        for (std::size_t i = 1; i < last; ++i) {
            EXPECT_LT(glm::length(translate.state().world[translate.index(skin(i))].scale() - Vec3(1.0)), 1e-9) << skinJoints << " " << i;
            EXPECT_LT(glm::length(scale.position(skin(i)) - translate.position(skin(i))), 1e-9) << "the same places";
            EXPECT_GT(scale.state().world[scale.index(skin(i))].scale().x, 1.1) << skinJoints << " " << i << " grows along the spine";
            EXPECT_NEAR(scale.state().world[scale.index(skin(i))].scale().y, 1.0, 1e-9);
        }
        EXPECT_NEAR(scale.state().world[scale.index(skin(last))].scale().x, 1.0, 1e-9) << "the chest keeps its size (the neck and arms too)";
    }
}

TEST(TorsoRig, BonesLengthParametricSpreadsSkinJointsByGuideSegment)
{
    model::GuideDocument guide = withSpineOptions({{"skin_joints", Value(4LL)}, {"bones_length", Value(std::string("parametric"))}});
    auto& joints = guide.instance(guide.instanceNamed("spine")->id)->joints;
    joints[1].local.translate *= 2.0; // a long lumbar segment, then three short ones
    PosedRig parametric(guide);
    guide.instance(guide.instanceNamed("spine")->id)->options["bones_length"] = Value(std::string("equal"));
    PosedRig equal(guide);
    ASSERT_TRUE(parametric.ok() && equal.ok());
    // The guide points: the driven chain sits on them.
    std::vector<Vec3> g;
    for (std::size_t i = 0; i < 5; ++i)
        g.push_back(equal.restPosition("spine::blend." + std::to_string(i)));
    for (std::size_t k = 1; k < 4; ++k) // k quarters of the four guide segments: on guide joint k
        EXPECT_LT(glm::length(parametric.restPosition(skin(k)) - g[k]), 1e-9) << k;
    double total = 0.0;
    for (std::size_t i = 1; i < 5; ++i)
        total += glm::length(g[i] - g[i - 1]);
    const double first = glm::length(g[1] - g[0]);
    ASSERT_GT(first, total / 4.0 + 0.05);
    EXPECT_LT(glm::length(equal.restPosition(skin(1)) - glm::mix(g[0], g[1], (total / 4.0) / first)), 1e-9) << "a quarter of the length";
}

TEST(TorsoRig, OrientOptionsTurnTheControlsWithTheSpine)
{
    PosedRig oriented(withSpineOptions({{"orient_pelvis", Value(true)}, {"orient_spine", Value(true)}, {"orient_shoulders", Value(true)}}));
    PosedRig upright("biped");
    ASSERT_TRUE(oriented.ok() && upright.ok());
    const auto g = spineGuides(upright);
    const auto xAxis = [](const PosedRig& r, const std::string& id) { return glm::normalize(Vec3(r.rig.nodes[r.index(id)].worldMatrix[0])); };
    EXPECT_GT(glm::dot(xAxis(oriented, "spine::ctrls.hips"), glm::normalize(g[1] - g[0])), 0.9999);
    EXPECT_GT(glm::dot(xAxis(oriented, "spine::ctrls.ik_chest"), glm::normalize(g[4] - g[3])), 0.9999);
    EXPECT_GT(glm::dot(xAxis(oriented, "spine::ctrls.ik_mid"), Vec3(0.0, 1.0, 0.0)), 0.99);
    for (const std::string id : {"spine::ctrls.hips", "spine::ctrls.ik_chest", "spine::ctrls.ik_mid"})
        EXPECT_LT(maxAbsDifference(Mat4(Mat3(upright.rig.nodes[upright.index(id)].worldMatrix)), Mat4(1.0)), 1e-12) << id << " upright by default";
    for (std::size_t i = 0; i < 5; ++i)
        EXPECT_LT(maxAbsDifference(oriented.rig.nodes[oriented.index(skin(i))].worldMatrix, upright.rig.nodes[upright.index(skin(i))].worldMatrix),
                  1e-12)
            << "the skin keeps its rest place";
}

TEST(TorsoRig, TheOptionsBuildIncrementallyAsInFull)
{
    model::GuideDocument guide = withSpineOptions({{"pivots", Value(std::string("centered"))}, {"stretch_mode", Value(std::string("scale"))},
                                                   {"skin_joints", Value(6LL)}, {"bones_length", Value(std::string("parametric"))},
                                                   {"orient_pelvis", Value(true)}, {"orient_shoulders", Value(true)}});
    rigging::BuildCache cache;
    test::buildAndCompare(guide, cache, "first");
    guide.instance(guide.instanceNamed("spine")->id)->options["pivots"] = Value(std::string("spine1"));
    test::buildAndCompare(guide, cache, "spine1");
    guide.instance(guide.instanceNamed("spine")->id)->options["pivots"] = Value(std::string("legacy"));
    test::buildAndCompare(guide, cache, "legacy");
}

} // namespace
} // namespace rs
