#include "build/RigBuilder.h"
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
    history.addListener([&] { ++notifications; });

    const auto* arm = doc.instanceNamed("arm");
    auto digit = build::makeInstance(doc, test::builtinTemplates(), "core.joints", arm->joints.back().id);
    ASSERT_TRUE(digit.ok());
    const model::InstanceId digitId = digit->id;
    EXPECT_FALSE(edit::addInstance(history, digit.take()));
    EXPECT_FALSE(edit::renameInstance(history, digitId, "finger_L"));
    EXPECT_FALSE(edit::setOption(history, digitId, "do_skin", false, true));
    const model::JointId joint = doc.instance(digitId)->joints.front().id;
    Transform moved;
    moved.translate = Vec3(0.1, 0, 0);
    EXPECT_FALSE(edit::setJointTransform(history, joint, moved));
    EXPECT_FALSE(edit::removeInstance(history, doc.instanceNamed("spine")->id));

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

TEST(GuideEdits, RefusedEditsChangeNothing)
{
    model::GuideDocument doc = test::loadSample("biped");
    const model::GuideDocument original = doc;
    edit::History history(doc);
    const model::InstanceId spine = doc.instanceNamed("spine")->id;
    EXPECT_EQ(edit::renameInstance(history, spine, "neck"), "an instance named 'neck' already exists");
    EXPECT_EQ(edit::renameInstance(history, spine, "2spine"),
              "'2spine' is not a valid name (letters, digits and _, not starting with a digit)");
    EXPECT_EQ(edit::setOption(history, spine, "number", std::string("many"), 3LL), "option 'number' takes a int, not a string");
    EXPECT_EQ(edit::removeInstance(history, 999), "no instance with id 999");
    EXPECT_EQ(history.size(), 0u);
    EXPECT_EQ(doc, original);
}

TEST(GuideEdits, SettingTheDefaultValueRemovesTheStoredOption)
{
    model::GuideDocument doc = test::loadChains();
    edit::History history(doc);
    const model::InstanceId spine = doc.instanceNamed("spine")->id;
    ASSERT_TRUE(doc.instance(spine)->options.count("number"));
    EXPECT_FALSE(edit::setOption(history, spine, "number", 3LL, 3LL));
    EXPECT_FALSE(doc.instance(spine)->options.count("number"));
    history.undo();
    EXPECT_EQ(doc.instance(spine)->options.at("number"), Value(4LL));
}

TEST(GuideEdits, NewInstancesGetFreshIdsAUniqueNameAndDefaultJoints)
{
    model::GuideDocument doc = test::loadSample("biped");
    const auto* neck = doc.instanceNamed("neck");
    auto a = build::makeInstance(doc, test::builtinTemplates(), "core.joints", neck->joints.back().id);
    ASSERT_TRUE(a.ok());
    EXPECT_EQ(a->name, "joints");
    EXPECT_EQ(a->joints.size(), 3u) << "the manifest's guides.number default";
    EXPECT_EQ(a->parent, neck->id);
    EXPECT_EQ(a->joints.front().id, doc.nextJointId());
    edit::History history(doc);
    ASSERT_FALSE(edit::addInstance(history, a.take()));
    auto b = build::makeInstance(doc, test::builtinTemplates(), "core.joints", model::kNoId);
    ASSERT_TRUE(b.ok());
    EXPECT_EQ(b->name, "joints1");
    EXPECT_FALSE(build::makeInstance(doc, test::builtinTemplates(), "no.such", model::kNoId).ok());
}
