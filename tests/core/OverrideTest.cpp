// Issue 23 step 1: one override model. Every kind of override (shape, default
// values, limits, locks, post transform, display name, test pose) is applied by
// the build, survives a rebuild, an unrelated option, an instance rename and a
// save / reopen; each restore toggle turns its kind off; an orphan is reported,
// kept and applied again when its node comes back.
#include "TestSupport.h"

#include "edit/GuideEdits.h"
#include "eval/Channels.h"
#include "io/GuideFile.h"
#include "rigging/RigBuilder.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

constexpr model::InstanceId kWorld = 1, kArm = 4;
const NodeKey kFk{kArm, "L", "ctrls.fk.0"};
const NodeKey kIkShape{kArm, {}, "ctrls.ik"}; // the authored side: both copies show it

// The biped with one record of every kind.
model::GuideDocument overriddenBiped()
{
    model::GuideDocument guide = test::loadSample("biped");
    EXPECT_EQ(guide.instance(kArm)->name, "arm");
    model::Override& fk = guide.overrides[kFk];
    fk.defaults = {{"rz", 15.0}, {"ry", 5.0}};
    fk.limits = {{"rx", {-30.0, 60.0}}};
    fk.locks = {{"ty", {true, true}}, {"tz", {false, false}}};
    fk.displayName = "upperarm_ctl_L";
    fk.pose = {{"ry", 10.0}};
    model::ShapeOverride& shape = guide.overrides[kIkShape].shape.emplace();
    shape.edit.transform.scale = Vec3(2.0);
    shape.color = Vec3(1.0, 0.0, 0.0);
    shape.lineWidth = 3.0;
    Transform post;
    post.translate = Vec3(0.0, 0.0, 1.0);
    post.scale = Vec3(2.0);
    guide.overrides[model::rigRootKey()].post = post;
    guide.overrides[{kWorld, {}, "ctrls.fly"}].shape.emplace().visible = false;
    return guide;
}

model::Rig build(const model::GuideDocument& guide, const model::RestoreToggles& restore = {})
{
    model::Rig rig = rigging::buildRig(guide, test::builtinTemplates(), rigging::BuilderRegistry::builtin(), {}, nullptr, restore);
    EXPECT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    return rig;
}

const model::RigNode& at(const model::Rig& rig, const NodeKey& key)
{
    static const model::RigNode none;
    const auto index = rig.find(key);
    EXPECT_TRUE(index) << key.tag;
    return index ? rig.nodes[*index] : none;
}

// Which kinds the rig shows, against `plain` (the same guide without overrides).
struct Seen {
    bool shapes, defaults, limits, locks, post, names;
};

Seen seenOf(const model::Rig& rig, const model::Rig& plain)
{
    const model::RigNode& fk = at(rig, kFk);
    const model::RigNode& ik = at(rig, {kArm, "L", "ctrls.ik"});
    const model::RigNode& plainIk = at(plain, {kArm, "L", "ctrls.ik"});
    const eval::ChannelLayout layout(rig);
    const auto rz = layout.find(*rig.find(kFk), "rz");
    Seen s{};
    s.shapes = ik.curves.size() == plainIk.curves.size() && ik.curves[0].color == Vec3(1.0, 0.0, 0.0) &&
               ik.curves[0].lineWidth == 3.0 &&
               glm::length(ik.curves[0].points[0] - 2.0 * plainIk.curves[0].points[0]) < 1e-9 &&
               at(rig, {kArm, "R", "ctrls.ik"}).curves[0].lineWidth == 3.0 && // the mirrored copy follows
               !at(rig, {kWorld, {}, "ctrls.fly"}).curves[0].visible;
    s.defaults = fk.channels.defaults[5] == 15.0 && fk.channels.defaults[4] == 5.0 && rz && layout[*rz].defaultValue == 15.0;
    s.limits = fk.channels.isLimited(3) && fk.channels.minimum[3] == -30.0 && fk.channels.maximum[3] == 60.0;
    s.locks = fk.channels.isLocked(1) && !fk.channels.isKeyable(2) && !fk.channels.isLocked(2);
    s.post = maxAbsDifference(rig.nodes[0].worldMatrix, glm::translate(Mat4(1.0), Vec3(0, 0, 1)) * glm::scale(Mat4(1.0), Vec3(2.0))) < 1e-12 &&
             maxAbsDifference(fk.worldMatrix, rig.nodes[0].worldMatrix * at(plain, kFk).worldMatrix) < 1e-9;
    s.names = fk.name == "upperarm_ctl_L";
    return s;
}

