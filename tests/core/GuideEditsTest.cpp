#include "rigging/RigBuilder.h"
#include "core/TestSupport.h"
#include "edit/GuideEdits.h"

#include <gtest/gtest.h>

using namespace rs;

TEST(GuideEdits, EveryEditUndoesBackToTheOriginalDocument)
{
    model::GuideDocument doc = test::loadSample("biped");
    const model::GuideDocument original = doc;
    edit::History history(doc);
    int notifications = 0;
    history.addListener([&](const edit::Change&) { ++notifications; });

    const auto* arm = doc.instanceNamed("arm");
    auto digit = rigging::makeInstance(doc, test::builtinTemplates(), "core.joints", arm->joints.back().id);
    ASSERT_TRUE(digit.ok());
    const model::InstanceId digitId = digit->id;
    EXPECT_TRUE(test::succeeded(edit::addInstance(history, digit.take())));
    EXPECT_TRUE(test::succeeded(edit::renameInstance(history, digitId, "finger_L")));
    EXPECT_TRUE(test::succeeded(edit::setOption(history, digitId, "do_skin", false, true)));
    const model::JointId joint = doc.instance(digitId)->joints.front().id;
    Transform moved;
    moved.translate = Vec3(0.1, 0, 0);
    EXPECT_TRUE(test::succeeded(edit::setJointTransform(history, joint, moved)));
    EXPECT_TRUE(test::succeeded(edit::removeInstance(history, doc.instanceNamed("spine")->id)));

    EXPECT_EQ(doc.instances().size(), 1u) << "removing the spine removes everything hanging below it";
    EXPECT_EQ(history.size(), 5u);
    EXPECT_EQ(notifications, 5);
    while (history.canUndo())
        history.undo();
    EXPECT_EQ(doc, original);
    while (history.canRedo())
        history.redo();
    EXPECT_EQ(doc.instances().size(), 1u);
}

TEST(GuideEdits, RemovingSeveralInstancesIsOneUndoStepEvenWhenOneHangsBelowAnother)
{
    model::GuideDocument doc = test::loadSample("biped");
    const model::GuideDocument original = doc;
    edit::History history(doc);
    // The arm and its thumb (below it) and the leg, in the order a rigger clicked them.
    const std::vector<model::InstanceId> ids{doc.instanceNamed("thumb")->id, doc.instanceNamed("arm")->id,
                                             doc.instanceNamed("leg")->id};
    const std::size_t armSubtree = doc.subtree(doc.instanceNamed("arm")->id).size();
    ASSERT_TRUE(test::succeeded(edit::removeInstances(history, ids)));
    EXPECT_EQ(history.size(), 1u);
    EXPECT_EQ(history.undoText(), "Remove 3 templates");
    EXPECT_EQ(doc.instances().size(), original.instances().size() - armSubtree - 1);
    EXPECT_EQ(doc.instanceNamed("arm"), nullptr);
    EXPECT_EQ(doc.instanceNamed("leg"), nullptr);
    history.undo();
    EXPECT_EQ(doc, original) << "every instance back at its place";
    history.redo();
    EXPECT_EQ(doc.instanceNamed("thumb"), nullptr);
    EXPECT_EQ(test::refusal(edit::removeInstances(history, {})), "no instance to remove");
    EXPECT_EQ(test::refusal(edit::removeInstances(history, {ids[2]})), "no instance with id " + std::to_string(ids[2]));
    EXPECT_EQ(history.size(), 1u);
}

TEST(GuideEdits, RefusedEditsChangeNothing)
{
    model::GuideDocument doc = test::loadSample("biped");
    const model::GuideDocument original = doc;
    edit::History history(doc);
    const model::InstanceId spine = doc.instanceNamed("spine")->id;
    EXPECT_EQ(test::refusal(edit::renameInstance(history, spine, "neck")), "an instance named 'neck' already exists");
    EXPECT_EQ(test::refusal(edit::renameInstance(history, spine, "2spine")),
              "'2spine' is not a valid name (letters, digits and _, not starting with a digit)");
    EXPECT_EQ(test::refusal(edit::setOption(history, spine, "number", std::string("many"), 3LL)), "option 'number' takes a int, not a string");
    EXPECT_EQ(test::refusal(edit::removeInstance(history, 999)), "no instance with id 999");
    EXPECT_EQ(history.size(), 0u);
    EXPECT_EQ(doc, original);
}

TEST(GuideEdits, SettingTheDefaultValueRemovesTheStoredOption)
{
    model::GuideDocument doc = test::loadChains();
    edit::History history(doc);
    const model::InstanceId spine = doc.instanceNamed("spine")->id;
    ASSERT_TRUE(doc.instance(spine)->options.count("number"));
    EXPECT_TRUE(test::succeeded(edit::setOption(history, spine, "number", 3LL, 3LL)));
    EXPECT_FALSE(doc.instance(spine)->options.count("number"));
    history.undo();
    EXPECT_EQ(doc.instance(spine)->options.at("number"), Value(4LL));
}

