// Mikan's controller-hierarchy options (do_pose, add_nodes, parent_scale,
// rotate_order, flip_orient: rigging/builders/ControlNodes.h) on core.joints
// and core.bones, as an animator checks them on the built and evaluated rig.
#include "EvalTestSupport.h"
#include "IncrementalCheck.h"
#include "core/TestSupport.h"
#include "eval/Channels.h"
#include "io/GuideFile.h"
#include "rigging/RigBuilder.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace rs {
namespace {

using Options = std::map<std::string, Value>;
using test::PosedRig;

// A three-joint chain of `templateId` out along +X at (0.3, 1, 0), guides only translated.
model::GuideDocument chain(const std::string& templateId, Options options)
{
    model::GuideDocument doc;
    options["number"] = Value(3LL);
    auto made = rigging::makeInstance(doc, test::builtinTemplates(), templateId, model::kNoId, options);
    EXPECT_TRUE(made.ok()) << formatAll(made.diagnostics());
    model::TemplateInstance instance = made.take();
    const Vec3 steps[] = {{0.3, 1.0, 0.0}, {0.25, 0.05, 0.02}, {0.2, -0.05, 0.03}};
    for (std::size_t i = 0; i < instance.joints.size(); ++i) {
        instance.joints[i].local.translate = steps[i];
        instance.joints[i].local.rotateDegrees = Vec3(0.0);
    }
    doc.insertInstance(instance, 0);
    return doc;
}

std::string pathOf(const model::GuideDocument& doc, const std::string& tag, const std::string& branch = {})
{
    return doc.instances().front().name + (branch.empty() ? "" : "." + branch) + "::" + tag;
}

Vec3 worldScale(const PosedRig& r, const std::string& id)
{
    const Mat3 m = r.state().world[r.index(id)].linear;
    return {glm::length(m[0]), glm::length(m[1]), glm::length(m[2])};
}

TEST(CoreTemplates, PoseGroupAndAddedNodesSitAroundEachControllerAtItsRest)
{
    const auto plain = chain("core.bones", {});
    const auto stacked = chain("core.bones", {{"do_pose", Value(true)}, {"add_nodes", Value(std::string("[inf, c, dyn]"))}});
    PosedRig a(plain), b(stacked);
    ASSERT_TRUE(a.ok() && b.ok());
    for (const std::string i : {"0", "1"}) {
        const model::RigNode& root = test::node(b.rig, pathOf(stacked, "roots." + i));
        const model::RigNode& pose = test::node(b.rig, pathOf(stacked, "nodes.pose." + i));
        const model::RigNode& inf = test::node(b.rig, pathOf(stacked, "nodes.inf." + i));
        const model::RigNode& ctrl = test::node(b.rig, pathOf(stacked, "ctrls." + i));
        const model::RigNode& dyn = test::node(b.rig, pathOf(stacked, "nodes.dyn." + i));
        const model::RigNode& skin = test::node(b.rig, pathOf(stacked, "skin." + i));
        // root > pose > inf > controller > dyn > skin, each at the controller's rest frame.
        EXPECT_EQ(b.rig.nodes[pose.parent].key, root.key);
        EXPECT_EQ(b.rig.nodes[inf.parent].key, pose.key);
        EXPECT_EQ(b.rig.nodes[ctrl.parent].key, inf.key);
        EXPECT_EQ(b.rig.nodes[dyn.parent].key, ctrl.key);
        EXPECT_EQ(b.rig.nodes[skin.parent].key, dyn.key);
        for (const model::RigNode* n : {&pose, &inf, &dyn})
            EXPECT_LT(maxAbsDifference(n->worldMatrix, ctrl.worldMatrix), 1e-12) << n->path;
        EXPECT_EQ(pose.kind, model::RigNodeKind::Group);
        // Named as Mikan marks them: pose_<name>, inf_<name>.
        EXPECT_EQ(pose.name.rfind("pose_", 0), 0u) << pose.name;
        EXPECT_EQ(inf.name.rfind("inf_", 0), 0u) << inf.name;
        // The bones themselves are where they were without the groups.
        EXPECT_LT(maxAbsDifference(skin.worldMatrix, test::node(a.rig, pathOf(plain, "skin." + i)).worldMatrix), 1e-12);
    }
    // The chain still hangs from controller to controller: turning the first bone carries the second.
    eval::Pose pose = b.defaults();
    pose[b.channel(pathOf(stacked, "ctrls.0"), "rz")] = 40.0;
    b.evaluate(pose);
    EXPECT_GT(glm::length(b.position(pathOf(stacked, "skin.1")) - b.restPosition(pathOf(stacked, "skin.1"))), 0.05);
}

TEST(CoreTemplates, ParentScaleOffKeepsAChildControlsSizeWhenItsParentIsScaled)
{
    for (const bool parentScale : {true, false}) {
        const auto doc = chain("core.joints", {{"parent_scale", Value(parentScale)}});
        PosedRig r(doc);
        ASSERT_TRUE(r.ok());
        const std::string first = pathOf(doc, "ctrls.0"), second = pathOf(doc, "ctrls.1");
        const double restLength = glm::length(r.restPosition(second) - r.restPosition(first));
        eval::Pose pose = r.defaults();
        for (const char* s : {"sx", "sy", "sz"})
            pose[r.channel(first, s)] = 2.0;
        r.evaluate(pose);
        const Vec3 scale = worldScale(r, second);
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(scale[k], parentScale ? 2.0 : 1.0, 1e-9) << "parent_scale " << parentScale;
        // Either way the child sits at the end of the scaled parent segment.
        EXPECT_NEAR(glm::length(r.position(second) - r.position(first)), 2.0 * restLength, 1e-9);
        EXPECT_EQ(test::node(r.rig, pathOf(doc, "roots.1")).scaleCompensate, !parentScale);
        EXPECT_FALSE(test::node(r.rig, pathOf(doc, "roots.0")).scaleCompensate) << "the chain's root follows what it hangs on";
    }
}

TEST(CoreTemplates, RotateOrderSetsTheControllersEulerOrder)
{
    const auto doc = chain("core.bones", {{"rotate_order", Value(std::string("zxy"))}});
    PosedRig r(doc);
    ASSERT_TRUE(r.ok());
    const std::string ctrl = pathOf(doc, "ctrls.1");
    EXPECT_EQ(test::node(r.rig, ctrl).channels.rotateOrder, model::RotateOrder::Zxy);
    EXPECT_EQ(r.defaults()[std::size_t(r.channel(ctrl, "rx") - 3 + eval::kRotateOrderChannel)], double(int(model::RotateOrder::Zxy)));
    // The channel box's angles turn the bone in that order.
    eval::Pose pose = r.defaults();
    pose[r.channel(ctrl, "rx")] = 30.0;
    pose[r.channel(ctrl, "rz")] = 50.0;
    r.evaluate(pose);
    const Mat3 rest(test::node(r.rig, ctrl).worldMatrix);
    const Mat3 turned = r.state().world[r.index(ctrl)].linear;
    const Mat3 expected = rest * eval::eulerRotation({30.0, 0.0, 50.0}, model::RotateOrder::Zxy);
    const Mat3 otherOrder = rest * eval::eulerRotation({30.0, 0.0, 50.0}, model::RotateOrder::Xyz);
    EXPECT_LT(maxAbsDifference(Mat4(turned), Mat4(expected)), 1e-9);
    EXPECT_GT(maxAbsDifference(Mat4(turned), Mat4(otherOrder)), 0.05) << "the order matters for these angles";
}

TEST(CoreTemplates, RotateOrderAutoTwistsFirstSwingsNextAndBendsLast)
{
    // auto: aim_axis first, the third axis next, up_axis (the bend) last, whichever axes the chain aims.
    const std::pair<std::pair<const char*, const char*>, model::RotateOrder> cases[] = {
        {{"x", "z"}, model::RotateOrder::Xyz}, {{"y", "x"}, model::RotateOrder::Yzx}, {{"-z", "y"}, model::RotateOrder::Zxy},
        {{"x", "-y"}, model::RotateOrder::Xzy}};
    for (const auto& [axes, expected] : cases) {
        const auto doc = chain("core.joints", {{"orient", Value(std::string("auto"))},
                                               {"aim_axis", Value(std::string(axes.first))},
                                               {"up_axis", Value(std::string(axes.second))},
                                               {"rotate_order", Value(std::string("auto"))}});
        const model::Rig rig = rigging::buildRig(doc, test::builtinTemplates());
        ASSERT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
        for (const char* ctrl : {"ctrls.0", "ctrls.1"})
            EXPECT_EQ(test::node(rig, pathOf(doc, ctrl)).channels.rotateOrder, expected) << axes.first << " " << axes.second;
    }
    // Bent 90 degrees about its up axis (z, last) a control still twists and swings apart: no gimbal lock.
    const auto doc = chain("core.joints", {{"orient", Value(std::string("auto"))}, {"aim_axis", Value(std::string("x"))},
                                           {"up_axis", Value(std::string("z"))}, {"rotate_order", Value(std::string("auto"))}});
    const auto order = test::node(rigging::buildRig(doc, test::builtinTemplates()), pathOf(doc, "ctrls.1")).channels.rotateOrder;
    const Mat3 twist = eval::eulerRotation({10.0, 0.0, 90.0}, order), swing = eval::eulerRotation({0.0, 10.0, 90.0}, order);
    EXPECT_GT(maxAbsDifference(Mat4(twist), Mat4(swing)), 0.1);
    const Mat3 lockedTwist = eval::eulerRotation({10.0, 0.0, 90.0}, model::RotateOrder::Xzy),
               lockedSwing = eval::eulerRotation({0.0, 10.0, 90.0}, model::RotateOrder::Xzy);
    EXPECT_LT(maxAbsDifference(Mat4(lockedTwist), Mat4(lockedSwing)), 1e-9) << "with the bend in the middle they lock (the test can tell)";
}

TEST(CoreTemplates, FlipOrientMakesTheSameValuesMoveBothSidesAsMirrorImages)
{
    Mat4 mirror(1.0);
    mirror[0][0] = -1.0;
    for (const bool flip : {false, true}) {
        const auto doc = chain("core.joints", {{"branches", Value(std::string("[L, R]"))}, {"flip_orient", Value(flip)}});
        PosedRig r(doc);
        ASSERT_TRUE(r.ok());
        eval::Pose pose = r.defaults();
        for (const std::string side : {"L", "R"}) {
            const std::string ctrl = pathOf(doc, "ctrls.0", side);
            pose[r.channel(ctrl, "tx")] = 0.1;
            pose[r.channel(ctrl, "ty")] = 0.2;
            pose[r.channel(ctrl, "tz")] = -0.05;
            pose[r.channel(ctrl, "rz")] = 25.0;
            pose[r.channel(ctrl, "ry")] = -10.0;
        }
        r.evaluate(pose);
        double worst = 0.0;
        for (const std::string tag : {"skin.0", "skin.1", "skin.2"}) {
            const Vec3 left = r.position(pathOf(doc, tag, "L")), right = r.position(pathOf(doc, tag, "R"));
            worst = std::max(worst, glm::length(right - Vec3(-left.x, left.y, left.z)));
        }
        if (flip)
            EXPECT_LT(worst, 1e-9) << "the same values pose the right side as the mirror image of the left";
        else
            EXPECT_GT(worst, 0.05) << "without flip_orient the mirror frames move some channels the other way";
        // The skin joints keep their mirror frames either way (rigid, right-handed), and so do the rest poses.
        for (const std::string tag : {"skin.0", "skin.1", "roots.1"}) {
            const model::RigNode& right = test::node(r.rig, pathOf(doc, tag, "R"));
            const model::RigNode& left = test::node(r.rig, pathOf(doc, tag, "L"));
            EXPECT_LT(glm::length(translationOf(right.worldMatrix) - Vec3(mirror * Vec4(translationOf(left.worldMatrix), 1.0))), 1e-12);
            if (tag.rfind("skin", 0) == 0)
                EXPECT_LT(maxAbsDifference(right.worldMatrix, mirror * left.worldMatrix * mirror), 1e-12) << tag;
        }
        // The right controller's curves are the mirror image of the left's in the world.
        const model::RigNode& cl = test::node(r.rig, pathOf(doc, "ctrls.1", "L"));
        const model::RigNode& cr = test::node(r.rig, pathOf(doc, "ctrls.1", "R"));
        ASSERT_FALSE(cl.curves.empty());
        for (std::size_t k = 0; k < cl.curves.front().points.size(); ++k) {
            const Vec3 pl = Vec3(cl.worldMatrix * Vec4(cl.curves.front().points[k], 1.0));
            const Vec3 pr = Vec3(cr.worldMatrix * Vec4(cr.curves.front().points[k], 1.0));
            EXPECT_LT(glm::length(pr - Vec3(-pl.x, pl.y, pl.z)), 1e-9) << "flip " << flip << " point " << k;
        }
    }
}

TEST(CoreTemplates, BadAddNodesAreRefusedWhereTheyAreWritten)
{
    // In a guide file: at the option's line.
    const std::string guide = "rigsmith_guide: 3\nname: g\ninstances:\n  - id: 1\n    template: core.bones\n    name: tail\n"
                              "    options:\n      do_pose: on\n      add_nodes: \"[inf, 2nd, inf]\"\n    joints:\n"
                              "      - {id: 1, t: [0, 0, 0]}\n      - {id: 2, parent: 1, t: [0, 1, 0]}\n";
    auto read = io::readGuideText(guide, "bad.yml");
    ASSERT_FALSE(read.ok());
    const std::string all = formatAll(read.diagnostics());
    EXPECT_NE(all.find("bad.yml:9:18: error: option add_nodes '2nd' is no node name"), std::string::npos) << all;
    EXPECT_NE(all.find("bad.yml:9:18: error: option add_nodes names 'inf' twice"), std::string::npos) << all;
    EXPECT_EQ(io::readGuideText(std::string(guide).replace(guide.find("2nd, inf"), 8, "c, dyn"), "good.yml").ok(), true);
    // Written unquoted (a YAML list), the same.
    std::string plain = guide;
    plain.replace(plain.find("\"[inf, 2nd, inf]\""), 17, "[inf, 2nd, inf]");
    auto plainRead = io::readGuideText(plain, "plain.yml");
    ASSERT_FALSE(plainRead.ok());
    EXPECT_NE(formatAll(plainRead.diagnostics()).find("plain.yml:9:18: error: option add_nodes '2nd' is no node name"),
              std::string::npos) << formatAll(plainRead.diagnostics());
    auto plainGood = io::readGuideText(std::string(plain).replace(plain.find("2nd, inf"), 8, "c, dyn"), "plain-good.yml");
    ASSERT_TRUE(plainGood.ok()) << formatAll(plainGood.diagnostics());
    EXPECT_EQ(plainGood->instances().front().options.at("add_nodes"), Value(std::string("[inf, c, dyn]")));

    // Set another way (an edit, the API): the build refuses it, naming the option.
    for (const std::string bad : {"[1st]", "[inf, inf]", "[root]", "[c, dyn, c]", "[in-f]", "{a: 1}"}) {
        const auto doc = chain("core.bones", {{"add_nodes", Value(bad)}});
        const model::Rig rig = rigging::buildRig(doc, test::builtinTemplates());
        EXPECT_TRUE(hasErrors(rig.diagnostics)) << bad;
        EXPECT_NE(formatAll(rig.diagnostics).find("option 'add_nodes'"), std::string::npos) << bad << ": " << formatAll(rig.diagnostics);
        EXPECT_FALSE(rig.findPath(pathOf(doc, "ctrls.0"))) << "no half-built chain";
    }
}

TEST(CoreTemplates, ControlOptionsRebuildIncrementallyAsAFullBuild)
{
    auto doc = chain("core.joints", {{"branches", Value(std::string("[L, R]"))}});
    const model::InstanceId id = doc.instances().front().id;
    rigging::BuildCache cache;
    test::buildAndCompare(doc, cache, "first build");
    const std::vector<std::pair<std::string, Value>> edits = {
        {"do_pose", Value(true)}, {"add_nodes", Value(std::string("[inf, c, dyn]"))}, {"parent_scale", Value(false)},
        {"rotate_order", Value(std::string("yzx"))}, {"flip_orient", Value(true)}, {"do_pose", Value(false)}};
    for (const auto& [name, value] : edits) {
        doc.instance(id)->options[name] = value;
        test::buildAndCompare(doc, cache, name);
    }
}

} // namespace
} // namespace rs