void expectEveryKind(const model::GuideDocument& guide, const std::string& when)
{
    model::GuideDocument bare = guide;
    bare.overrides.clear();
    const Seen s = seenOf(build(guide), build(bare));
    EXPECT_TRUE(s.shapes) << when;
    EXPECT_TRUE(s.defaults) << when;
    EXPECT_TRUE(s.limits) << when;
    EXPECT_TRUE(s.locks) << when;
    EXPECT_TRUE(s.post) << when;
    EXPECT_TRUE(s.names) << when;
    const auto pose = rigging::restoredPose(guide, {});
    const std::map<std::string, double> expected{{"ry", 10.0}};
    ASSERT_TRUE(pose.count(kFk)) << when;
    EXPECT_EQ(pose.at(kFk), expected) << when;
}

} // namespace

TEST(Overrides, EveryKindSurvivesARebuildAnUnrelatedOptionARenameAndASaveReopen)
{
    model::GuideDocument guide = overriddenBiped();
    edit::History history(guide);
    expectEveryKind(guide, "first build");
    expectEveryKind(guide, "rebuild");
    const model::InstanceId head = guide.instanceNamed("neck")->id;
    ASSERT_TRUE(test::succeeded(edit::setOption(history, head, "head_space", Value(std::string("world")), Value(std::string("neck")))));
    expectEveryKind(guide, "an unrelated option");
    ASSERT_TRUE(test::succeeded(edit::renameInstance(history, kArm, "limb")));
    expectEveryKind(guide, "the arm renamed");
    const std::string text = io::writeGuideText(guide);
    auto reopened = io::readGuideText(text, "overrides.yml");
    ASSERT_TRUE(reopened.ok()) << formatAll(reopened.diagnostics());
    EXPECT_EQ(reopened->overrides, guide.overrides);
    EXPECT_EQ(io::writeGuideText(*reopened), text) << "byte-identical round trip";
    expectEveryKind(*reopened, "saved and reopened");
}

TEST(Overrides, EachRestoreToggleTurnsItsKindOff)
{
    const model::GuideDocument guide = overriddenBiped();
    model::GuideDocument bare = guide;
    bare.overrides.clear();
    const model::Rig plain = build(bare);
    using K = model::OverrideKind;
    for (K kind : {K::Shapes, K::Defaults, K::Limits, K::Locks, K::Post, K::Names, K::Pose}) {
        model::RestoreToggles restore;
        restore.set(kind, false);
        const Seen s = seenOf(build(guide, restore), plain);
        const std::string name = model::overrideKindName(kind);
        EXPECT_EQ(s.shapes, kind != K::Shapes) << name;
        EXPECT_EQ(s.defaults, kind != K::Defaults) << name;
        EXPECT_EQ(s.limits, kind != K::Limits) << name;
        EXPECT_EQ(s.locks, kind != K::Locks) << name;
        EXPECT_EQ(s.post, kind != K::Post) << name;
        EXPECT_EQ(s.names, kind != K::Names) << name;
        EXPECT_EQ(rigging::restoredPose(guide, restore).empty(), kind == K::Pose) << name;
    }
    // Off, a kind builds as the templates make it.
    model::RestoreToggles none;
    for (int k = 0; k < model::kOverrideKindCount; ++k)
        none.set(static_cast<K>(k), false);
    const model::Rig off = build(guide, none);
    EXPECT_EQ(at(off, kFk).name, at(plain, kFk).name);
    EXPECT_EQ(at(off, kFk).channels, at(plain, kFk).channels);
    EXPECT_EQ(off.nodes[0].worldMatrix, plain.nodes[0].worldMatrix);
}

