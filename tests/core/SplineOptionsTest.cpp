// rig.spline's Mikan options as an animator checks them on the built and
// evaluated tail: bones (skin joints along the curve whatever the guide
// count) and bone_length, uniform_ik (controllers by guide joint), fk_easing
// (an end tweaker carries its neighbouring curve point), tweakers as an enum
// that still loads on/off, Mikan's option names (iks, default_stretch), an
// exact mirror and an incremental build equal to the full one.
#include "EvalTestSupport.h"
#include "SplineTestSupport.h"
#include "core/IncrementalCheck.h"
#include "core/TestSupport.h"
#include "eval/SplineCurve.h"
#include "rigging/RigBuilder.h"
#include "session/Session.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace rs {
namespace {

using Options = std::map<std::string, Value>;
using test::PosedRig;

using test::curledTail;

std::string at(const std::string& tag) { return "tail::" + tag; }

std::vector<Vec3> restPositions(const model::Rig& rig, const std::string& prefix, int count)
{
    std::vector<Vec3> out;
    for (int i = 0; i < count; ++i)
        out.push_back(translationOf(test::node(rig, at(prefix + std::to_string(i))).worldMatrix));
    return out;
}

// Arc length along the rest curve through the spline controllers (a dense
// polyline on it) of each point, which must lie on the curve.
std::vector<double> arcPositions(const model::Rig& rig, int controls, const std::vector<Vec3>& points)
{
    std::vector<eval::Affine> targets;
    for (int c = 0; c < controls; ++c)
        targets.push_back(eval::Affine::fromMatrix(test::node(rig, at("ctrls.spline." + std::to_string(c))).worldMatrix));
    const std::vector<Vec3> dense = eval::restCurvePoints(targets, 40001, false);
    std::vector<double> arc(dense.size(), 0.0);
    for (std::size_t i = 1; i < dense.size(); ++i)
        arc[i] = arc[i - 1] + glm::length(dense[i] - dense[i - 1]);
    std::vector<double> out;
    for (const Vec3& p : points) {
        std::size_t best = 0;
        for (std::size_t i = 1; i < dense.size(); ++i)
            if (glm::length(dense[i] - p) < glm::length(dense[best] - p))
                best = i;
        EXPECT_LT(glm::length(dense[best] - p), 2e-5) << "a bone sits on the curve";
        out.push_back(arc[best]);
    }
    return out;
}

double spacingSpread(const std::vector<double>& arc)
{
    double low = 1e9, high = 0.0;
    for (std::size_t i = 1; i < arc.size(); ++i)
        low = std::min(low, arc[i] - arc[i - 1]), high = std::max(high, arc[i] - arc[i - 1]);
    return high - low;
}

TEST(Evaluator, TailSplineBonesPutSevenSkinJointsAtEqualLengthsAlongTheCurve)
{
    const Options options{{"bones", Value(7LL)}, {"bone_length", Value(std::string("equal"))}, {"uniform_ik", Value(true)}};
    PosedRig r(curledTail(options, 5));
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.rig.diagnostics.empty()) << formatAll(r.rig.diagnostics);
    EXPECT_EQ(r.rig.skinJointCount(), 7u) << "seven skin joints on a chain of five guide joints";
    const std::vector<double> equal = arcPositions(r.rig, 4, restPositions(r.rig, "skin.", 7));
    EXPECT_LT(spacingSpread(equal), 1e-4) << "equal lengths along the curve";
    // parametric spreads them by the curve's parameter: not equal on this tail (the test can fail).
    Options parametric = options;
    parametric["bone_length"] = Value(std::string("parametric"));
    const model::Rig byParameter = rigging::buildRig(curledTail(parametric, 5), test::builtinTemplates());
    EXPECT_GT(spacingSpread(arcPositions(byParameter, 4, restPositions(byParameter, "skin.", 7))), 1e-3);
    // cvs: spread by guide joint along the guides, as their spacing goes.
    Options cvs = options;
    cvs["bone_length"] = Value(std::string("cvs"));
    cvs["bones"] = Value(9LL);
    const model::Rig byGuide = rigging::buildRig(curledTail(cvs, 5), test::builtinTemplates());
    const model::GuideDocument guide = curledTail(cvs, 5);
    const auto& joints = guide.instances().front().joints;
    for (int g = 0; g < 5; ++g) // bone 2g sits on guide joint g
        EXPECT_LT(glm::length(translationOf(test::node(byGuide, at("skin." + std::to_string(2 * g))).worldMatrix) -
                              translationOf(guide.jointWorldMatrix(joints[std::size_t(g)].id))), 1e-12);

