// The guide's `overrides:` section: readable, sorted, one record per node,
// byte-identical round trips, errors at file:line for bad records, and the
// migration of a schema-2 guide's instance `shapes:` and `pose:`.
#include "TestSupport.h"

#include "io/GuideFile.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

const std::string kHeader = "rigsmith_guide: 3\n"
                            "instances:\n"
                            "  - id: 1\n"
                            "    template: world.character\n"
                            "    name: world\n"
                            "    joints:\n"
                            "      - {id: 1, t: [0, 0, 0]}\n";

} // namespace

TEST(OverrideFile, RecordsAreWrittenSortedOnePerNodeAndRoundTripByteIdentically)
{
    model::GuideDocument guide = test::loadSample("biped");
    // Inserted out of order: the file lists them by key (root, then instance, branch, tag).
    guide.overrides[{4, "R", "ctrls.fk.1"}].pose = {{"rz", 30.0}, {"ik_blend", 0.0}};
    guide.overrides[{4, "L", "ctrls.fk.0"}].limits = {{"rx", {-45.0, 90.0}}};
    guide.overrides[{4, "L", "ctrls.fk.0"}].locks = {{"tx", {true, false}}};
    guide.overrides[{4, "L", "ctrls.fk.0"}].defaults = {{"rz", 10.0}};
    guide.overrides[{4, "L", "ctrls.fk.0"}].displayName = "upperarm_fk_L";
    model::ShapeOverride& shape = guide.overrides[{4, {}, "ctrls.ik"}].shape.emplace();
    shape.edit.transform.translate = Vec3(0.0, 0.1, 0.0);
    shape.edit.cvs[{0, 3}] = Vec3(0.0, 0.05, 0.0);
    shape.color = Vec3(1.0, 0.5, 0.0);
    shape.lineWidth = 2.0;
    shape.visible = true;
    guide.overrides[model::rigRootKey()].post = Transform{Vec3(0.0, 0.0, 1.0), Vec3(0.0), Vec3(2.0)};
    const std::string text = io::writeGuideText(guide);
    const std::string expected = "overrides:\n"
                                 "  - node: rig\n"
                                 "    post: {t: [0, 0, 1], s: [2, 2, 2]}\n"
                                 "  - instance: 4  # arm\n"
                                 "    node: ctrls.ik\n"
                                 "    shape: {t: [0, 0.1, 0], color: [1, 0.5, 0], line_width: 2, visible: on}\n"
                                 "    cvs:\n"
                                 "      - {curve: 0, cv: 3, offset: [0, 0.05, 0]}\n"
                                 "  - instance: 4  # arm\n"
                                 "    branch: L\n"
                                 "    node: ctrls.fk.0\n"
                                 "    defaults: {rz: 10}\n"
                                 "    limits: {rx: [-45, 90]}\n"
                                 "    locks: {tx: {locked: on, keyable: off}}\n"
                                 "    name: upperarm_fk_L\n"
                                 "  - instance: 4  # arm\n"
                                 "    branch: R\n"
                                 "    node: ctrls.fk.1\n"
                                 "    pose: {ik_blend: 0, rz: 30}\n";
    EXPECT_NE(text.find(expected), std::string::npos) << text;
    auto read = io::readGuideText(text, "sorted.yml");
    ASSERT_TRUE(read.ok()) << formatAll(read.diagnostics());
    EXPECT_EQ(read->overrides, guide.overrides);
    EXPECT_EQ(io::writeGuideText(*read), text);
}

