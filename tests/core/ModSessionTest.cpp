// Mod commands of the session: adding, editing and removing a mod are one undo
// step each with a typed change event (Mods, naming the owner instance), and the
// live rig follows.
#include "ModsTestSupport.h"
#include "core/StartedSession.h"

#include "edit/ModEdits.h"
#include "session/Session.h"

#include <gtest/gtest.h>

using namespace rs;
using edit::Change;
using edit::ChangeKind;

namespace {

using Started = test::StartedSession;

} // namespace

TEST(Mods, SessionAddsEditsAndRemovesAModAsUndoableStepsAndTheRigFollows)
{
    Started t;
    const model::Mod hide = test::modFromText(t.s.document(), "arm", "hide: [ctrls.pole]");
    ASSERT_TRUE(test::succeeded(t.s.addMod(hide)));
    ASSERT_EQ(t.s.document().mods.size(), 1u);
    ASSERT_FALSE(t.changes.empty());
    EXPECT_TRUE(t.changes.back().has(ChangeKind::Mods));
    EXPECT_TRUE(t.changes.back().has(ChangeKind::Rig)); // rebuilt at once
    EXPECT_EQ(t.changes.back().instances, (std::vector<model::InstanceId>{4}));
    EXPECT_TRUE(t.node("arm.L::ctrls.pole").hidden);
    EXPECT_EQ(t.s.history().undoText(), "Add hide mod");

    const model::Mod other = test::modFromText(t.s.document(), "arm", "hide: [ctrls.pin]");
    ASSERT_TRUE(test::succeeded(t.s.setMod(0, other)));
    EXPECT_FALSE(t.node("arm.L::ctrls.pole").hidden);
    EXPECT_TRUE(t.node("arm.R::ctrls.pin").hidden);
    EXPECT_EQ(t.s.history().undoText(), "Edit hide mod");
    const std::size_t steps = t.s.history().size();
    EXPECT_TRUE(test::succeeded(t.s.setMod(0, other))); // no change: no step
    EXPECT_EQ(t.s.history().size(), steps);

    ASSERT_TRUE(test::succeeded(t.s.removeMod(0)));
    EXPECT_TRUE(t.s.document().mods.empty());
    EXPECT_FALSE(t.node("arm.R::ctrls.pin").hidden);
    t.s.history().undo();
    EXPECT_EQ(t.s.document().mods, std::vector<model::Mod>{other});
    EXPECT_TRUE(t.node("arm.R::ctrls.pin").hidden);
    t.s.history().undo();
    t.s.history().undo();
    EXPECT_TRUE(t.s.document().mods.empty());
    EXPECT_FALSE(t.node("arm.L::ctrls.pole").hidden);
}

TEST(Mods, SessionRefusesAMalformedModOrAnIndexPastTheEnd)
{
    Started t;
    model::Mod bad;
    bad.settings = model::HideMod{};
    EXPECT_FALSE(test::refusal(t.s.addMod(bad)).empty());
    model::DriveMod unsorted;
    unsorted.driver.tag = unsorted.driven.tag = "rig";
    unsorted.driver.channel = "x";
    unsorted.driven.channel = "y";
    unsorted.keys = {{1.0, 0.0}, {0.0, 1.0}};
    bad.settings = unsorted;
    EXPECT_NE(test::refusal(t.s.addMod(bad)).find("sorted"), std::string::npos);
    EXPECT_FALSE(test::refusal(t.s.removeMod(3)).empty());
    EXPECT_FALSE(test::refusal(t.s.setMod(0, test::modFromText(t.s.document(), "", "hide: ['arm.L::ctrls.pin']"))).empty());
    EXPECT_TRUE(t.s.document().mods.empty());
    EXPECT_EQ(t.s.history().size(), 0u);
}