    // Posed: the bones ride on the curve, the last at the last controller.
    eval::Pose pose = r.defaults();
    pose[r.channel(at("ctrls.spline.0"), "stretch")] = 1.0;
    pose = r.moveTo(pose, at("ctrls.spline.3"), r.restPosition(at("ctrls.spline.3")) + Vec3(0.0, 0.3, 0.1), at("ctrls.spline.3"));
    r.evaluate(pose);
    EXPECT_LT(glm::length(r.position(at("skin.6")) - r.position(at("ctrls.spline.3"))), 1e-9);
    EXPECT_LT(glm::length(r.position(at("skin.0")) - r.restPosition(at("skin.0"))), 1e-9) << "the base stays";
    // Each guide joint hooks on the nearest bone: the tip guide on the last.
    EXPECT_FALSE(r.rig.findPath(at("skin.7")));
}

TEST(Evaluator, TailSplineUniformIkSpreadsTheControllersByGuideJointInsteadOfByLength)
{
    const model::GuideDocument guide = curledTail({{"uniform_ik", Value(true)}});
    const model::Rig byGuide = rigging::buildRig(guide, test::builtinTemplates());
    const auto& joints = guide.instances().front().joints;
    // Four controllers on seven guide joints: at guide joints 0, 2, 4 and 6.
    for (int c = 0; c < 4; ++c)
        EXPECT_LT(glm::length(translationOf(test::node(byGuide, at("ctrls.spline." + std::to_string(c))).worldMatrix) -
                              translationOf(guide.jointWorldMatrix(joints[std::size_t(2 * c)].id))), 1e-12) << c;
    // Off (the default): at equal lengths along the guides, so not at guide joint 2.
    const model::Rig byLength = rigging::buildRig(curledTail({}), test::builtinTemplates());
    const std::vector<Vec3> controls = restPositions(byLength, "ctrls.spline.", 4);
    const double first = glm::length(controls[1] - controls[0]), last = glm::length(controls[3] - controls[2]);
    EXPECT_NEAR(first, last, 0.02) << "about equal lengths on a gentle curl";
    EXPECT_GT(glm::length(controls[1] - translationOf(guide.jointWorldMatrix(joints[2].id))), 0.02);
}

TEST(Evaluator, TailSplineFkEasingInMovesTheSecondCurvePointWithTheFirstTweaker)
{
    auto moveFirstTweaker = [](const Options& options) {
        PosedRig r(curledTail(options));
        EXPECT_TRUE(r.ok());
        const Vec3 second = r.restPosition(at("ctrls.tweak.1")), first = r.restPosition(at("ctrls.tweak.0"));
        eval::Pose pose = r.defaults();
        pose[r.channel(at("ctrls.tweak.0"), "rz")] = 40.0;
        pose[r.channel(at("ctrls.tweak.0"), "ty")] = 0.05;
        r.evaluate(pose);
        const Vec3 last = r.position(at("ctrls.tweak.6")) - r.restPosition(at("ctrls.tweak.6"));
        // What the second tweaker did: moved, and kept its distance from the first (a rigid swing).
        return std::tuple(glm::length(r.position(at("ctrls.tweak.1")) - second),
                          glm::length(r.position(at("ctrls.tweak.1")) - r.position(at("ctrls.tweak.0"))) - glm::length(second - first),
                          glm::length(last));
    };
    const Value unchained(std::string("unchained"));
    const auto [easedMove, easedStretch, easedTip] = moveFirstTweaker({{"tweakers", unchained}, {"fk_easing", Value(std::string("in"))}});
    EXPECT_GT(easedMove, 0.05) << "the first tweaker carries the second curve point";
    EXPECT_LT(std::abs(easedStretch), 1e-9) << "rigidly, as an FK parent";
    EXPECT_LT(easedTip, 1e-12) << "the other end stays with in only";
    const auto [plainMove, plainStretch, plainTip] = moveFirstTweaker({{"tweakers", unchained}});
    EXPECT_LT(plainMove, 1e-12) << "without easing each tweaker moves its own point";
    // out: the last tweaker carries the second to last point.
    PosedRig out(curledTail({{"tweakers", unchained}, {"fk_easing", Value(std::string("out"))}}));
    eval::Pose pose = out.defaults();
    pose[out.channel(at("ctrls.tweak.6"), "tx")] = 0.1;
    out.evaluate(pose);
    EXPECT_GT(glm::length(out.position(at("ctrls.tweak.5")) - out.restPosition(at("ctrls.tweak.5"))), 0.09);
    EXPECT_LT(glm::length(out.position(at("ctrls.tweak.1")) - out.restPosition(at("ctrls.tweak.1"))), 1e-12);
    // Rest unchanged whatever the easing.
    const auto rest = out.evaluate(out.defaults()).world;
    for (model::RigNodeIndex i = 0; i < out.rig.nodes.size(); ++i)
        EXPECT_LT(maxAbsDifference(rest[i].matrix(), out.rig.nodes[i].worldMatrix), 1e-9) << out.rig.nodes[i].path;
}