TEST(GuideEdits, AFloatOptionGivenAsAWholeNumberIsStoredAsAFloatAndItsDefaultUnsetsIt)
{
    // A float option's 0.0 is written "0" and reads back as an int (the robot's arms' ik_blend): the same number
    // is the same value, so giving the default as a whole number unsets it, and a whole number is kept as a float.
    model::GuideDocument doc = test::loadSample("robot");
    edit::History history(doc);
    const model::InstanceId arm = doc.instanceNamed("arm")->id;
    ASSERT_TRUE(doc.instance(arm)->options.count("ik_blend"));
    EXPECT_TRUE(sameValue(doc.instance(arm)->options.at("ik_blend"), Value(0.0)));
    EXPECT_TRUE(test::succeeded(edit::setOption(history, arm, "ik_blend", Value(0.0), Value(1.0))));
    EXPECT_EQ(history.size(), 0u) << "0 and 0.0 are the same blend: nothing to undo";
    EXPECT_TRUE(test::succeeded(edit::setOption(history, arm, "ik_blend", Value(1LL), Value(1.0))));
    EXPECT_FALSE(doc.instance(arm)->options.count("ik_blend")) << "1 is the default 1.0";
    EXPECT_TRUE(test::succeeded(edit::setOption(history, arm, "ik_blend", Value(0LL), Value(1.0))));
    EXPECT_EQ(doc.instance(arm)->options.at("ik_blend"), Value(0.0)) << "stored as the option's kind";
    EXPECT_FALSE(sameValue(Value(1LL), Value(true))) << "a number is not a switch";
}

TEST(GuideEdits, NewInstancesGetFreshIdsAUniqueNameAndDefaultJoints)
{
    model::GuideDocument doc = test::loadSample("biped");
    const auto* neck = doc.instanceNamed("neck");
    auto a = rigging::makeInstance(doc, test::builtinTemplates(), "core.joints", neck->joints.back().id);
    ASSERT_TRUE(a.ok());
    EXPECT_EQ(a->name, "joints");
    EXPECT_EQ(a->joints.size(), 3u) << "the manifest's guides.number default";
    EXPECT_EQ(a->parent, neck->id);
    EXPECT_EQ(a->joints.front().id, doc.nextJointId());
    edit::History history(doc);
    ASSERT_TRUE(test::succeeded(edit::addInstance(history, a.take())));
    auto b = rigging::makeInstance(doc, test::builtinTemplates(), "core.joints", model::kNoId);
    ASSERT_TRUE(b.ok());
    EXPECT_EQ(b->name, "joints1");
    EXPECT_FALSE(rigging::makeInstance(doc, test::builtinTemplates(), "no.such", model::kNoId).ok());
}

TEST(GuideEdits, AGuideParameterRegeneratesTheJointsKeepingTheOnesThatStillExist)
{
    model::GuideDocument document = test::loadSample("biped");
    const model::GuideDocument original = document;
    edit::History history(document);
    const model::InstanceId spine = document.instanceNamed("spine")->id;
    const auto before = document.instanceNamed("spine")->joints;
    const Vec3 chest = translationOf(document.jointWorldMatrix(before.back().id));

    auto longer = rigging::regenerateGuide(document, test::builtinTemplates(), spine, {{"number", Value(7LL)}});
    ASSERT_TRUE(longer) << formatAll(longer.diagnostics());
    ASSERT_TRUE(test::succeeded(edit::replaceInstance(history, longer.take(), "Set guide option number")));
    const auto& joints = document.instance(spine)->joints;
    ASSERT_EQ(joints.size(), 7u);
    for (std::size_t k = 0; k < 4; ++k) {
        EXPECT_EQ(joints[k].id, before[k].id);
        EXPECT_LT(glm::length(translationOf(document.jointWorldMatrix(joints[k].id)) -
                              translationOf(original.jointWorldMatrix(before[k].id))), 1e-12) << k;
    }
    EXPECT_EQ(joints.back().id, before.back().id) << "the chest stays the chest";
    EXPECT_LT(glm::length(translationOf(document.jointWorldMatrix(joints.back().id)) - chest), 1e-12);
    EXPECT_EQ(document.instanceNamed("neck")->parentJoint, before.back().id) << "the neck still hangs on the chest";
    EXPECT_EQ(document.instance(spine)->options.at("number"), Value(7LL));
    const model::Rig rig = rigging::buildRig(document, test::builtinTemplates());
    EXPECT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);

    history.undo();
    EXPECT_TRUE(document == original);

    // Fewer joints: a child hanging under a joint that would go away refuses the edit.
    auto shorter = rigging::regenerateGuide(document, test::builtinTemplates(), spine, {{"number", Value(3LL)}});
    ASSERT_TRUE(shorter);
    EXPECT_EQ(shorter->joints.size(), 3u);
    edit::History other(document);
    document.instance(document.instanceNamed("neck")->id)->parentJoint = before[2].id;
    const Status refused = edit::replaceInstance(other, shorter.take(), "Set guide option number");
    EXPECT_EQ(test::refusal(refused), "'neck' hangs under a guide joint of 'spine' that would go away");
    ASSERT_FALSE(refused.diagnostics().empty());
    EXPECT_EQ(refused.diagnostics().front().subject, Subject::ofInstance(document.instanceNamed("neck")->id))
        << "names the instance that would lose its hook";
    EXPECT_EQ(document.instance(spine)->joints.size(), 5u);
}

TEST(GuideDocument, TakingAnUnknownInstanceReturnsNothingAndLeavesTheGuide)
{
    model::GuideDocument guide = test::loadSample("biped");
    const std::size_t count = guide.instances().size();
    EXPECT_FALSE(guide.takeInstance(guide.nextInstanceId()).has_value());
    EXPECT_EQ(guide.instances().size(), count);
    const model::InstanceId neck = guide.instanceNamed("neck")->id;
    const auto taken = guide.takeInstance(neck);
    ASSERT_TRUE(taken.has_value());
    EXPECT_EQ(taken->id, neck);
    EXPECT_EQ(guide.instances().size(), count - 1);
    EXPECT_FALSE(guide.takeInstance(neck).has_value());
}
