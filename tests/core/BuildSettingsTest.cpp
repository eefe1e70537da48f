// Issue 23 item 2: the guide's build settings (restore toggles, cleanup) are
// saved with the guide only when changed, read back with clear errors, and
// edited in the session as undoable steps with a typed change event.
#include "TestSupport.h"
#include "core/StartedSession.h"

#include "io/GuideFile.h"
#include "session/Session.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace rs;
using edit::Change;
using edit::ChangeKind;

TEST(BuildSettings, AreSavedInTheGuideOnlyWhenChangedAndSurviveAReopen)
{
    model::GuideDocument guide = test::loadSample("biped");
    const std::string before = io::writeGuideText(guide);
    EXPECT_EQ(before.find("build:"), std::string::npos) << "a guide that never changed them is written as before";
    EXPECT_EQ(before, test::readText(test::samplePath("biped")));
    guide.build.cleanup = true;
    guide.build.restore.set(model::OverrideKind::Shapes, false);
    guide.build.restore.set(model::OverrideKind::Pose, false);
    const std::string text = io::writeGuideText(guide);
    EXPECT_NE(text.find("build:\n  cleanup: on\n  no_restore: [shapes, pose]\n"), std::string::npos) << text;
    auto reopened = io::readGuideText(text, "settings.yml");
    ASSERT_TRUE(reopened.ok()) << formatAll(reopened.diagnostics());
    EXPECT_EQ(reopened->build, guide.build);
    EXPECT_EQ(io::writeGuideText(*reopened), text) << "byte-identical round trip";
    // Only the restore toggles: no cleanup line.
    guide.build.cleanup = false;
    const std::string restoreOnly = io::writeGuideText(guide);
    EXPECT_NE(restoreOnly.find("build:\n  no_restore: [shapes, pose]\n"), std::string::npos) << restoreOnly;
    auto again = io::readGuideText(restoreOnly, "settings.yml");
    ASSERT_TRUE(again.ok()) << formatAll(again.diagnostics());
    EXPECT_EQ(again->build, guide.build);
}

TEST(BuildSettings, AnUnknownKindOrABadValueIsAnErrorAtItsLine)
{
    const std::string guide = io::writeGuideText(test::loadSample("prop"));
    const auto lines = std::count(guide.begin(), guide.end(), '\n');
    auto bad = io::readGuideText(guide + "build:\n  cleanup: on\n  no_restore: [shapes, colours]\n", "bad.yml");
    ASSERT_FALSE(bad.ok());
    const std::string log = formatAll(bad.diagnostics());
    EXPECT_NE(log.find("bad.yml:" + std::to_string(lines + 3) + ":"), std::string::npos) << log;
    EXPECT_NE(log.find("error: unknown override kind 'colours' in build: no_restore (known: shapes, defaults, limits, locks, "
                       "post, names, pose)"),
              std::string::npos) << log;
    auto notBool = io::readGuideText(guide + "build:\n  cleanup: maybe\n", "bad.yml");
    ASSERT_FALSE(notBool.ok());
    EXPECT_NE(formatAll(notBool.diagnostics()).find("bad.yml:" + std::to_string(lines + 2) + ":"), std::string::npos)
        << formatAll(notBool.diagnostics());
    auto unknown = io::readGuideText(guide + "build:\n  tidy: on\n", "odd.yml");
    ASSERT_TRUE(unknown.ok()) << "an unknown key only warns";
    EXPECT_NE(formatAll(unknown.diagnostics()).find("warning: unknown key 'tidy' in build"), std::string::npos);
}

namespace {

using Started = test::StartedSession;

} // namespace

TEST(BuildSettings, TheSessionsTogglesAreUndoableStepsWithATypedChange)
{
    Started t;
    const NodeKey fk = t.node("arm.L::ctrls.fk.0").key;
    model::Override record;
    record.displayName = "upperarm_ctl_L";
    ASSERT_TRUE(test::succeeded(t.s.setOverride(fk, record)));
    const std::size_t steps = t.s.history().size();
    model::RestoreToggles restore;
    restore.set(model::OverrideKind::Names, false);
    ASSERT_TRUE(test::succeeded(t.s.setRestore(restore)));
    EXPECT_EQ(t.s.history().size(), steps + 1);
    EXPECT_EQ(t.s.history().undoText(), "Do not restore names on build");
    ASSERT_FALSE(t.changes.empty());
    EXPECT_TRUE(t.changes.back().has(ChangeKind::Build));
    EXPECT_TRUE(t.changes.back().has(ChangeKind::Rig)) << "the rig is built again";
    EXPECT_NE(t.node("arm.L::ctrls.fk.0").name, "upperarm_ctl_L");
    EXPECT_FALSE(t.s.document().build.restore.restores(model::OverrideKind::Names)) << "kept in the guide";
    EXPECT_TRUE(t.s.setRestore(restore).failed()) << "no empty step";
    EXPECT_EQ(t.s.history().size(), steps + 1);

    ASSERT_TRUE(test::succeeded(t.s.setCleanup(true)));
    EXPECT_EQ(t.s.history().undoText(), "Clean up on build");
    EXPECT_TRUE(t.changes.back().has(ChangeKind::Build));
    EXPECT_TRUE(t.node("arm.L::ctrls.fk.0").channels.isLocked(0));
    EXPECT_TRUE(t.node("arm.L::skin.limb.0").hidden);

    t.s.history().undo();
    EXPECT_FALSE(t.s.cleanup());
    EXPECT_FALSE(t.node("arm.L::ctrls.fk.0").channels.isLocked(0));
    EXPECT_TRUE(t.changes.back().has(ChangeKind::Build));
    t.s.history().undo();
    EXPECT_TRUE(t.s.restore().restores(model::OverrideKind::Names));
    EXPECT_EQ(t.node("arm.L::ctrls.fk.0").name, "upperarm_ctl_L");
    t.s.history().redo();
    t.s.history().redo();
    EXPECT_TRUE(t.s.cleanup());

    // Saved and reopened, the settings come back.
    auto reopened = io::readGuideText(io::writeGuideText(t.s.document()), "saved.yml");
    ASSERT_TRUE(reopened.ok()) << formatAll(reopened.diagnostics());
    EXPECT_EQ(reopened->build, t.s.document().build);
}

TEST(BuildSettings, ATestPoseOnAChannelCleanupLocksIsKeptUntilCleanupIsOff)
{
    Started t;
    const NodeKey fk = t.node("arm.L::ctrls.fk.0").key;
    model::Override record;
    record.pose = {{"tx", 0.05}};
    ASSERT_TRUE(test::succeeded(t.s.setOverride(fk, record)));
    auto channel = [&](const std::string& name) { return *t.s.program()->channels().find(*t.s.rig()->find(fk), name); };
    EXPECT_EQ(t.s.pose()[channel("tx")], 0.05);
    ASSERT_TRUE(test::succeeded(t.s.setCleanup(true)));
    EXPECT_EQ(t.s.pose()[channel("tx")], 0.0) << "locked by cleanup: at its default";
    ASSERT_TRUE(test::succeeded(t.s.setChannel(channel("rx"), 10.0, false))); // a pose edit writes the pose back
    const auto& pose = t.s.document().overrides.at(fk).pose;
    EXPECT_EQ(pose.at("rx"), 10.0);
    ASSERT_TRUE(pose.count("tx")) << "the locked channel's value stays in the guide";
    EXPECT_EQ(pose.at("tx"), 0.05);
    ASSERT_TRUE(test::succeeded(t.s.setCleanup(false)));
    EXPECT_EQ(t.s.pose()[channel("tx")], 0.05);
}