TEST(Evaluator, TailSplineLoadsMikansNamesAndOnOffTweakers)
{
    // iks and default_stretch are Mikan's names for controls and stretch.
    PosedRig r(curledTail({{"iks", Value(5LL)}, {"default_stretch", Value(true)}, {"tweakers", Value(true)}}));
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.rig.diagnostics.empty()) << formatAll(r.rig.diagnostics);
    EXPECT_TRUE(r.rig.findPath(at("ctrls.spline.4"))) << "five controllers";
    EXPECT_EQ(r.defaults()[std::size_t(r.channel(at("ctrls.spline.0"), "stretch"))], 1.0);
    EXPECT_TRUE(r.rig.findPath(at("ctrls.tweak.6"))) << "tweakers: on loads as unchained";
    // Both names: ours wins, with a warning.
    const model::Rig both = rigging::buildRig(curledTail({{"iks", Value(5LL)}, {"controls", Value(3LL)}}), test::builtinTemplates());
    EXPECT_FALSE(both.findPath(at("ctrls.spline.3")));
    EXPECT_NE(formatAll(both.diagnostics).find("same option"), std::string::npos) << formatAll(both.diagnostics);
    // chained builds as it says, without a warning (SplineTweakTest.cpp checks what it does).
    const model::Rig chained = rigging::buildRig(curledTail({{"tweakers", Value(std::string("chained"))}}), test::builtinTemplates());
    EXPECT_TRUE(chained.findPath(at("ctrls.tweak.3")));
    EXPECT_TRUE(chained.diagnostics.empty()) << formatAll(chained.diagnostics);
    // A single bone is refused naming the option.
    const model::Rig one = rigging::buildRig(curledTail({{"bones", Value(1LL)}}), test::builtinTemplates());
    EXPECT_TRUE(hasErrors(one.diagnostics));
    EXPECT_NE(formatAll(one.diagnostics).find("(option 'bones')"), std::string::npos) << formatAll(one.diagnostics);
}

// The editor opens a guide that uses Mikan's name as the option itself, so
// the Options dock shows and edits `controls`, not a default beside `iks`.
TEST(Evaluator, TailSplineOpenedInTheEditorShowsMikansNameAsTheOption)
{
    session::Session s(std::make_shared<templates::TemplateRegistry>(test::builtinTemplates()));
    s.replaceDocument(curledTail({{"iks", Value(5LL)}, {"controls", Value(3LL)}}, 7));
    const model::TemplateInstance& both = s.document().instances().front();
    EXPECT_EQ(both.options.at("controls"), Value(3LL)) << "both given: ours stays";
    s.replaceDocument(curledTail({{"iks", Value(5LL)}}));
    const model::TemplateInstance& tail = s.document().instances().front();
    EXPECT_EQ(tail.options.count("iks"), 0u);
    EXPECT_EQ(tail.options.at("controls"), Value(5LL));
    s.build();
    EXPECT_TRUE(s.rig()->findPath(at("ctrls.spline.4")));
    EXPECT_FALSE(s.rig()->findPath(at("ctrls.spline.5")));
}

