// Mikan's controller-hierarchy options on rig.spline (do_pose, add_nodes,
// parent_scale, rotate_order; flip_orient in SplineTweakTest's mirror test):
// every spline controller, tweaker and fk control gets the stack of
// rigging/builders/ControlNodes.h, and the tail moves as it did without it.
#include "EvalTestSupport.h"
#include "SplineTestSupport.h"
#include "core/IncrementalCheck.h"
#include "io/GuideFile.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace rs {
namespace {

using Options = std::map<std::string, Value>;
using test::curledTail;
using test::PosedRig;

std::string at(const std::string& tag) { return "tail::" + tag; }

Options withTweakersAndFk(Options options = {})
{
    options["tweakers"] = Value(std::string("chained"));
    options["fk"] = Value(true);
    return options;
}

// The tail posed on every kind of control.
eval::Pose posed(const PosedRig& r)
{
    eval::Pose pose = r.defaults();
    pose[r.channel(at("ctrls.spline.2"), "ty")] = 0.1;
    pose[r.channel(at("ctrls.spline.1"), "rz")] = 20.0;
    pose[r.channel(at("ctrls.tweak.3"), "rx")] = 25.0;
    pose[r.channel(at("ctrls.tweak.1"), "tz")] = 0.03;
    pose[r.channel(at("ctrls.fk.4"), "ry")] = 15.0;
    return pose;
}

TEST(SplineControlNodes, PoseGroupAndAddedNodesSitAroundEachControlAndChangeNoMotion)
{
    PosedRig plain(curledTail(withTweakersAndFk()));
    PosedRig stacked(curledTail(withTweakersAndFk({{"do_pose", Value(true)}, {"add_nodes", Value(std::string("[inf, c, dyn]"))}})));
    ASSERT_TRUE(plain.ok() && stacked.ok());
    EXPECT_TRUE(stacked.rig.diagnostics.empty()) << formatAll(stacked.rig.diagnostics);
    const model::Rig& rig = stacked.rig;
    for (const std::string key : {"spline.1", "tweak.2", "fk.3"}) {
        const model::RigNode& root = test::node(rig, at("roots." + key));
        const model::RigNode& pose = test::node(rig, at("nodes.pose." + key));
        const model::RigNode& inf = test::node(rig, at("nodes.inf." + key));
        const model::RigNode& ctrl = test::node(rig, at("ctrls." + key));
        const model::RigNode& dyn = test::node(rig, at("nodes.dyn." + key));
        EXPECT_EQ(rig.nodes[pose.parent].key, root.key) << key;
        EXPECT_EQ(rig.nodes[inf.parent].key, pose.key) << key;
        EXPECT_EQ(rig.nodes[ctrl.parent].key, inf.key) << key;
        EXPECT_EQ(rig.nodes[dyn.parent].key, ctrl.key) << key;
        for (const model::RigNode* n : {&root, &pose, &inf, &dyn})
            EXPECT_LT(maxAbsDifference(n->worldMatrix, ctrl.worldMatrix), 1e-12) << n->path;
        EXPECT_EQ(pose.name.rfind("pose_", 0), 0u) << pose.name;
    }
    // The fk control's skin joint hangs under its last group.
    EXPECT_EQ(rig.nodes[test::node(rig, at("skin.3")).parent].key, test::node(rig, at("nodes.dyn.fk.3")).key);
    // The same tail at rest and posed.
    for (const model::RigNode& node : plain.rig.nodes) {
        if (node.key.tag.rfind("skin.", 0) == 0) {
            EXPECT_LT(maxAbsDifference(node.worldMatrix, test::node(rig, node.path).worldMatrix), 1e-12) << node.path;
        }
    }
    plain.evaluate(posed(plain));
    stacked.evaluate(posed(stacked));
    for (const model::RigNode& node : plain.rig.nodes) {
        if (node.key.tag.rfind("skin.", 0) == 0 || node.key.tag.rfind("ctrls.", 0) == 0) {
            EXPECT_LT(maxAbsDifference(plain.state().worldMatrix(plain.index(node.path)),
                                       stacked.state().worldMatrix(stacked.index(node.path))), 1e-9) << node.path;
        }
    }
}

// flip_orient: the curve follows a group with the mirror frame under each
// controller, and the stretch attribute stays on the first controller.
TEST(SplineControlNodes, FlipOrientKeepsTheStretchAttributeOnTheFirstController)
{
    PosedRig r(curledTail({{"flip_orient", Value(true)}, {"branches", Value(std::string("[L, R]"))}}));
    ASSERT_TRUE(r.ok());
    for (const char* side : {"L", "R"}) {
        const std::string first = std::string("tail.") + side + "::ctrls.spline.0";
        const model::RigNode& follow = test::node(r.rig, std::string("tail.") + side + "::mch.follow.spline.0");
        EXPECT_EQ(r.rig.nodes[follow.parent].path, first);
        r.channel(first, "stretch"); // fails the test when it is not there
    }
}

TEST(SplineControlNodes, ParentScaleOffKeepsTheNextSplineControllersSize)
{
    for (const bool parentScale : {true, false}) {
        PosedRig r(curledTail({{"parent_scale", Value(parentScale)}}));
        ASSERT_TRUE(r.ok());
        EXPECT_EQ(test::node(r.rig, at("roots.spline.1")).scaleCompensate, !parentScale);
        EXPECT_FALSE(test::node(r.rig, at("roots.spline.0")).scaleCompensate) << "the first follows the hook";
        const std::string first = at("ctrls.spline.0"), second = at("ctrls.spline.1");
        const double restLength = glm::length(r.restPosition(second) - r.restPosition(first));
        eval::Pose pose = r.defaults();
        for (const char* s : {"sx", "sy", "sz"})
            pose[r.channel(first, s)] = 2.0;
        r.evaluate(pose);
        const Mat3 m = r.state().world[r.index(second)].linear;
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(glm::length(m[k]), parentScale ? 2.0 : 1.0, 1e-9) << "parent_scale " << parentScale;
        EXPECT_NEAR(glm::length(r.position(second) - r.position(first)), 2.0 * restLength, 1e-9) << "it still follows";
    }
}

TEST(SplineControlNodes, RotateOrderSetsEveryControllersEulerOrder)
{
    PosedRig r(curledTail(withTweakersAndFk({{"rotate_order", Value(std::string("zxy"))}})));
    ASSERT_TRUE(r.ok());
    for (const std::string key : {"spline.0", "spline.3", "tweak.0", "tweak.6", "fk.2"}) {
        const std::string ctrl = at("ctrls." + key);
        EXPECT_EQ(test::node(r.rig, ctrl).channels.rotateOrder, model::RotateOrder::Zxy) << key;
    }
    // The channel box's angles turn a tweaker in that order.
    const std::string ctrl = at("ctrls.tweak.3");
    eval::Pose pose = r.defaults();
    pose[r.channel(ctrl, "rx")] = 30.0;
    pose[r.channel(ctrl, "rz")] = 50.0;
    r.evaluate(pose);
    const Mat3 expected = Mat3(test::node(r.rig, ctrl).worldMatrix) * eval::eulerRotation({30.0, 0.0, 50.0}, model::RotateOrder::Zxy);
    EXPECT_LT(maxAbsDifference(Mat4(r.state().world[r.index(ctrl)].linear), Mat4(expected)), 1e-9);
    // Left at xyz (the default), as before the option.
    const model::Rig plain = rigging::buildRig(curledTail(withTweakersAndFk()), test::builtinTemplates());
    EXPECT_EQ(test::node(plain, at("ctrls.tweak.3")).channels.rotateOrder, model::RotateOrder::Xyz);
}

TEST(SplineControlNodes, BadControlOptionsAreRefusedNamingTheOption)
{
    for (const std::string bad : {"[1st]", "[inf, inf]", "[root]"}) {
        const model::Rig rig = rigging::buildRig(curledTail({{"add_nodes", Value(bad)}}), test::builtinTemplates());
        EXPECT_TRUE(hasErrors(rig.diagnostics)) << bad;
        EXPECT_NE(formatAll(rig.diagnostics).find("option 'add_nodes'"), std::string::npos) << bad << ": " << formatAll(rig.diagnostics);
        EXPECT_FALSE(rig.findPath(at("ctrls.spline.0"))) << "no half-built tail";
    }
    // In a guide file: at the option's line.
    const std::string guide = "rigsmith_guide: 3\nname: g\ninstances:\n  - id: 1\n    template: rig.spline\n    name: tail\n"
                              "    options:\n      add_nodes: \"[inf, 2nd]\"\n      tweakers: chained\n    joints:\n"
                              "      - {id: 1, t: [0, 0, 0]}\n      - {id: 2, parent: 1, t: [0, 0, -0.2]}\n"
                              "      - {id: 3, parent: 2, t: [0, 0, -0.2]}\n";
    const auto read = io::readGuideText(guide, "tail.yml");
    ASSERT_FALSE(read.ok());
    EXPECT_NE(formatAll(read.diagnostics()).find("tail.yml:8:18: error: option add_nodes '2nd' is no node name"), std::string::npos)
        << formatAll(read.diagnostics());
    // A rotate order that is none of the enum's: said so, and the default used (as for every enum option).
    const model::Rig order = rigging::buildRig(curledTail({{"rotate_order", Value(std::string("xxz"))}}), test::builtinTemplates());
    EXPECT_NE(formatAll(order.diagnostics).find("option 'rotate_order' = 'xxz' is not one of its labels"), std::string::npos)
        << formatAll(order.diagnostics);
    EXPECT_EQ(test::node(order, at("ctrls.spline.1")).channels.rotateOrder, model::RotateOrder::Xyz);
}

TEST(SplineControlNodes, ControlOptionsRebuildIncrementallyAsAFullBuild)
{
    model::GuideDocument guide = curledTail(withTweakersAndFk({{"branches", Value(std::string("[L, R]"))}}));
    const model::InstanceId id = guide.instances().front().id;
    rigging::BuildCache cache;
    test::buildAndCompare(guide, cache, "first build");
    const std::vector<std::pair<std::string, Value>> edits = {
        {"do_pose", Value(true)}, {"add_nodes", Value(std::string("[inf, c, dyn]"))}, {"parent_scale", Value(false)},
        {"rotate_order", Value(std::string("yzx"))}, {"flip_orient", Value(true)}, {"add_nodes", Value(std::string(""))},
        {"do_pose", Value(false)}};
    for (const auto& [name, value] : edits) {
        guide.instance(id)->options[name] = value;
        test::buildAndCompare(guide, cache, name);
    }
}

} // namespace
} // namespace rs
