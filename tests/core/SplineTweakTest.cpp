// rig.spline's chained tweakers (Mikan's tweakers in a hierarchy) as an
// animator checks them on the built and evaluated tail: each tweaker carries
// the tweakers after it as an FK chain does, while every tweaker still rides
// on the spline controllers around it; at zero (or with only the last one
// moved) the curve is the unchained one; fk_easing, a mirrored branch, an
// incremental build, pickwalk.
#include "EvalTestSupport.h"
#include "SplineTestSupport.h"
#include "core/IncrementalCheck.h"
#include "eval/Pickwalk.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace rs {
namespace {

using Options = std::map<std::string, Value>;
using test::curledTail;
using test::PosedRig;

constexpr int kTweakers = 7; // curledTail's guide joints

std::string at(const std::string& tag) { return "tail::" + tag; }
std::string tweak(int i) { return at("ctrls.tweak." + std::to_string(i)); }

Options tail(const std::string& tweakers, const std::string& easing = "off")
{
    return {{"tweakers", Value(tweakers)}, {"fk_easing", Value(easing)}};
}

// The spline controllers bent and stretched, as an animator poses the tail
// before touching the tweakers.
eval::Pose bentControls(const PosedRig& r)
{
    eval::Pose pose = r.defaults();
    pose[r.channel(at("ctrls.spline.0"), "stretch")] = 1.0;
    pose[r.channel(at("ctrls.spline.1"), "rx")] = 25.0;
    pose[r.channel(at("ctrls.spline.2"), "ty")] = 0.12;
    pose[r.channel(at("ctrls.spline.2"), "rz")] = -30.0;
    pose[r.channel(at("ctrls.spline.3"), "tx")] = 0.08;
    return pose;
}

// The worst distance between the same skin joints and tweakers of two evaluated tails.
double worstDifference(const PosedRig& a, const PosedRig& b)
{
    double worst = 0.0;
    for (const model::RigNode& node : a.rig.nodes)
        if (node.key.tag.rfind("skin.", 0) == 0 || node.key.tag.rfind("ctrls.tweak.", 0) == 0)
            worst = std::max(worst, maxAbsDifference(a.state().worldMatrix(a.index(node.path)), b.state().worldMatrix(b.index(node.path))));
    return worst;
}

TEST(SplineTweak, TurningATweakerTurnsTheTweakersAfterItRigidlyAboutIt)
{
    for (const char* easing : {"off", "in", "out", "in-out"}) {
        for (const bool chained : {true, false}) {
            PosedRig r(curledTail(tail(chained ? "chained" : "unchained", easing)));
            ASSERT_TRUE(r.ok()) << easing;
            EXPECT_TRUE(r.rig.diagnostics.empty()) << formatAll(r.rig.diagnostics);
            eval::Pose pose = r.defaults();
            pose[r.channel(tweak(2), "rz")] = 30.0;
            r.evaluate(pose);
            const Mat4 rest = r.rig.nodes[r.index(tweak(2))].worldMatrix;
            const Vec3 pivot = translationOf(rest);
            const Mat3 turn(glm::rotate(Mat4(1.0), glm::radians(30.0), glm::normalize(Vec3(rest[2]))));
            EXPECT_LT(glm::length(r.position(tweak(2)) - pivot), 1e-12) << "it turns in place";
            for (int k = 0; k < 2; ++k)
                EXPECT_LT(glm::length(r.position(tweak(k)) - r.restPosition(tweak(k))), 1e-12) << "the ones before stay: " << k;
            for (int k = 3; k < kTweakers; ++k) {
                const Vec3 restAt = r.restPosition(tweak(k));
                if (!chained) {
                    EXPECT_LT(glm::length(r.position(tweak(k)) - restAt), 1e-12) << easing << ": unchained, each its own: " << k;
                    continue;
                }
                EXPECT_LT(glm::length(r.position(tweak(k)) - (pivot + turn * (restAt - pivot))), 1e-6) << easing << ": " << k;
                const Mat3 turned = turn * Mat3(r.rig.nodes[r.index(tweak(k))].worldMatrix);
                EXPECT_LT(maxAbsDifference(Mat4(r.state().world[r.index(tweak(k))].linear), Mat4(turned)), 1e-6) << "turned alike: " << k;
            }
        }
    }
}

TEST(SplineTweak, TranslatingATweakerMovesEveryLaterTweakerByAsMuch)
{
    for (const bool chained : {true, false}) {
        PosedRig r(curledTail(tail(chained ? "chained" : "unchained")));
        ASSERT_TRUE(r.ok());
        eval::Pose pose = r.defaults();
        pose[r.channel(tweak(1), "tx")] = 0.05;
        pose[r.channel(at("ctrls.spline.0"), "stretch")] = 1.0; // the chain keeps its share of the curve
        r.evaluate(pose);
        const Vec3 moved = r.position(tweak(1)) - r.restPosition(tweak(1));
        EXPECT_NEAR(glm::length(moved), 0.05, 1e-12);
        EXPECT_LT(glm::length(r.position(tweak(0)) - r.restPosition(tweak(0))), 1e-12);
        for (int k = 2; k < kTweakers; ++k) {
            const Vec3 by = r.position(tweak(k)) - r.restPosition(tweak(k));
            if (chained)
                EXPECT_LT(glm::length(by - moved), 1e-6) << "5 cm as tweaker 1: " << k;
            else
                EXPECT_LT(glm::length(by), 1e-12) << "unchained moves none: " << k;
        }
        // The curve goes with them: the tip's skin joint moves 5 cm too (chained), or stays (unchained).
        const Vec3 tip = r.position(at("skin.6")) - r.restPosition(at("skin.6"));
        if (chained)
            EXPECT_LT(glm::length(tip - moved), 1e-6);
        else
            EXPECT_LT(glm::length(tip), 1e-9);
    }
}

// The tweakers at zero: the chained curve is the unchained one however the
// spline controllers are posed; only the last tweaker moved, too (it carries
// nothing). With each fk_easing.
TEST(SplineTweak, AtZeroOrWithTheLastTweakerMovedChainedIsUnchained)
{
    for (const char* easing : {"off", "in", "out", "in-out"}) {
        PosedRig chained(curledTail(tail("chained", easing))), unchained(curledTail(tail("unchained", easing)));
        ASSERT_TRUE(chained.ok() && unchained.ok()) << easing;
        // Rest: the built rest pose is the evaluation at defaults.
        const auto& rest = chained.evaluate(chained.defaults()).world;
        for (model::RigNodeIndex i = 0; i < chained.rig.nodes.size(); ++i)
            EXPECT_LT(maxAbsDifference(rest[i].matrix(), chained.rig.nodes[i].worldMatrix), 1e-9) << chained.rig.nodes[i].path;
        chained.evaluate(bentControls(chained));
        unchained.evaluate(bentControls(unchained));
        EXPECT_LT(worstDifference(chained, unchained), 1e-12) << easing << ": all tweakers at zero";
        auto moveLast = [](const PosedRig& r) {
            eval::Pose pose = bentControls(r);
            pose[r.channel(tweak(kTweakers - 1), "ty")] = 0.07;
            pose[r.channel(tweak(kTweakers - 1), "rz")] = 35.0;
            pose[r.channel(tweak(kTweakers - 1), "rx")] = -20.0;
            return pose;
        };
        chained.evaluate(moveLast(chained));
        unchained.evaluate(moveLast(unchained));
        EXPECT_LT(worstDifference(chained, unchained), 1e-9) << easing << ": the last tweaker moved";
        EXPECT_GT(glm::length(chained.position(at("skin.6")) - chained.restPosition(at("skin.6"))), 0.05) << "it did move";
    }
}

// fk_easing in: the second curve point rides on the first tweaker's place,
// so turning the first tweaker swings the whole chain from the base as one
// (the eased point carried once, not twice).
TEST(SplineTweak, EasedChainedTweakersCarryTheEasedPointOnce)
{
    PosedRig r(curledTail(tail("chained", "in")));
    ASSERT_TRUE(r.ok());
    eval::Pose pose = r.defaults();
    pose[r.channel(tweak(0), "rx")] = 40.0;
    r.evaluate(pose);
    const Mat4 rest = r.rig.nodes[r.index(tweak(0))].worldMatrix;
    const Vec3 pivot = translationOf(rest);
    const Mat3 turn(glm::rotate(Mat4(1.0), glm::radians(40.0), glm::normalize(Vec3(rest[0]))));
    for (int k = 1; k < kTweakers; ++k)
        EXPECT_LT(glm::length(r.position(tweak(k)) - (pivot + turn * (r.restPosition(tweak(k)) - pivot))), 1e-6) << k;
    // out: the last tweaker turned swings the point before it about the last tweaker, as unchained.
    PosedRig out(curledTail(tail("chained", "out")));
    eval::Pose outPose = out.defaults();
    outPose[out.channel(tweak(6), "rz")] = 40.0;
    out.evaluate(outPose);
    const Mat4 last = out.rig.nodes[out.index(tweak(6))].worldMatrix;
    const Mat3 swing(glm::rotate(Mat4(1.0), glm::radians(40.0), glm::normalize(Vec3(last[2]))));
    const Vec3 end = translationOf(last);
    EXPECT_LT(glm::length(out.position(tweak(5)) - (end + swing * (out.restPosition(tweak(5)) - end))), 1e-6);
    EXPECT_LT(glm::length(out.position(tweak(4)) - out.restPosition(tweak(4))), 1e-12);
    // A chain of three eased both ways: its middle point rides on both ends' places and takes both
    // end tweakers' offsets; it builds and evaluates (no loop), at rest where it was built.
    PosedRig three(curledTail(tail("chained", "in-out"), 3));
    ASSERT_TRUE(three.ok());
    EXPECT_TRUE(three.rig.diagnostics.empty()) << formatAll(three.rig.diagnostics);
    eval::Pose threePose = three.defaults();
    threePose[three.channel(tweak(2), "ty")] = 0.05;
    three.evaluate(threePose);
    EXPECT_NEAR(glm::length(three.position(tweak(1)) - three.restPosition(tweak(1))), 0.05, 1e-9) << "the last one's offset";
    threePose[three.channel(tweak(2), "ty")] = 0.0;
    const auto& threeRest = three.evaluate(threePose).world;
    for (model::RigNodeIndex i = 0; i < three.rig.nodes.size(); ++i)
        EXPECT_LT(maxAbsDifference(threeRest[i].matrix(), three.rig.nodes[i].worldMatrix), 1e-9) << three.rig.nodes[i].path;
}

TEST(SplineTweak, ChainedTweakersMirrorExactlyOnABranch)
{
    Mat4 mirror(1.0);
    mirror[0][0] = -1.0;
    for (const bool flip : {true, false}) {
        Options options = tail("chained", "in-out");
        options["branches"] = Value(std::string("[L, R]"));
        options["flip_orient"] = Value(flip);
        options["fk"] = Value(true);
        options["do_pose"] = Value(true);
        PosedRig r(curledTail(options));
        ASSERT_TRUE(r.ok());
        auto side = [](const std::string& tag, const char* s) { return std::string("tail.") + s + "::" + tag; };
        eval::Pose pose = r.defaults();
        std::vector<model::RigNodeIndex> left;
        for (const char* s : {"L", "R"}) {
            if (!flip && std::string(s) == "R")
                continue; // posed as the mirror image of L below
            pose[r.channel(side("ctrls.tweak.2", s), "rz")] = 30.0;
            pose[r.channel(side("ctrls.tweak.1", s), "tx")] = 0.05;
            pose[r.channel(side("ctrls.tweak.4", s), "ry")] = -15.0;
            pose[r.channel(side("ctrls.spline.1", s), "ty")] = 0.1;
            pose[r.channel(side("ctrls.spline.1", s), "rz")] = 20.0;
            pose[r.channel(side("ctrls.fk.3", s), "rx")] = 10.0;
        }
        if (!flip) {
            for (const model::RigNode& node : r.rig.nodes)
                if (node.path.find(".L::") != std::string::npos)
                    left.push_back(r.index(node.path));
            pose = r.posing->mirror(pose, left);
        }
        r.evaluate(pose);
        std::size_t pairs = 0;
        for (const model::RigNode& right : r.rig.nodes) {
            const auto at = right.path.find(".R::");
            if (at == std::string::npos)
                continue;
            const std::string leftPath = std::string(right.path).replace(at, 4, ".L::");
            const Mat4 l = r.state().worldMatrix(r.index(leftPath)), rr = r.state().worldMatrix(r.index(right.path));
            EXPECT_LT(glm::length(translationOf(rr) - Vec3(mirror * Vec4(translationOf(l), 1.0))), 1e-9) << right.path;
            if (right.kind == model::RigNodeKind::Joint)
                EXPECT_LT(maxAbsDifference(rr, mirror * l * mirror), 1e-9) << right.path;
            ++pairs;
        }
        EXPECT_GT(pairs, 60u);
        EXPECT_GT(glm::length(r.position(side("skin.6", "R")) - r.restPosition(side("skin.6", "R"))), 0.05) << "posed";
    }
}

TEST(SplineTweak, ChainedTweakersRebuildIncrementallyAsAFullBuild)
{
    model::GuideDocument guide = curledTail(tail("unchained"));
    const model::InstanceId id = guide.instances().front().id;
    rigging::BuildCache cache;
    test::buildAndCompare(guide, cache, "first build");
    const std::pair<const char*, Value> edits[] = {
        {"tweakers", Value(std::string("chained"))}, {"fk_easing", Value(std::string("in-out"))},
        {"branches", Value(std::string("[L, R]"))},  {"flip_orient", Value(true)},
        {"fk_easing", Value(std::string("out"))},    {"tweakers", Value(std::string("unchained"))}};
    for (const auto& [option, value] : edits) {
        guide.instance(id)->options[option] = value;
        test::buildAndCompare(guide, cache, option);
    }
    guide.instance(id)->options["tweakers"] = Value(std::string("chained"));
    guide.instance(id)->joints[3].local.translate.y += 0.05;
    test::buildAndCompare(guide, cache, "a guide joint moved");
}

// A carry that cannot be evaluated is refused when the rig compiles, naming
// the constraint: a carried node with no channels, pivots not one per node.
TEST(SplineTweak, ACarryOfANodeWithoutChannelsIsACompileError)
{
    model::Rig rig = rigging::buildRig(curledTail(tail("chained")), test::builtinTemplates());
    ASSERT_TRUE(eval::RigProgram::compile(rig).ok());
    model::RigConstraint* carry = nullptr;
    for (model::RigConstraint& c : rig.constraints)
        if (c.path == at("cns.carry.3"))
            carry = &c;
    ASSERT_NE(carry, nullptr);
    auto& settings = std::get<model::CarryConstraint>(carry->settings);
    ASSERT_EQ(settings.carried.size(), 3u) << "tweakers 0, 1 and 2";
    model::Rig groupCarried = rig;
    std::get<model::CarryConstraint>(groupCarried.constraints[std::size_t(carry - rig.constraints.data())].settings).carried[1] =
        *rig.findPath(at("mch.curve.1"));
    const auto refused = eval::RigProgram::compile(groupCarried);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(formatAll(refused.diagnostics()).find("constraint '" + at("cns.carry.3") + "': node '" + at("mch.curve.1") +
                                                    "' has no transform channels to carry"), std::string::npos)
        << formatAll(refused.diagnostics());
    settings.carried.pop_back();
    const auto mismatched = eval::RigProgram::compile(rig);
    ASSERT_FALSE(mismatched.ok());
    EXPECT_NE(formatAll(mismatched.diagnostics()).find("carries 2 nodes with 3 pivots"), std::string::npos)
        << formatAll(mismatched.diagnostics());
}

TEST(SplineTweak, PickwalkGoesDownTheChainedTweakers)
{
    const model::Rig chained = rigging::buildRig(curledTail(tail("chained")), test::builtinTemplates());
    model::RigNodeIndex at = *chained.findPath(tweak(0));
    for (int k = 1; k < kTweakers; ++k) {
        at = eval::pickwalk(chained, at, eval::WalkDirection::Down);
        EXPECT_EQ(chained.nodes[at].path, tweak(k));
    }
    EXPECT_EQ(chained.nodes[eval::pickwalk(chained, at, eval::WalkDirection::Up)].path, tweak(kTweakers - 2));
    // Unchained, each tweaker is a root of its own: down from the first goes nowhere.
    const model::Rig unchained = rigging::buildRig(curledTail(tail("unchained")), test::builtinTemplates());
    const model::RigNodeIndex first = *unchained.findPath(tweak(0));
    EXPECT_EQ(eval::pickwalk(unchained, first, eval::WalkDirection::Down), first);
}

} // namespace
} // namespace rs