TEST(OverrideFile, BadRecordsAreErrorsAtTheirLine)
{
    const std::string text = kHeader +
                             "overrides:\n"
                             "  - {instance: 1, node: ctrls.world, limits: {tx: [2, 1]}}\n"          // 9
                             "  - {node: ctrls.fly, pose: {tx: 1}}\n"                                 // 10
                             "  - {instance: 1, node: ctrls.world, post: {t: [0, 0, 1]}}\n"          // 11
                             "  - {instance: 1, node: ctrls.fly, shape: {line_width: 0}}\n"          // 12
                             "  - {instance: 1, node: ctrls.fly, shape: {color: [2, 0, 0]}}\n"       // 13
                             "  - {instance: 1, node: ctrls.fly, locks: {tx: {locked: maybe}}}\n"    // 14
                             "  - {instance: 1, node: ctrls.god, pose: {tx: 1}}\n"                   // 15
                             "  - {instance: 1, node: ctrls.god, pose: {ty: 1}}\n";                  // 16
    auto read = io::readGuideText(text, "bad.yml");
    ASSERT_FALSE(read.ok());
    const std::string messages = formatAll(read.diagnostics());
    for (const char* expected : {"bad.yml:9:51: error: limits of 'tx': min 2 is above max 1",
                                 "bad.yml:10:5: error: an override record needs 'instance'",
                                 "bad.yml:11:5: error: a post transform belongs to the rig root",
                                 "bad.yml:12:56: error: shape 'line_width' must be more than 0",
                                 "bad.yml:13:51: error: shape 'color' needs three numbers from 0 to 1",
                                 "bad.yml:14:", "bad.yml:16:5: error: a second override record for the same node"})
        EXPECT_NE(messages.find(expected), std::string::npos) << expected << "\n" << messages;
}

TEST(OverrideFile, ASchemaTwoGuideMigratesItsShapeEditsAndPoseWithANote)
{
    const std::string text = "rigsmith_guide: 2\n"
                             "instances:\n"
                             "  - id: 1\n"
                             "    template: world.character\n"
                             "    name: world\n"
                             "    shapes:\n"
                             "      ctrls.fly: {t: [0, 0.1, 0], s: [2, 2, 2]}\n"
                             "    joints:\n"
                             "      - {id: 1, t: [0, 0, 0]}\n"
                             "pose:\n"
                             "  - {instance: 1, node: ctrls.fly, values: {tx: 1}}\n";
    auto read = io::readGuideText(text, "old.yml");
    ASSERT_TRUE(read.ok()) << formatAll(read.diagnostics());
    const std::string messages = formatAll(read.diagnostics());
    EXPECT_NE(messages.find("old.yml:6:5: note: 2 shape edit and test pose record(s) of an older guide were read as overrides"),
              std::string::npos) << messages;
    const NodeKey fly{1, {}, "ctrls.fly"};
    ASSERT_TRUE(read->overrides.count(fly));
    const model::Override& record = read->overrides.at(fly);
    ASSERT_TRUE(record.shape);
    EXPECT_EQ(record.shape->edit.transform.translate, Vec3(0.0, 0.1, 0.0));
    EXPECT_EQ(record.shape->edit.transform.scale, Vec3(2.0));
    EXPECT_EQ(record.pose, (std::map<std::string, double>{{"tx", 1.0}}));
    // Saved in the new form, with nothing lost.
    const std::string saved = io::writeGuideText(*read);
    EXPECT_EQ(saved.find("shapes:"), std::string::npos) << saved;
    EXPECT_NE(saved.find("overrides:\n  - instance: 1  # world\n    node: ctrls.fly\n    shape: {t: [0, 0.1, 0], s: [2, 2, 2]}\n"
                         "    pose: {tx: 1}\n"),
              std::string::npos) << saved;
    auto again = io::readGuideText(saved, "new.yml");
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again->overrides, read->overrides);
}

TEST(OverrideFile, ARecordGivenTwiceInTheOldAndNewFormIsAnError)
{
    const std::string text = "rigsmith_guide: 2\n"
                             "instances:\n"
                             "  - id: 1\n"
                             "    template: world.character\n"
                             "    name: world\n"
                             "    joints:\n"
                             "      - {id: 1, t: [0, 0, 0]}\n"
                             "pose:\n"
                             "  - {instance: 1, node: ctrls.fly, values: {tx: 1}}\n"
                             "overrides:\n"
                             "  - {instance: 1, node: ctrls.fly, pose: {tx: 2}}\n";
    auto read = io::readGuideText(text, "both.yml");
    ASSERT_FALSE(read.ok());
    EXPECT_NE(formatAll(read.diagnostics()).find("both.yml:8:1: error: the test pose of node 'ctrls.fly' (instance 1) is given both"),
              std::string::npos) << formatAll(read.diagnostics());
}
