// Override commands of the session: each is one undo step with a typed
// change event, the live rig follows, and the channel box's "set as default",
// "reset to default", "lock" and "limit" land in the guide's overrides.
#include "TestSupport.h"
#include "core/StartedSession.h"

#include "edit/OverrideEdits.h"
#include "eval/Channels.h"
#include "session/Session.h"

#include <gtest/gtest.h>

using namespace rs;
using edit::Change;
using edit::ChangeKind;

namespace {

const NodeKey kFk{4, "L", "ctrls.fk.0"};

struct Started : test::StartedSession {
    int channel(const std::string& name) const
    {
        return *s.program()->channels().find(*s.rig()->find(kFk), name);
    }
    const model::RigNode& fk() const { return s.rig()->nodes[*s.rig()->find(kFk)]; }
};

} // namespace

TEST(OverrideSession, SettingAndRemovingAnOverrideIsOneUndoStepWithATypedChange)
{
    Started t;
    model::Override record;
    record.displayName = "upperarm_ctl_L";
    record.limits = {{"rx", {-20.0, 20.0}}};
    const std::size_t steps = t.s.history().size();
    ASSERT_TRUE(test::succeeded(t.s.setOverride(kFk, record, "Name upper arm")));
    EXPECT_EQ(t.s.history().size(), steps + 1);
    EXPECT_EQ(t.s.history().undoText(), "Name upper arm");
    ASSERT_FALSE(t.changes.empty());
    EXPECT_TRUE(t.changes.back().has(ChangeKind::Overrides));
    EXPECT_FALSE(t.changes.back().has(ChangeKind::Shapes));
    EXPECT_EQ(t.changes.back().instances, std::vector<model::InstanceId>{4});
    EXPECT_TRUE(t.changes.back().has(ChangeKind::Rig)) << "the live rig follows";
    EXPECT_EQ(t.fk().name, "upperarm_ctl_L");
    EXPECT_TRUE(t.fk().channels.isLimited(3));
    // The same record again: no step.
    ASSERT_TRUE(test::succeeded(t.s.setOverride(kFk, record)));
    EXPECT_EQ(t.s.history().size(), steps + 1);
    ASSERT_TRUE(test::succeeded(t.s.removeOverride(kFk)));
    EXPECT_EQ(t.s.history().size(), steps + 2);
    EXPECT_FALSE(t.s.document().overrides.count(kFk));
    EXPECT_NE(t.fk().name, "upperarm_ctl_L");
    t.s.history().undo();
    EXPECT_EQ(t.s.document().overrides.at(kFk), record);
    EXPECT_EQ(t.fk().name, "upperarm_ctl_L");
}

TEST(OverrideSession, ABadRecordIsRefusedAndChangesNothing)
{
    Started t;
    const model::GuideDocument before = t.s.document();
    model::Override bad;
    bad.limits = {{"rx", {20.0, -20.0}}};
    EXPECT_EQ(test::refusal(t.s.setOverride(kFk, bad)), "the limits of 'rx' need finite min <= max");
    model::Override post;
    post.post = Transform{};
    EXPECT_EQ(test::refusal(t.s.setOverride(kFk, post)), "a post transform belongs to the rig root");
    EXPECT_EQ(t.s.document(), before);
}

TEST(OverrideSession, TheChannelBoxSetsResetsLocksAndLimitsThroughOverrides)
{
    Started t;
    const int rz = t.channel("rz");
    ASSERT_TRUE(test::succeeded(t.s.setChannel(rz, 25.0, false)));
    EXPECT_EQ(t.s.document().overrides.at(kFk).pose.at("rz"), 25.0);
    // Set as default: the value becomes what reset returns to; the test pose drops it.
    const std::size_t steps = t.s.history().size();
    ASSERT_TRUE(test::succeeded(t.s.setChannelAsDefault(rz)));
    EXPECT_EQ(t.s.history().size(), steps + 1);
    EXPECT_EQ(t.s.document().overrides.at(kFk).defaults.at("rz"), 25.0);
    EXPECT_FALSE(t.s.document().overrides.at(kFk).pose.count("rz"));
    EXPECT_EQ(t.s.program()->channels()[t.channel("rz")].defaultValue, 25.0);
    EXPECT_EQ(t.s.pose()[t.channel("rz")], 25.0) << "the pose shows the default";
    // Moved, then reset to the default.
    ASSERT_TRUE(test::succeeded(t.s.setChannel(t.channel("rz"), -5.0, false)));
    ASSERT_TRUE(test::succeeded(t.s.resetChannelToDefault(t.channel("rz"))));
    EXPECT_EQ(t.s.pose()[t.channel("rz")], 25.0);
    EXPECT_FALSE(t.s.document().overrides.at(kFk).pose.count("rz"));
    // Lock: the channel refuses edits; unlock frees it.
    ASSERT_TRUE(test::succeeded(t.s.setChannelLocked(t.channel("tx"), true)));
    EXPECT_TRUE(t.fk().channels.isLocked(0));
    EXPECT_TRUE(t.s.setChannel(t.channel("tx"), 0.1, false).failed());
    ASSERT_TRUE(test::succeeded(t.s.setChannelLocked(t.channel("tx"), false)));
    EXPECT_FALSE(t.fk().channels.isLocked(0));
    // Limit: values clamp.
    ASSERT_TRUE(test::succeeded(t.s.setChannelLimit(t.channel("rx"), model::ChannelLimit{-10.0, 10.0})));
    ASSERT_TRUE(test::succeeded(t.s.setChannel(t.channel("rx"), 50.0, false)));
    EXPECT_EQ(t.s.pose()[t.channel("rx")], 10.0);
    ASSERT_TRUE(test::succeeded(t.s.setChannelLimit(t.channel("rx"), std::nullopt)));
    EXPECT_FALSE(t.fk().channels.isLimited(3));
}

TEST(OverrideSession, RestoreTogglesRebuildWithoutAKind)
{
    Started t;
    model::Override record;
    record.displayName = "upperarm_ctl_L";
    ASSERT_TRUE(test::succeeded(t.s.setOverride(kFk, record)));
    model::RestoreToggles restore;
    restore.set(model::OverrideKind::Names, false);
    t.s.setRestore(restore);
    EXPECT_NE(t.fk().name, "upperarm_ctl_L");
    EXPECT_TRUE(t.s.document().overrides.count(kFk)) << "the record stays";
    t.s.setRestore({});
    EXPECT_EQ(t.fk().name, "upperarm_ctl_L");
}
