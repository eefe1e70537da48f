// Mikan's general-purpose templates as a rigger checks them on the built and
// evaluated rig (issue 22 item 7): core.bones (a bone per segment aimed at the
// next guide joint, the tip a hook) and core.group (a transform to hang parts
// under, with no controller or skin joint).
#include "EvalTestSupport.h"
#include "core/TestSupport.h"
#include "rigging/RigBuilder.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace rs {
namespace {

using test::PosedRig;

// A bent chain of four guide joints (three bones) with a prop hanging from its tip.
model::GuideDocument bentBones()
{
    model::GuideDocument doc;
    model::TemplateInstance bones = test::addInstance(doc, "core.bones", model::kNoId, {{"number", Value(4LL)}});
    model::TemplateInstance* b = doc.instance(bones.id);
    b->joints[0].local.translate = Vec3(0.0, 1.0, 0.0);
    b->joints[1].local.translate = Vec3(0.3, 0.0, 0.0);
    b->joints[2].local.translate = Vec3(0.0, 0.2, 0.1);
    b->joints[3].local.translate = Vec3(0.0, 0.0, 0.25);
    test::addInstance(doc, "core.xform", b->joints.back().id);
    return doc;
}

TEST(CoreTemplates, BonesAimEachSegmentAtTheNextGuideJointAndTheTipIsAHook)
{
    const model::GuideDocument doc = bentBones();
    PosedRig r(doc);
    ASSERT_TRUE(r.ok());
    const model::TemplateInstance& bones = doc.instances().front();
    EXPECT_FALSE(r.rig.findPath(bones.name + "::ctrls.3")) << "no controller on the tip";
    for (int i = 0; i < 3; ++i) {
        const std::string ctrl = bones.name + "::ctrls." + std::to_string(i);
        ASSERT_TRUE(r.rig.findPath(ctrl)) << ctrl;
        ASSERT_TRUE(r.rig.findPath(bones.name + "::skin." + std::to_string(i)));
        const Vec3 from = translationOf(doc.jointWorldMatrix(bones.joints[i].id));
        const Vec3 to = translationOf(doc.jointWorldMatrix(bones.joints[i + 1].id));
        const Mat4 world = r.rig.nodes[r.index(ctrl)].worldMatrix;
        EXPECT_LT(glm::length(translationOf(world) - from), 1e-9) << ctrl;
        EXPECT_GT(glm::dot(glm::normalize(Vec3(world[1])), glm::normalize(to - from)), 1.0 - 1e-9) << ctrl << ": +Y along the bone";
        EXPECT_NEAR(glm::dot(Vec3(world[0]), Vec3(world[1])), 0.0, 1e-9) << "orthonormal";
    }
    // The prop under the tip hangs from the tip hook: turning the first bone carries it.
    const std::string prop = doc.instances().back().name + "::ctrls.xform";
    const Vec3 rest = r.restPosition(prop);
    EXPECT_LT(glm::length(rest - translationOf(doc.jointWorldMatrix(bones.joints.back().id))), 1e-9);
    eval::Pose pose = r.defaults();
    pose[r.channel(bones.name + "::ctrls.0", "rz")] = 90.0;
    r.evaluate(pose);
    const Vec3 pivot = r.restPosition(bones.name + "::ctrls.0");
    const Vec3 moved = r.position(prop);
    EXPECT_GT(glm::length(moved - rest), 0.1) << "the tip's child follows the bones";
    EXPECT_NEAR(glm::length(moved - pivot), glm::length(rest - pivot), 1e-9) << "a rigid turn about the first bone";
}

TEST(CoreTemplates, BonesRefuseASingleGuideJoint)
{
    model::GuideDocument doc;
    model::TemplateInstance bones = test::addInstance(doc, "core.bones", model::kNoId);
    doc.instance(bones.id)->joints.resize(1);
    const model::Rig rig = rigging::buildRig(doc, test::builtinTemplates());
    bool reported = false;
    for (const Diagnostic& d : rig.diagnostics)
        reported = reported || (d.severity == Severity::Error && d.message.find("at least two guide joints") != std::string::npos);
    EXPECT_TRUE(reported) << formatAll(rig.diagnostics);
    EXPECT_FALSE(rig.findPath(bones.name + "::ctrls.0"));
}

TEST(CoreTemplates, GroupMakesNoControllerOrSkinJointAndCarriesWhatHangsUnderIt)
{
    model::GuideDocument doc;
    model::TemplateInstance root = test::addInstance(doc, "core.xform", model::kNoId);
    model::TemplateInstance group = test::addInstance(doc, "core.group", root.joints.front().id);
    doc.instance(group.id)->joints.front().local.translate = Vec3(0.5, 0.0, 0.0);
    model::TemplateInstance part = test::addInstance(doc, "core.xform", group.joints.front().id);
    doc.instance(part.id)->joints.front().local.translate = Vec3(0.0, 0.4, 0.0);
    PosedRig r(doc);
    ASSERT_TRUE(r.ok());
    std::size_t groupControllers = 0, groupJoints = 0;
    for (const model::RigNode& node : r.rig.nodes)
        if (node.key.instance == group.id) {
            groupControllers += node.kind == model::RigNodeKind::Controller;
            groupJoints += node.kind == model::RigNodeKind::Joint;
        }
    EXPECT_EQ(groupControllers, 0u);
    EXPECT_EQ(groupJoints, 0u);
    const std::string partCtrl = part.name + "::ctrls.xform";
    const Vec3 rest = r.restPosition(partCtrl);
    eval::Pose pose = r.defaults();
    pose[r.channel(root.name + "::ctrls.xform", "ty")] = 1.0;
    r.evaluate(pose);
    EXPECT_LT(glm::length(r.position(partCtrl) - (rest + Vec3(0.0, 1.0, 0.0))), 1e-9) << "the part hangs under the group";
}

TEST(CoreTemplates, XformDoOptionsLockWhatAnimatorsDoNotTouchAndSetTheRotateOrder)
{
    model::GuideDocument doc;
    const model::TemplateInstance plain = test::addInstance(doc, "core.xform", model::kNoId);
    const model::TemplateInstance wheelCap =
        test::addInstance(doc, "core.xform", plain.joints.front().id, {{"do_scale", Value(false)}, {"do_translate", Value(false)}, {"rotate_order", Value(std::string("zxy"))}});
    PosedRig r(doc);
    ASSERT_TRUE(r.ok());
    const model::ChannelSettings& free = r.rig.nodes[r.index(plain.name + "::ctrls.xform")].channels;
    const model::ChannelSettings& capped = r.rig.nodes[r.index(wheelCap.name + "::ctrls.xform")].channels;
    for (int c = 0; c < 9; ++c) {
        EXPECT_FALSE(free.isLocked(c)) << "by default a prop's part moves, turns and scales: " << model::channelName(c);
        EXPECT_TRUE(free.isAnimatable(c)) << model::channelName(c);
        EXPECT_EQ(capped.isLocked(c), c < 3 || c >= 6) << model::channelName(c);
        EXPECT_EQ(capped.isAnimatable(c), c >= 3 && c < 6) << model::channelName(c);
    }
    EXPECT_EQ(free.rotateOrder, model::RotateOrder::Xyz);
    EXPECT_EQ(capped.rotateOrder, model::RotateOrder::Zxy);
    // The evaluator's channel layout sees the locks (the channel box greys them out, poses ignore them).
    EXPECT_TRUE(r.program->channels()[std::size_t(r.channel(wheelCap.name + "::ctrls.xform", "tx"))].locked);
    EXPECT_FALSE(r.program->channels()[std::size_t(r.channel(wheelCap.name + "::ctrls.xform", "rz"))].locked);
}

} // namespace
} // namespace rs
