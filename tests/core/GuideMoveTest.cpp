#include "rigging/RigBuilder.h"
#include "core/TestSupport.h"
#include "edit/GuideMove.h"
#include "io/GuideFile.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

Vec3 worldOf(const model::GuideDocument& doc, model::JointId joint)
{
    return translationOf(doc.jointWorldMatrix(joint));
}

// Applies a drag's transforms the way the editor's preview does (no history).
void preview(model::GuideDocument& doc, const std::vector<edit::JointTransform>& transforms)
{
    for (const auto& t : transforms)
        doc.instance(doc.ownerOf(t.joint)->id)->joint(t.joint)->local = t.local;
}

} // namespace

TEST(GuideMove, LocalTransformsRoundTripEveryWorldMatrix)
{
    model::GuideDocument doc = test::loadSample("biped");
    for (const auto& instance : doc.instances())
        for (const auto& joint : instance.joints) {
            const Transform back = edit::localFor(doc, joint.id, doc.jointWorldMatrix(joint.id));
            EXPECT_LT(maxAbsDifference(back.matrix(), joint.local.matrix()), 1e-9) << instance.name << " " << joint.id;
        }
}

TEST(GuideMove, ADragMovesEverySelectedJointAsOneUndoStepAndChildrenFollow)
{
    model::GuideDocument doc = test::loadSample("biped");
    const model::GuideDocument original = doc;
    edit::History history(doc);
    const auto& arm = doc.instanceNamed("arm")->joints;
    const model::JointId elbow = arm[2].id, hand = arm[3].id;
    const model::JointId knee = doc.instanceNamed("leg")->joints[2].id;
    const Vec3 handBefore = worldOf(doc, hand), kneeBefore = worldOf(doc, knee), elbowBefore = worldOf(doc, elbow);

    edit::GuideDrag drag(doc, elbow, {elbow, knee, hand}, {});
    EXPECT_EQ(drag.start().size(), 2u) << "the hand follows the elbow rather than moving twice";
    Mat4 target = doc.jointWorldMatrix(elbow);
    target[3] += Vec4(0.0, 0.0, 0.1, 0.0);
    const auto transforms = drag.transformsFor(target);
    preview(doc, transforms); // the interactive preview
    preview(doc, drag.start()); // restored before the one recorded step
    EXPECT_TRUE(test::succeeded(edit::setJointTransforms(history, transforms, "Move elbow")));

    EXPECT_EQ(history.size(), 1u);
    EXPECT_EQ(history.undoText(), "Move elbow");
    EXPECT_LT(glm::length(worldOf(doc, elbow) - (elbowBefore + Vec3(0, 0, 0.1))), 1e-9);
    EXPECT_LT(glm::length(worldOf(doc, knee) - (kneeBefore + Vec3(0, 0, 0.1))), 1e-9);
    EXPECT_LT(glm::length(worldOf(doc, hand) - (handBefore + Vec3(0, 0, 0.1))), 1e-9);
    history.undo();
    EXPECT_TRUE(doc == original);
    EXPECT_EQ(test::refusal(edit::setJointTransforms(history, drag.start(), "Move elbow")), "the joints did not move");
}

TEST(GuideMove, RotatingTurnsEachJointAboutItsOwnPivot)
{
    model::GuideDocument doc = test::loadSample("biped");
    const auto& arm = doc.instanceNamed("arm")->joints;
    const model::JointId shoulder = arm[1].id, elbow = arm[2].id;
    const Vec3 pivot = worldOf(doc, shoulder), elbowBefore = worldOf(doc, elbow);
    edit::GuideDrag drag(doc, shoulder, {shoulder}, {});
    const Mat4 turn = rotationMatrix(Vec3(0, 1, 0), glm::radians(90.0));
    Mat4 target = doc.jointWorldMatrix(shoulder);
    target = translationMatrix(pivot) * turn * translationMatrix(-pivot) * target;
    preview(doc, drag.transformsFor(target));
    EXPECT_LT(glm::length(worldOf(doc, shoulder) - pivot), 1e-9) << "the pivot stays";
    const Vec3 expected = pivot + Vec3(turn * Vec4(elbowBefore - pivot, 0.0));
    EXPECT_LT(glm::length(worldOf(doc, elbow) - expected), 1e-9) << "the child swings around the shoulder";
}

