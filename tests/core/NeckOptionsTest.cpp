// neck.head's options as an animator checks them on the built and evaluated
// biped (issue 22): skin bones spread along the neck by length or by
// parameter, stretch by translation or by scale, the neck's rigidity at the
// chest and the head, the head's space switch and the neck controls' axes.
#include "EvalTestSupport.h"
#include "IncrementalCheck.h"
#include "io/GuideFile.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

model::GuideDocument withNeckOptions(const std::map<std::string, Value>& options)
{
    model::GuideDocument guide = test::loadSample("biped");
    for (const auto& [name, value] : options)
        guide.instance(guide.instanceNamed("neck")->id)->options[name] = value;
    return guide;
}

std::string skin(std::size_t k) { return "neck::skin." + std::to_string(k); }

// The neck's guide points from its base to the head (where the driven joints sit at rest).
std::vector<Vec3> neckGuides(const PosedRig& r) { return {r.restPosition("neck::drv.0"), r.restPosition("neck::drv.1"), r.restPosition("neck::drv.2")}; }

double turnDegrees(const Mat3& from, const Mat3& to)
{
    const Mat3 relative = glm::transpose(from) * to;
    return glm::degrees(std::acos(std::clamp((relative[0][0] + relative[1][1] + relative[2][2] - 1.0) / 2.0, -1.0, 1.0)));
}

Mat3 worldRotation(const PosedRig& r, const std::string& id) { return r.state().world[r.index(id)].rotation(); }

bool hasAttribute(const PosedRig& r, const std::string& id, const std::string& name)
{
    const auto& attributes = r.rig.nodes[r.index(id)].attributes;
    return std::any_of(attributes.begin(), attributes.end(), [&](const model::RigAttribute& a) { return a.name == name; });
}

TEST(NeckRig, FiveBonesSpreadEquallyByLengthOrByGuideSegment)
{
    for (const std::string mode : {"equal", "parametric"}) {
        PosedRig r(withNeckOptions({{"bones", Value(5LL)}, {"bones_length", Value(mode)}}));
        ASSERT_TRUE(r.ok()) << mode;
        const auto g = neckGuides(r);
        const double first = glm::length(g[1] - g[0]), second = glm::length(g[2] - g[1]);
        ASSERT_GT(second, 1.5 * first) << "the biped's neck guides are unevenly spaced";
        EXPECT_FALSE(r.rig.findPath(skin(5))) << "five bones and the head";
        EXPECT_TRUE(r.rig.findPath("neck::skin.head"));
        for (std::size_t k = 0; k < 5; ++k) {
            Vec3 expected;
            if (mode == "equal") { // k fifths of the neck's length from its base
                const double at = (first + second) * double(k) / 5.0;
                expected = at <= first ? glm::mix(g[0], g[1], at / first) : glm::mix(g[1], g[2], (at - first) / second);
            } else { // k fifths of the two guide segments
                const double u = 2.0 * double(k) / 5.0;
                expected = u <= 1.0 ? glm::mix(g[0], g[1], u) : glm::mix(g[1], g[2], u - 1.0);
            }
            EXPECT_LT(glm::length(r.restPosition(skin(k)) - expected), 1e-9) << mode << " bone " << k;
        }
        // The bones ride on the spline: the head pushed forward bends them smoothly.
        const Vec3 head = r.restPosition("neck::ctrls.head");
        r.evaluate(r.moveTo(r.defaults(), "neck::ctrls.head", head + Vec3(0.0, 0.0, 0.04), "neck::ctrls.head"));
        double previous = -1.0;
        for (std::size_t k = 0; k < 5; ++k) {
            const double forward = r.position(skin(k)).z - r.restPosition(skin(k)).z;
            EXPECT_GT(forward, previous) << mode << " bone " << k;
            previous = forward;
        }
        EXPECT_NEAR(r.position(skin(0)).z - r.restPosition(skin(0)).z, 0.0, 1e-9) << "the base stays on the chest";
    }
}

// The head pulled 20 cm away along the neck.
Pose headPulledAway(PosedRig& r)
{
    const Vec3 base = r.restPosition("neck::drv.0"), head = r.restPosition("neck::ctrls.head");
    return r.moveTo(r.defaults(), "neck::ctrls.head", head + 0.2 * glm::normalize(head - base), "neck::ctrls.head");
}