// Guides dragged onto each other leave no curve to spread the bones on: the
// build warns, spreads them by guide joint and makes a rig that evaluates
// (review finding: it indexed an empty curve).
TEST(Evaluator, TailSplineBonesOnCoincidentGuidesWarnAndBuild)
{
    for (const char* mode : {"equal", "parametric", "cvs"}) {
        model::GuideDocument onTop = curledTail({{"tweakers", Value(std::string("unchained"))}, {"bones", Value(4LL)},
                                                 {"bone_length", Value(std::string(mode))}});
        model::TemplateInstance& tail = *onTop.instance(onTop.instances().front().id);
        tail.joints[1].local.translate = Vec3(0.0); // the second guide dragged onto the first
        const model::Rig rig = rigging::buildRig(onTop, test::builtinTemplates());
        EXPECT_FALSE(hasErrors(rig.diagnostics)) << mode << ": " << formatAll(rig.diagnostics);
        EXPECT_TRUE(rig.findPath(at("skin.3"))) << mode << ": four bones";
        if (std::string(mode) != "cvs")
            EXPECT_NE(formatAll(rig.diagnostics).find("two points at one place"), std::string::npos)
                << mode << ": " << formatAll(rig.diagnostics);
        // Every guide at one place: no curve, no crash.
        model::GuideDocument point = onTop;
        for (std::size_t j = 1; j < point.instance(tail.id)->joints.size(); ++j)
            point.instance(tail.id)->joints[j].local.translate = Vec3(0.0);
        const model::Rig collapsed = rigging::buildRig(point, test::builtinTemplates());
        EXPECT_TRUE(collapsed.findPath(at("skin.0"))) << mode << ": " << formatAll(collapsed.diagnostics);
        PosedRig posed(onTop);
        ASSERT_TRUE(posed.ok()) << mode;
        posed.evaluate(posed.defaults());
    }
}

TEST(ChainOrient, SplineOptionsMirrorExactlyOnABranch)
{
    Options options{{"bones", Value(9LL)},
                    {"bone_length", Value(std::string("equal"))},
                    {"uniform_ik", Value(true)},
                    {"tweakers", Value(std::string("unchained"))},
                    {"fk_easing", Value(std::string("in-out"))},
                    {"fk", Value(true)},
                    {"branches", Value(std::string("[L, R]"))}};
    const model::Rig rig = rigging::buildRig(curledTail(options), test::builtinTemplates());
    EXPECT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    Mat4 mirror(1.0);
    mirror[0][0] = -1.0;
    std::size_t pairs = 0;
    for (const model::RigNode& right : rig.nodes) {
        const auto side = right.path.find(".R::");
        if (side == std::string::npos)
            continue;
        const model::RigNode& left = test::node(rig, std::string(right.path).replace(side, 4, ".L::"));
        EXPECT_LT(maxAbsDifference(right.worldMatrix, mirror * left.worldMatrix * mirror), 1e-12) << right.path;
        ++pairs;
    }
    EXPECT_GT(pairs, 40u);
}

TEST(Evaluator, TailSplineOptionsRebuildIncrementallyAsAFullBuild)
{
    model::GuideDocument guide = curledTail({});
    const model::InstanceId tail = guide.instances().front().id;
    rigging::BuildCache cache;
    test::buildAndCompare(guide, cache, "first build");
    const std::pair<const char*, Value> edits[] = {
        {"bones", Value(6LL)},          {"bone_length", Value(std::string("equal"))}, {"uniform_ik", Value(true)},
        {"tweakers", Value(true)},      {"fk_easing", Value(std::string("in-out"))},  {"iks", Value(3LL)},
        {"default_stretch", Value(true)}, {"bone_length", Value(std::string("parametric"))}};
    for (const auto& [option, value] : edits) {
        guide.instance(tail)->options[option] = value;
        test::buildAndCompare(guide, cache, option);
    }
    guide.instance(tail)->joints[3].local.translate.y += 0.05;
    test::buildAndCompare(guide, cache, "a guide joint moved");
}

} // namespace
} // namespace rs