TEST(GuideMove, SymmetryMovesTheMirrorTwinAndSnappingRoundsToTheGrid)
{
    model::GuideDocument doc = test::loadSample("biped");
    edit::History history(doc);
    const model::InstanceId arm = doc.instanceNamed("arm")->id;
    ASSERT_TRUE(test::succeeded(edit::renameInstance(history, arm, "arm_L")));
    std::vector<model::InstanceId> copies;
    ASSERT_TRUE(test::succeeded(edit::duplicateInstances(history, {arm}, &copies)));
    ASSERT_TRUE(test::succeeded(edit::renameInstance(history, copies.front(), "arm_R")));
    const model::JointId wrist = doc.instance(arm)->joints[3].id;
    const model::JointId twin = edit::mirrorJointOf(doc, wrist);
    EXPECT_EQ(twin, doc.instance(copies.front())->joints[3].id);
    EXPECT_EQ(edit::mirrorJointOf(doc, twin), wrist);
    EXPECT_EQ(edit::mirrorJointOf(doc, doc.instanceNamed("spine")->joints[0].id), model::kNoId) << "no side, no twin";

    edit::GuideDrag drag(doc, wrist, {wrist}, {true, 0.05});
    Mat4 target = doc.jointWorldMatrix(wrist);
    target[3] = Vec4(0.512, 1.333, 0.026, 1.0);
    preview(doc, drag.transformsFor(target));
    EXPECT_LT(glm::length(worldOf(doc, wrist) - Vec3(0.5, 1.35, 0.05)), 1e-9) << "snapped to the 5 cm grid";
    EXPECT_LT(glm::length(worldOf(doc, twin) - Vec3(-0.5, 1.35, 0.05)), 1e-9) << "the twin lands on the other side";
}

TEST(GuideMove, DuplicateCopiesTheSubtreeWithNewIdsAndNames)
{
    model::GuideDocument doc = test::loadSample("biped");
    const model::GuideDocument original = doc;
    edit::History history(doc);
    const model::InstanceId arm = doc.instanceNamed("arm")->id;
    const auto below = doc.subtree(arm);
    ASSERT_GT(below.size(), 1u) << "the sample's fingers hang under the arm";
    std::vector<model::InstanceId> copies;
    ASSERT_TRUE(test::succeeded(edit::duplicateInstances(history, {arm}, &copies)));
    EXPECT_EQ(history.size(), 1u);
    EXPECT_EQ(history.undoText(), "Duplicate 'arm'");
    ASSERT_EQ(copies.size(), 1u);
    const auto copied = doc.subtree(copies.front());
    ASSERT_EQ(copied.size(), below.size());
    EXPECT_EQ(doc.instance(copies.front())->name, "arm1");
    for (std::size_t i = 0; i < below.size(); ++i) {
        const auto* a = doc.instance(below[i]);
        const auto* b = doc.instance(copied[i]);
        EXPECT_NE(a->name, b->name);
        for (std::size_t j = 0; j < a->joints.size(); ++j) {
            EXPECT_NE(a->joints[j].id, b->joints[j].id);
            EXPECT_LT(glm::length(worldOf(doc, a->joints[j].id) - worldOf(doc, b->joints[j].id)), 1e-12);
        }
    }
    const model::Rig rig = rigging::buildRig(doc, test::builtinTemplates());
    EXPECT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    history.undo();
    EXPECT_TRUE(doc == original);
}

