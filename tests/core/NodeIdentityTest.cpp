// Typed node identity: every per-node record of a guide (test pose, shape
// edits, name overrides) is keyed by instance id, so renaming an instance (by
// command or in the file) keeps them; guides of schema 1 migrate; records of
// nodes a build does not make are reported and kept.
#include "TestSupport.h"

#include "edit/GuideEdits.h"
#include "eval/PoseTools.h"
#include "io/GuideFile.h"
#include "rigging/RigBuilder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

using namespace rs;

namespace {

// What a rigger sees of a built, posed rig, by node key: world matrix, name
// (which follows the instance's name), first curve point (shape edits).
struct Seen {
    Mat4 world;
    std::string name;
    Vec3 firstPoint{0.0};
};

std::map<NodeKey, Seen> seenOf(const model::GuideDocument& guide)
{
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    EXPECT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    auto posed = eval::posedRig(rig, model::testPose(guide.overrides));
    EXPECT_TRUE(posed.ok());
    std::map<NodeKey, Seen> out;
    for (const auto& node : posed->nodes)
        out[node.key] = {node.worldMatrix, node.name, node.curves.empty() ? Vec3(0.0) : node.curves.front().points.front()};
    return out;
}

void expectSameRig(const std::map<NodeKey, Seen>& a, const std::map<NodeKey, Seen>& b)
{
    ASSERT_EQ(a.size(), b.size());
    for (const auto& [key, seen] : a) {
        const auto other = b.find(key);
        ASSERT_NE(other, b.end()) << key.tag;
        EXPECT_LT(maxAbsDifference(seen.world, other->second.world), 1e-12) << key.tag;
        EXPECT_LT(glm::length(seen.firstPoint - other->second.firstPoint), 1e-12) << key.tag;
    }
}

// The biped with a test pose on both arms, an IK shape edit and a name override
// on the arm, every record keyed by the arm's id.
model::GuideDocument editedBiped(edit::History& history)
{
    model::GuideDocument guide = test::loadSample("biped");
    const model::InstanceId arm = guide.instanceNamed("arm")->id;
    model::PoseValues pose;
    pose[{arm, "L", "ctrls.fk.0"}]["rz"] = -40.0;
    pose[{arm, "R", "ctrls.fk.1"}]["ry"] = 25.0;
    pose[{arm, "L", "ctrls.switch"}]["ik_blend"] = 0.0;
    model::setTestPose(guide.overrides, pose);
    model::ShapeEdit shape;
    shape.transform.translate = Vec3(0.0, 0.05, 0.0);
    guide.overrides[{arm, {}, "ctrls.ik"}].shape.emplace().edit = shape;
    guide.instance(arm)->names["ik"] = "hand";
    history.reset(guide);
    return guide;
}

} // namespace

TEST(NodeIdentity, RenamingAnInstanceByCommandKeepsItsPoseShapeEditsAndNameOverrides)
{
    model::GuideDocument document;
    edit::History history(document);
    const model::GuideDocument edited = editedBiped(history);
    const auto before = seenOf(document);
    const model::InstanceId arm = document.instanceNamed("arm")->id;
    ASSERT_TRUE(test::succeeded(edit::renameInstance(history, arm, "limb")));
    ASSERT_EQ(document.instance(arm)->name, "limb");
    EXPECT_EQ(document.overrides, edited.overrides);
    expectSameRig(before, seenOf(document));
    // The pose did move the arm, the shape edit and the name override apply.
    const auto& after = seenOf(document);
    const auto& fk = after.at({arm, "L", "ctrls.fk.0"});
    const auto rest = seenOf(test::loadSample("biped"));
    EXPECT_GT(maxAbsDifference(fk.world, rest.at({arm, "L", "ctrls.fk.0"}).world), 0.1);
    EXPECT_EQ(after.at({arm, "L", "ctrls.ik"}).name, "c_limb_hand_L"); // the new name, the kept override
    EXPECT_GT(glm::length(after.at({arm, "L", "ctrls.ik"}).firstPoint - rest.at({arm, "L", "ctrls.ik"}).firstPoint), 0.04);
    // The built rig's display paths follow the new name; no record is orphaned.
    const model::Rig rig = rigging::buildRig(document, test::builtinTemplates());
    EXPECT_TRUE(rig.findPath("limb.L::ctrls.fk.0"));
    EXPECT_FALSE(rig.findPath("arm.L::ctrls.fk.0"));
    for (const auto& d : rig.diagnostics)
        EXPECT_EQ(d.message.find("kept in the guide"), std::string::npos) << d.message;
}