TEST(NeckRig, TranslateStretchKeepsEveryJointsScaleAndScaleStretchGrowsThemWithTheirSpacing)
{
    PosedRig translate(withNeckOptions({{"bones", Value(5LL)}}));
    ASSERT_TRUE(translate.ok());
    const Vec3 base = translate.restPosition("neck::drv.0"), head = translate.restPosition("neck::ctrls.head");
    const Vec3 along = glm::normalize(head - base);
    const double ratio = (glm::length(head - base) + 0.2) / glm::length(head - base);
    translate.evaluate(headPulledAway(translate));
    for (std::size_t k = 0; k < 5; ++k) {
        const eval::Affine& w = translate.state().world[translate.index(skin(k))];
        EXPECT_LT(glm::length(w.scale() - Vec3(1.0)), 1e-9) << "translate: bone " << k;
    }
    const double spread = glm::dot(translate.position(skin(4)) - translate.position(skin(0)), along);
    EXPECT_NEAR(spread / glm::dot(translate.restPosition(skin(4)) - translate.restPosition(skin(0)), along), ratio, 1e-3)
        << "the bones move apart as the neck stretches";

    PosedRig scale(withNeckOptions({{"bones", Value(5LL)}, {"stretch_mode", Value(std::string("scale"))}}));
    ASSERT_TRUE(scale.ok());
    scale.evaluate(headPulledAway(scale));
    for (std::size_t k = 0; k < 5; ++k) {
        EXPECT_LT(glm::length(scale.position(skin(k)) - translate.position(skin(k))), 1e-9) << "the same places: bone " << k;
        const eval::Affine& w = scale.state().world[scale.index(skin(k))];
        EXPECT_NEAR(w.scale().x, ratio, 1e-3) << "scale: bone " << k << " grows along the neck with its spacing";
        EXPECT_NEAR(w.scale().y, 1.0, 1e-9);
        EXPECT_NEAR(w.scale().z, 1.0, 1e-9);
    }
    EXPECT_NEAR(scale.state().world[scale.index("neck::skin.head")].scale().x, 1.0, 1e-9) << "the head keeps its size";
}

TEST(NeckRig, DefaultStretchOffKeepsTheNecksLengthUntilTheAnimatorTurnsItOn)
{
    PosedRig r(withNeckOptions({{"default_stretch", Value(false)}}));
    ASSERT_TRUE(r.ok());
    const int stretch = r.channel("neck::ctrls.head", "stretch");
    EXPECT_EQ(r.defaults()[stretch], 0.0);
    const double rest = glm::length(r.restPosition("neck::drv.2") - r.restPosition("neck::drv.0"));
    Pose pose = headPulledAway(r);
    r.evaluate(pose);
    EXPECT_NEAR(glm::length(r.position("neck::drv.2") - r.position("neck::drv.0")), rest, 1e-4) << "the neck keeps its length";
    pose[stretch] = 1.0;
    r.evaluate(pose);
    EXPECT_NEAR(glm::length(r.position("neck::drv.2") - r.position("neck::drv.0")), rest + 0.2, 1e-4) << "and reaches the head";
}

// The head bent 60 degrees forward about the neck's base, turned with it.
Pose headBent(PosedRig& r, double degrees)
{
    Pose pose = r.defaults();
    const Mat3 rest = worldRotation(r, "neck::ctrls.head");
    pose[r.channel("neck::ctrls.head", "rx")] = degrees; // nods (head_orient world: about the side axis, X)
    r.evaluate(pose);
    const Mat3 turn = worldRotation(r, "neck::ctrls.head") * glm::transpose(rest);
    const Vec3 base = r.restPosition("neck::drv.0"), head = r.restPosition("neck::ctrls.head");
    return r.moveTo(pose, "neck::ctrls.head", base + turn * (head - base), "neck::ctrls.head");
}

TEST(NeckRig, RigidityAtTheBaseKeepsTheFirstNeckJointAlongTheChestWhenTheHeadBends)
{
    const auto firstJointTurn = [](const std::map<std::string, Value>& options) {
        PosedRig r(withNeckOptions(options));
        EXPECT_TRUE(r.ok());
        r.evaluate(r.defaults());
        const Mat3 rest = worldRotation(r, skin(0));
        r.evaluate(headBent(r, 60.0));
        return turnDegrees(rest, worldRotation(r, skin(0)));
    };
    const Value on(true);
    EXPECT_LT(firstJointTurn({{"rigidity", on}, {"rigidity_dn", Value(1.0)}}), 1e-6) << "rigid: along the chest";
    EXPECT_LT(firstJointTurn({}), 1e-6) << "without the rigidity attributes: as rigid (today's neck)";
    EXPECT_GT(firstJointTurn({{"rigidity", on}, {"rigidity_dn", Value(0.0)}}), 10.0) << "free: it aims at the head";
    const double half = firstJointTurn({{"rigidity", on}, {"rigidity_dn", Value(0.5)}});
    EXPECT_GT(half, 1.0);
    EXPECT_LT(half, firstJointTurn({{"rigidity", on}, {"rigidity_dn", Value(0.0)}}));
}