TEST(GuideMove, ReHangingKeepsTheGuideInPlaceAndRefusesCycles)
{
    model::GuideDocument doc = test::loadSample("biped");
    const model::GuideDocument original = doc;
    edit::History history(doc);
    const model::InstanceId arm = doc.instanceNamed("arm")->id;
    const model::JointId neckBase = doc.instanceNamed("neck")->joints[1].id;
    std::vector<Vec3> before;
    for (model::InstanceId id : doc.subtree(arm))
        for (const auto& j : doc.instance(id)->joints) before.push_back(worldOf(doc, j.id));

    ASSERT_TRUE(test::succeeded(edit::reparentInstance(history, arm, neckBase)));
    EXPECT_EQ(doc.instance(arm)->parent, doc.instanceNamed("neck")->id);
    EXPECT_EQ(doc.instance(arm)->parentJoint, neckBase);
    std::size_t k = 0;
    for (model::InstanceId id : doc.subtree(arm))
        for (const auto& j : doc.instance(id)->joints) EXPECT_LT(glm::length(worldOf(doc, j.id) - before[k++]), 1e-9);
    for (std::size_t i = 0; i < doc.instances().size(); ++i) { // parents stay before children
        if (doc.instances()[i].parent != model::kNoId) {
            EXPECT_LT(*doc.indexOf(doc.instances()[i].parent), i);
        }
    }
    const model::Rig rig = rigging::buildRig(doc, test::builtinTemplates());
    EXPECT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);

    const model::JointId finger = doc.instance(doc.subtree(arm).back())->joints.front().id;
    EXPECT_EQ(test::refusal(edit::reparentInstance(history, arm, finger)), "'arm' cannot hang under itself or an instance below it");
    history.undo();
    EXPECT_TRUE(doc == original);
}

TEST(GuideMove, AShapeEditMovesTheControllersCurvesOnBothSidesAndIsSaved)
{
    model::GuideDocument doc = test::loadSample("biped");
    const model::GuideDocument original = doc;
    edit::History history(doc);
    const model::InstanceId arm = doc.instanceNamed("arm")->id;
    const model::Rig before = rigging::buildRig(doc, test::builtinTemplates());
    Transform edit;
    edit.translate = Vec3(0.0, 0.1, 0.0);
    edit.scale = Vec3(2.0);
    ASSERT_TRUE(test::succeeded(edit::setShapeEdit(history, arm, "ctrls.ik", {edit, {}})));
    EXPECT_EQ(history.undoText(), "Edit shape ctrls.ik of arm");
    const model::Rig after = rigging::buildRig(doc, test::builtinTemplates());
    EXPECT_FALSE(hasErrors(after.diagnostics)) << formatAll(after.diagnostics);

    const auto& left0 = test::node(before, "arm.L::ctrls.ik");
    const auto& left1 = test::node(after, "arm.L::ctrls.ik");
    ASSERT_EQ(left0.curves.size(), left1.curves.size());
    ASSERT_FALSE(left0.curves.empty());
    for (std::size_t k = 0; k < left0.curves.front().points.size(); ++k)
        EXPECT_LT(glm::length(left1.curves.front().points[k] - Vec3(edit.matrix() * Vec4(left0.curves.front().points[k], 1.0))), 1e-12);
    // The right side shows the same edit, mirrored: its curves in the world are the left's reflected.
    const auto& right1 = test::node(after, "arm.R::ctrls.ik");
    const Vec3 l = Vec3(left1.worldMatrix * Vec4(left1.curves.front().points[0], 1.0));
    const Vec3 r = Vec3(right1.worldMatrix * Vec4(right1.curves.front().points[0], 1.0));
    EXPECT_LT(glm::length(r - Vec3(-l.x, l.y, l.z)), 1e-9);
    EXPECT_EQ(test::node(after, "arm.L::ctrls.fk.0").curves.front().points,
              test::node(before, "arm.L::ctrls.fk.0").curves.front().points) << "other controls unchanged";

    // Saved and read back; a bad value is an error with its line.
    const std::string text = io::writeGuideText(doc);
    EXPECT_NE(text.find("    node: ctrls.ik\n    shape: {t: [0, 0.1, 0], s: [2, 2, 2]}\n"), std::string::npos) << text;
    auto read = io::readGuideText(text, "edited.yml");
    ASSERT_TRUE(read) << formatAll(read.diagnostics());
    EXPECT_TRUE(*read == doc);
    std::string broken = text;
    broken.replace(broken.find("{t: [0, 0.1, 0]"), 15, "{t: [0, up, 0]");
    auto refused = io::readGuideText(broken, "broken.yml");
    EXPECT_FALSE(refused);
    EXPECT_NE(formatAll(refused.diagnostics()).find("broken.yml:"), std::string::npos) << formatAll(refused.diagnostics());

    history.undo();
    EXPECT_TRUE(doc == original);
}
