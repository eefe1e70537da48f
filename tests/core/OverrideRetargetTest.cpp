// The Overrides panel's and the channel box's session commands: edits on the
// selected channels of several controllers as one undo step, orphans with
// their reason, re-targeting a record onto another node, deleting orphans.
#include "TestSupport.h"

#include "eval/Channels.h"
#include "session/Session.h"

#include <gtest/gtest.h>

using namespace rs;
using Edit = session::Session::ChannelEdit;

namespace {

const NodeKey kFkL{4, "L", "ctrls.fk.0"};
const NodeKey kFkR{4, "R", "ctrls.fk.0"};

struct Started {
    session::Session s{std::make_shared<templates::TemplateRegistry>(test::builtinTemplates())};
    Started()
    {
        s.replaceDocument(test::loadSample("biped"));
        s.build();
    }
    int channel(const NodeKey& key, const std::string& name) const
    {
        return *s.program()->channels().find(*s.rig()->find(key), name);
    }
    const model::RigNode& node(const NodeKey& key) const { return s.rig()->nodes[*s.rig()->find(key)]; }
};

} // namespace

TEST(OverrideSession, ChannelEditsOnSeveralControllersAreOneUndoStep)
{
    Started t;
    ASSERT_TRUE(t.s.rig()->find(kFkR));
    const std::vector<int> rotations{t.channel(kFkL, "rx"), t.channel(kFkL, "ry"), t.channel(kFkR, "rx"), t.channel(kFkR, "ry")};
    const std::size_t steps = t.s.history().size();
    ASSERT_TRUE(test::succeeded(t.s.editChannels(rotations, Edit::Lock)));
    EXPECT_EQ(t.s.history().size(), steps + 1);
    EXPECT_EQ(t.s.history().undoText(), "Lock 4 channels");
    for (const NodeKey& key : {kFkL, kFkR}) {
        EXPECT_TRUE(t.node(key).channels.isLocked(3));
        EXPECT_TRUE(t.node(key).channels.isLocked(4));
        EXPECT_FALSE(t.node(key).channels.isLocked(5));
        EXPECT_TRUE(t.s.document().overrides.at(key).locks.at("rx").locked);
    }
    ASSERT_TRUE(test::succeeded(t.s.editChannels(rotations, Edit::NonKeyable)));
    EXPECT_FALSE(t.s.program()->channels()[t.channel(kFkR, "ry")].keyable);
    EXPECT_TRUE(t.s.program()->channels()[t.channel(kFkR, "ry")].locked) << "the lock stays";
    ASSERT_TRUE(test::succeeded(t.s.editChannels(rotations, Edit::Limit, model::ChannelLimit{-30.0, 45.0})));
    EXPECT_EQ(t.s.document().overrides.at(kFkR).limits.at("ry"), (model::ChannelLimit{-30.0, 45.0}));
    EXPECT_TRUE(t.node(kFkL).channels.isLimited(3));
    EXPECT_EQ(t.s.history().size(), steps + 3);
    t.s.history().undo(); // the limits
    t.s.history().undo(); // keyable
    t.s.history().undo(); // the locks, all four at once
    EXPECT_FALSE(t.s.document().overrides.count(kFkL));
    EXPECT_FALSE(t.node(kFkR).channels.isLocked(3));
    // A bad limit changes nothing.
    EXPECT_TRUE(t.s.editChannels(rotations, Edit::Limit, model::ChannelLimit{5.0, -5.0}).failed());
    EXPECT_FALSE(t.s.document().overrides.count(kFkL));
}

TEST(OverrideSession, SetAsDefaultAndResetOnManyChannels)
{
    Started t;
    const int l = t.channel(kFkL, "rz"), r = t.channel(kFkR, "rz");
    ASSERT_TRUE(test::succeeded(t.s.setChannel(l, 20.0, false)));
    ASSERT_TRUE(test::succeeded(t.s.setChannel(r, -15.0, false)));
    const std::size_t steps = t.s.history().size();
    ASSERT_TRUE(test::succeeded(t.s.editChannels({l, r}, Edit::SetDefault)));
    EXPECT_EQ(t.s.history().size(), steps + 1);
    EXPECT_EQ(t.s.document().overrides.at(kFkL).defaults.at("rz"), 20.0);
    EXPECT_EQ(t.s.document().overrides.at(kFkR).defaults.at("rz"), -15.0);
    ASSERT_TRUE(test::succeeded(t.s.setChannel(l, 0.0, false)));
    ASSERT_TRUE(test::succeeded(t.s.setChannel(r, 0.0, false)));
    ASSERT_TRUE(test::succeeded(t.s.resetChannelsToDefault({l, r})));
    EXPECT_EQ(t.s.pose()[l], 20.0);
    EXPECT_EQ(t.s.pose()[r], -15.0);
    EXPECT_EQ(t.s.history().undoText(), "Reset 2 channels");
}