TEST(NodeIdentity, RenamingAnInstanceInTheGuideFileKeepsItsRecords)
{
    model::GuideDocument document;
    edit::History history(document);
    editedBiped(history);
    std::string text = io::writeGuideText(document);
    EXPECT_NE(text.find("  - instance: 4  # arm\n    branch: L\n    node: ctrls.fk.0\n    pose: {rz: -40}\n"), std::string::npos) << text;
    const auto at = text.find("    name: arm\n");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 14, "    name: limb\n"); // what a rigger does in a text editor
    auto reread = io::readGuideText(text, "renamed.yml");
    ASSERT_TRUE(reread.ok()) << formatAll(reread.diagnostics());
    EXPECT_EQ(reread->instance(4)->name, "limb");
    EXPECT_EQ(reread->overrides, document.overrides);
    expectSameRig(seenOf(document), seenOf(*reread));
}

TEST(NodeIdentity, AGuideOfSchemaOneMigratesItsPoseWithANoteAndBuildsTheSame)
{
    model::GuideDocument document;
    edit::History history(document);
    editedBiped(history);
    // Schema 1 keyed the pose by the instance's name (the shape edit is written as an override).
    model::GuideDocument unposed = document;
    model::setTestPose(unposed.overrides, {});
    std::string text = io::writeGuideText(unposed);
    text.replace(text.find("rigsmith_guide: 3"), 17, "rigsmith_guide: 1");
    text = text +
           "pose:\n"
           "  \"arm.L::ctrls.fk.0\": {rz: -40}\n"
           "  \"arm.L::ctrls.switch\": {ik_blend: 0}\n"
           "  \"arm.R::ctrls.fk.1\": {ry: 25}\n"
           "  \"gone.L::ctrls.fk.0\": {rx: 5}\n";
    auto old = io::readGuideText(text, "old.yml");
    ASSERT_TRUE(old.ok()) << formatAll(old.diagnostics());
    EXPECT_EQ(old->overrides, document.overrides);
    const std::string messages = formatAll(old.diagnostics());
    EXPECT_NE(messages.find("old.yml:"), std::string::npos) << messages;
    EXPECT_NE(messages.find("note: 3 pose record(s) keyed by instance name were migrated"), std::string::npos) << messages;
    EXPECT_NE(messages.find("warning: pose of 'gone.L::ctrls.fk.0': no instance named 'gone'; the record is kept"),
              std::string::npos) << messages;
    expectSameRig(seenOf(document), seenOf(*old));
    // The unmatched record is reported by the build and survives a save.
    const model::Rig rig = rigging::buildRig(*old, test::builtinTemplates());
    EXPECT_NE(formatAll(rig.diagnostics).find("'gone.L::ctrls.fk.0' (an older guide's record)"), std::string::npos);
    const std::string saved = io::writeGuideText(*old);
    EXPECT_NE(saved.find("legacy_pose:\n  \"gone.L::ctrls.fk.0\": {rx: 5}\n"), std::string::npos) << saved;
    auto again = io::readGuideText(saved, "again.yml");
    ASSERT_TRUE(again.ok()) << formatAll(again.diagnostics());
    EXPECT_EQ(again->overrides, document.overrides);
    EXPECT_EQ(again->legacyPose, old->legacyPose);
}