TEST(NeckRig, RigidityAtTheHeadBendsTheNeckUpToTheHeadOrNot)
{
    PosedRig r(withNeckOptions({{"rigidity", Value(true)}}));
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.defaults()[r.channel("neck::ctrls.head", "rigidity_dn")], 1.0);
    const int up = r.channel("neck::ctrls.head", "rigidity_up");
    EXPECT_EQ(r.defaults()[up], 0.0) << "Mikan's default: free at the head";
    // The head only nods: a free end ignores it, a rigid one bends the neck to it.
    Pose pose = r.defaults();
    pose[r.channel("neck::ctrls.head", "rx")] = 40.0;
    r.evaluate(pose);
    EXPECT_LT(glm::length(r.position(skin(1)) - r.restPosition(skin(1))), 1e-9);
    pose[up] = 1.0;
    r.evaluate(pose);
    EXPECT_GT(glm::length(r.position(skin(1)) - r.restPosition(skin(1))), 1e-3);
}

TEST(NeckRig, WithoutSpaceSwitchTheHeadRidesOnTheNeck)
{
    PosedRig r(withNeckOptions({{"space_switch", Value(false)}}));
    ASSERT_TRUE(r.ok());
    EXPECT_FALSE(hasAttribute(r, "neck::ctrls.head", "space"));
    EXPECT_FALSE(hasAttribute(r, "neck::ctrls.head", "point_space"));
    PosedRig switched("biped");
    EXPECT_TRUE(hasAttribute(switched, "neck::ctrls.head", "space"));
    r.evaluate(r.defaults());
    const Mat3 rest = worldRotation(r, "neck::skin.head");
    Pose pose = r.defaults();
    pose[r.channel("neck::ctrls.fk.0", "rz")] = 25.0;
    r.evaluate(pose);
    EXPECT_NEAR(turnDegrees(rest, worldRotation(r, "neck::skin.head")), 25.0, 0.5);
}

TEST(NeckRig, OrientNeckOffTurnsTheNeckControlsAboutTheWorldAxes)
{
    PosedRig oriented("biped");
    PosedRig world(withNeckOptions({{"orient_neck", Value(false)}}));
    ASSERT_TRUE(oriented.ok() && world.ok());
    const auto g = neckGuides(oriented);
    EXPECT_GT(glm::dot(Vec3(oriented.rig.nodes[oriented.index("neck::ctrls.fk.0")].worldMatrix[0]), glm::normalize(g[1] - g[0])), 0.999);
    EXPECT_LT(maxAbsDifference(Mat4(Mat3(world.rig.nodes[world.index("neck::ctrls.fk.0")].worldMatrix)), Mat4(1.0)), 1e-12);
    for (const std::string id : {"neck::skin.0", "neck::skin.1", "neck::skin.head"})
        EXPECT_LT(maxAbsDifference(world.rig.nodes[world.index(id)].worldMatrix, oriented.rig.nodes[oriented.index(id)].worldMatrix), 1e-12)
            << id << " keeps its rest place";
}

TEST(NeckRig, AimAndUpAxesRenameTheNeckControlsAxesAndTurnTheNeckAlike)
{
    // Mikan's neck axes: Y along the neck, X across it. The controllers' axes
    // change; the joints stay, and turning about the new aim axis (ry) twists
    // the neck as turning about the old one (rx) did.
    PosedRig xAim("biped");
    PosedRig yAim(withNeckOptions({{"aim_axis", Value(std::string("y"))}, {"up_axis", Value(std::string("x"))}}));
    ASSERT_TRUE(xAim.ok() && yAim.ok()) << formatAll(yAim.rig.diagnostics);
    const auto g = neckGuides(yAim);
    const Mat4 oldFrame = xAim.rig.nodes[xAim.index("neck::ctrls.fk.0")].worldMatrix;
    const Mat4 newFrame = yAim.rig.nodes[yAim.index("neck::ctrls.fk.0")].worldMatrix;
    EXPECT_GT(glm::dot(glm::normalize(Vec3(newFrame[1])), glm::normalize(g[1] - g[0])), 0.999) << "Y along the neck";
    EXPECT_LT(glm::length(Vec3(newFrame[0]) - Vec3(oldFrame[1])), 1e-12) << "X where Y was";
    EXPECT_LT(glm::length(Vec3(newFrame[2]) + Vec3(oldFrame[2])), 1e-12) << "a right-handed frame: Z turned over";
    EXPECT_LT(glm::length(Vec3(newFrame[3]) - Vec3(oldFrame[3])), 1e-12);
    for (const std::string id : {"neck::skin.0", "neck::skin.1", "neck::skin.head"})
        EXPECT_LT(maxAbsDifference(yAim.rig.nodes[yAim.index(id)].worldMatrix, xAim.rig.nodes[xAim.index(id)].worldMatrix), 1e-12)
            << id << " keeps its rest place";

    Pose twistOld = xAim.defaults(), twistNew = yAim.defaults();
    twistOld[xAim.channel("neck::ctrls.fk.0", "rx")] = 25.0;
    twistNew[yAim.channel("neck::ctrls.fk.0", "ry")] = 25.0;
    xAim.evaluate(twistOld);
    yAim.evaluate(twistNew);
    for (const std::string id : {"neck::skin.0", "neck::skin.1", "neck::skin.head"}) {
        EXPECT_LT(turnDegrees(worldRotation(xAim, id), worldRotation(yAim, id)), 1e-6) << id;
        EXPECT_LT(glm::length(xAim.state().world[xAim.index(id)].translation - yAim.state().world[yAim.index(id)].translation), 1e-9) << id;
    }
    EXPECT_GT(turnDegrees(worldRotation(xAim, "neck::skin.head"), xAim.rig.nodes[xAim.index("neck::skin.head")].worldMatrix), 5.0)
        << "the twist moved the head";

    // An up axis along the aim axis is an error naming it.
    const model::Rig bad = rigging::buildRig(withNeckOptions({{"aim_axis", Value(std::string("y"))}, {"up_axis", Value(std::string("-y"))}}),
                                             test::builtinTemplates());
    EXPECT_NE(formatAll(bad.diagnostics).find("up_axis -y lies along aim_axis y"), std::string::npos) << formatAll(bad.diagnostics);
}