TEST(OverrideSession, AnOrphanHasAReasonAndIsRetargetedInOneStep)
{
    Started t;
    const NodeKey gone{4, "L", "ctrls.fk.9"};
    model::Override record;
    record.limits = {{"rx", {-5.0, 5.0}}};
    record.displayName = "moved_ctl_L";
    ASSERT_TRUE(test::succeeded(t.s.setOverride(gone, record)));
    const auto reason = t.s.orphanReason(gone);
    ASSERT_TRUE(reason);
    EXPECT_NE(reason->find("ctrls.fk.9"), std::string::npos) << *reason;
    EXPECT_FALSE(t.s.orphanReason(kFkL)) << "a node the rig makes is no orphan";
    EXPECT_TRUE(t.s.orphanReason(NodeKey{77, "", "ctrls.x"})->find("no longer exists") != std::string::npos);

    model::Override existing;
    existing.limits = {{"ry", {-1.0, 1.0}}};
    ASSERT_TRUE(test::succeeded(t.s.setOverride(kFkL, existing)));
    const std::size_t steps = t.s.history().size();
    ASSERT_TRUE(test::succeeded(t.s.retargetOverride(gone, kFkL)));
    EXPECT_EQ(t.s.history().size(), steps + 1);
    EXPECT_FALSE(t.s.document().overrides.count(gone));
    const model::Override& moved = t.s.document().overrides.at(kFkL);
    EXPECT_EQ(moved.limits.at("rx"), (model::ChannelLimit{-5.0, 5.0}));
    EXPECT_EQ(moved.limits.at("ry"), (model::ChannelLimit{-1.0, 1.0})) << "the target's own kinds are kept";
    EXPECT_EQ(t.node(kFkL).name, "moved_ctl_L");
    t.s.history().undo();
    EXPECT_TRUE(t.s.document().overrides.count(gone));
    EXPECT_EQ(t.s.document().overrides.at(kFkL), existing);
}

TEST(OverrideSession, RetargetRefusesWhatCannotMove)
{
    Started t;
    const NodeKey gone{4, "L", "ctrls.fk.9"};
    EXPECT_NE(test::refusal(t.s.retargetOverride(gone, kFkL)), "") << "no record";
    model::Override record;
    record.displayName = "x_ctl";
    ASSERT_TRUE(test::succeeded(t.s.setOverride(gone, record)));
    EXPECT_NE(test::refusal(t.s.retargetOverride(gone, NodeKey{4, "L", "ctrls.nothing"})), "");
    EXPECT_NE(test::refusal(t.s.retargetOverride(gone, gone)), "");
    model::Override post;
    post.post = Transform{};
    post.post->scale = Vec3(2.0);
    ASSERT_TRUE(test::succeeded(t.s.setOverride(model::rigRootKey(), post)));
    EXPECT_NE(test::refusal(t.s.retargetOverride(model::rigRootKey(), kFkL)), "");
    EXPECT_TRUE(t.s.document().overrides.count(gone));
}

TEST(OverrideSession, DeletingAllOrphansIsOneStep)
{
    Started t;
    model::Override record;
    record.displayName = "a_ctl";
    ASSERT_TRUE(test::succeeded(t.s.setOverride(NodeKey{4, "L", "ctrls.fk.8"}, record)));
    record.displayName = "b_ctl";
    ASSERT_TRUE(test::succeeded(t.s.setOverride(NodeKey{4, "L", "ctrls.fk.9"}, record)));
    const std::size_t steps = t.s.history().size();
    ASSERT_TRUE(test::succeeded(t.s.setOverrides({{{4, "L", "ctrls.fk.8"}, {}}, {{4, "L", "ctrls.fk.9"}, {}}}, "Delete all orphans")));
    EXPECT_EQ(t.s.history().size(), steps + 1);
    EXPECT_EQ(t.s.history().undoText(), "Delete all orphans");
    EXPECT_FALSE(t.s.document().overrides.count(NodeKey{4, "L", "ctrls.fk.8"}));
    EXPECT_NE(test::refusal(t.s.setOverrides({{{4, "L", "ctrls.fk.8"}, {}}}, "x")), "");
}