TEST(NodeIdentity, ARecordWhoseNodeIsGoneIsReportedByNameAndKept)
{
    model::GuideDocument document;
    edit::History history(document);
    editedBiped(history);
    const model::InstanceId arm = document.instanceNamed("arm")->id;
    model::PoseValues pose = model::testPose(document.overrides);
    pose[{arm, "L", "ctrls.fk.9"}]["rx"] = 10.0; // a control this arm does not make
    ASSERT_TRUE(test::succeeded(edit::setPose(history, pose, "Pose")));
    model::ShapeEdit shape;
    shape.transform.scale = Vec3(2.0);
    ASSERT_TRUE(test::succeeded(edit::setShapeEdit(history, arm, "ctrls.nothing", shape)));
    const model::Rig rig = rigging::buildRig(document, test::builtinTemplates());
    const std::string log = formatAll(rig.diagnostics);
    EXPECT_NE(log.find("warning: orphan override of 'arm.L::ctrls.fk.9' (pose): the rig has no such node; it is kept in the guide"),
              std::string::npos) << log;
    EXPECT_NE(log.find("warning: orphan override of 'arm::ctrls.nothing' (shapes): the rig has no such node; it is kept in the guide"),
              std::string::npos) << log;
    const auto orphan = std::find_if(rig.diagnostics.begin(), rig.diagnostics.end(),
                                     [](const Diagnostic& d) { return d.message.find("ctrls.fk.9") != std::string::npos; });
    ASSERT_NE(orphan, rig.diagnostics.end());
    EXPECT_EQ(orphan->subject, Subject::ofInstance(arm, "L"));
    // Saved and read back: both records are still there.
    auto reread = io::readGuideText(io::writeGuideText(document), "orphans.yml");
    ASSERT_TRUE(reread.ok()) << formatAll(reread.diagnostics());
    EXPECT_EQ(reread->overrides, document.overrides);
    ASSERT_TRUE(reread->overrides.count({arm, {}, "ctrls.nothing"}));
    EXPECT_TRUE(reread->overrides.at({arm, {}, "ctrls.nothing"}).shape);
}

TEST(NodeIdentity, PoseRecordsWithBadKeysAreErrorsAtTheirLine)
{
    const std::string text = "rigsmith_guide: 2\n"
                             "instances:\n"
                             "  - id: 1\n"
                             "    template: world.character\n"
                             "    name: world\n"
                             "    joints:\n"
                             "      - {id: 1, t: [0, 0, 0]}\n"
                             "pose:\n"
                             "  - {instance: 1, node: ctrls.world, values: {tx: 1}}\n"
                             "  - {node: ctrls.fly, values: {tx: 1}}\n"
                             "  - {instance: 1, node: ctrls.world, values: {ty: 1}}\n";
    auto read = io::readGuideText(text, "bad.yml");
    ASSERT_FALSE(read.ok());
    const std::string messages = formatAll(read.diagnostics());
    EXPECT_NE(messages.find("bad.yml:10:5: error: a pose record needs 'instance'"), std::string::npos) << messages;
    EXPECT_NE(messages.find("bad.yml:11:5: error: a second pose record for the same node"), std::string::npos) << messages;
}

TEST(NodeIdentity, EveryNodeKeyIsUniqueAndNamesItsAuthoredInstance)
{
    const model::GuideDocument guide = test::loadSample("biped");
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    ASSERT_EQ(rig.byKey.size(), rig.nodes.size());
    for (model::RigNodeIndex i = 0; i < rig.nodes.size(); ++i) {
        const auto& node = rig.nodes[i];
        EXPECT_EQ(rig.find(node.key), i);
        if (i == 0) {
            EXPECT_TRUE(node.key.isRoot());
            continue;
        }
        const auto* instance = guide.instance(node.key.instance);
        ASSERT_NE(instance, nullptr) << node.path;
        EXPECT_EQ(node.owner, instance->id);
        // The display path is made of the current name, the branch and the tag.
        EXPECT_EQ(node.path, instance->name + (node.key.branch.empty() ? "" : "." + node.key.branch) + "::" + node.key.tag);
    }
}