TEST(Overrides, TheGuidesRestoreTogglesTurnEachKindOffAndSurviveASaveReopen)
{
    const model::GuideDocument authored = overriddenBiped();
    model::GuideDocument bare = authored;
    bare.overrides.clear();
    const model::Rig plain = build(bare);
    using K = model::OverrideKind;
    for (K kind : {K::Shapes, K::Defaults, K::Limits, K::Locks, K::Post, K::Names, K::Pose}) {
        model::GuideDocument guide = authored;
        guide.build.restore.set(kind, false);
        auto reopened = io::readGuideText(io::writeGuideText(guide), "toggles.yml");
        ASSERT_TRUE(reopened.ok()) << formatAll(reopened.diagnostics());
        ASSERT_EQ(reopened->build, guide.build);
        // The build overloads without toggles take the guide's.
        const model::Rig rig = rigging::buildRig(*reopened, test::builtinTemplates());
        const Seen s = seenOf(rig, plain);
        const std::string name = model::overrideKindName(kind);
        EXPECT_EQ(s.shapes, kind != K::Shapes) << name;
        EXPECT_EQ(s.defaults, kind != K::Defaults) << name;
        EXPECT_EQ(s.limits, kind != K::Limits) << name;
        EXPECT_EQ(s.locks, kind != K::Locks) << name;
        EXPECT_EQ(s.post, kind != K::Post) << name;
        EXPECT_EQ(s.names, kind != K::Names) << name;
        EXPECT_EQ(rigging::restoredPose(*reopened, reopened->build.restore).empty(), kind == K::Pose) << name;
    }
}

TEST(Overrides, AnOrphanIsReportedKeptAndAppliedAgainWhenItsNodeComesBack)
{
    model::GuideDocument guide = overriddenBiped();
    edit::History history(guide);
    const NodeKey fly{kWorld, {}, "ctrls.fly"};
    guide.overrides[fly].displayName = "fly_ctl";
    guide.overrides[fly].defaults = {{"ty", 0.5}};
    const model::Override record = guide.overrides.at(fly);
    // The template option removes the control: the record is an orphan.
    ASSERT_TRUE(test::succeeded(edit::setOption(history, kWorld, "do_fly", Value(false), Value(true))));
    const model::Rig without = build(guide);
    ASSERT_FALSE(without.find(fly));
    const std::string log = formatAll(without.diagnostics);
    EXPECT_NE(log.find("warning: orphan override of 'world::ctrls.fly' (shapes, defaults, names): the rig has no such node; "
                       "it is kept in the guide and applied again if the node comes back"),
              std::string::npos) << log;
    const auto orphan = std::find_if(without.diagnostics.begin(), without.diagnostics.end(),
                                     [](const Diagnostic& d) { return d.message.find("ctrls.fly") != std::string::npos; });
    ASSERT_NE(orphan, without.diagnostics.end());
    EXPECT_EQ(orphan->subject, Subject::ofInstance(kWorld));
    // Kept in the document and in the file.
    EXPECT_EQ(guide.overrides.at(fly), record);
    auto reopened = io::readGuideText(io::writeGuideText(guide), "orphan.yml");
    ASSERT_TRUE(reopened.ok()) << formatAll(reopened.diagnostics());
    ASSERT_TRUE(reopened->overrides.count(fly));
    EXPECT_EQ(reopened->overrides.at(fly), record);
    // The option restored: the control is back with its overrides.
    ASSERT_TRUE(test::succeeded(edit::setOption(history, kWorld, "do_fly", Value(true), Value(true))));
    const model::Rig back = build(guide);
    const model::RigNode& node = at(back, fly);
    EXPECT_EQ(node.name, "fly_ctl");
    EXPECT_EQ(node.channels.defaults[1], 0.5);
    EXPECT_FALSE(node.curves.front().visible);
    EXPECT_EQ(formatAll(back.diagnostics).find("orphan"), std::string::npos) << formatAll(back.diagnostics);
}

TEST(Overrides, AnOverrideOfAMissingChannelIsAWarningNamingTheNode)
{
    model::GuideDocument guide = test::loadSample("biped");
    guide.overrides[kFk].defaults = {{"nothing", 1.0}};
    guide.overrides[kFk].limits = {{"rx", {-10.0, 10.0}}};
    guide.overrides[kFk].defaults["rx"] = 45.0; // outside the limit: clamped, with a warning
    const model::Rig rig = build(guide);
    const std::string log = formatAll(rig.diagnostics);
    EXPECT_NE(log.find("override of 'arm.L::ctrls.fk.0': the node has no channel 'nothing' (kept in the guide)"), std::string::npos) << log;
    EXPECT_NE(log.find("override of 'arm.L::ctrls.fk.0': the default 45 of 'rx' is outside its limits; using 10"), std::string::npos) << log;
    EXPECT_EQ(at(rig, kFk).channels.defaults[3], 10.0);
}