TEST(NeckRig, TheOptionsBuildIncrementallyAsInFullAndMirrorOnBranches)
{
    model::GuideDocument guide = withNeckOptions({{"bones", Value(4LL)}, {"bones_length", Value(std::string("parametric"))},
                                                  {"stretch_mode", Value(std::string("scale"))}, {"rigidity", Value(true)},
                                                  {"orient_neck", Value(false)}, {"branches", Value(std::string("[L, R]"))}});
    guide.instance(guide.instanceNamed("neck")->id)->joints[0].local.translate.x = 0.12; // two necks, off the middle
    rigging::BuildCache cache;
    test::buildAndCompare(guide, cache, "first");
    guide.instance(guide.instanceNamed("neck")->id)->options["bones"] = Value(6LL);
    test::buildAndCompare(guide, cache, "more bones");

    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    ASSERT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    Mat4 mirror(1.0);
    mirror[0][0] = -1.0;
    std::size_t pairs = 0;
    for (const model::RigNode& right : rig.nodes) {
        const auto at = right.path.find("neck.R::");
        if (at == std::string::npos)
            continue;
        const model::RigNode& left = test::node(rig, std::string(right.path).replace(at, 8, "neck.L::"));
        EXPECT_LT(maxAbsDifference(right.worldMatrix, mirror * left.worldMatrix * mirror), 1e-9) << right.path;
        ++pairs;
    }
    EXPECT_GT(pairs, 12u);
}

TEST(NeckRig, ABadOptionValueIsReportedAndTheDefaultOrTheLimitUsed)
{
    const std::string guide = "rigsmith_guide: 3\nname: g\ninstances:\n  - id: 1\n    template: neck.head\n    name: neck\n"
                              "    options:\n      bones: 40\n      stretch_mode: stretchy\n    joints:\n"
                              "      - {id: 1, t: [0, 1.5, 0]}\n      - {id: 2, parent: 1, t: [0, 0.1, 0]}\n"
                              "      - {id: 3, parent: 2, t: [0, 0.1, 0]}\n";
    auto read = io::readGuideText(guide, "neck.yml");
    ASSERT_TRUE(read.ok()) << formatAll(read.diagnostics());
    const model::Rig rig = rigging::buildRig(read.take(), test::builtinTemplates());
    const std::string said = formatAll(rig.diagnostics);
    EXPECT_NE(said.find("option 'bones' = 40 is out of range, using 16"), std::string::npos) << said;
    EXPECT_NE(said.find("option 'stretch_mode' = 'stretchy' is not one of its labels, using the default"), std::string::npos) << said;
    EXPECT_TRUE(rig.findPath("neck::skin.15"));
    EXPECT_FALSE(rig.findPath("neck::skin.16"));

    // Bones without the spline: said, and one skin joint per neck guide.
    const model::Rig fk = rigging::buildRig(withNeckOptions({{"bones", Value(5LL)}, {"spline", Value(false)}}), test::builtinTemplates());
    EXPECT_NE(formatAll(fk.diagnostics).find("bones needs spline"), std::string::npos) << formatAll(fk.diagnostics);
    EXPECT_TRUE(fk.findPath("neck::skin.1"));
    EXPECT_FALSE(fk.findPath("neck::skin.2"));
}

} // namespace
} // namespace rs
