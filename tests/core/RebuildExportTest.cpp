// Issue 23's round trip: the same guide, overrides included, gives byte-identical
// glb and fbx exports whether it is built fresh or rebuilt by a session after
// edits that were undone (the incremental build replays cached fragments).
#include "core/FbxReader.h"
#include "core/TestSupport.h"
#include "io/ExportScene.h"
#include "io/GuideFile.h"
#include "io/RigExport.h"
#include "model/Override.h"
#include "rigging/RigBuilder.h"
#include "session/Session.h"

#include <gtest/gtest.h>

namespace rs {
namespace {

model::GuideDocument bipedWithOverrides()
{
    model::GuideDocument doc = io::readGuideFile(test::samplePath("biped")).take();
    const model::TemplateInstance* arm = doc.instanceNamed("arm");
    const NodeKey fk{arm->id, "L", "ctrls.fk.0"};
    doc.overrides[fk].defaults["rx"] = 12.5;
    doc.overrides[fk].limits["ry"] = model::ChannelLimit{-30.0, 45.0};
    doc.overrides[fk].displayName = "upper_arm_fk_L";
    doc.overrides[NodeKey{arm->id, "R", "ctrls.ik"}].shape.emplace().color = Vec3(0.2, 0.9, 0.4);
    doc.overrides[model::rigRootKey()].post = Transform{Vec3(0.0, 0.0, 0.5), Vec3(0.0), Vec3(1.25)};
    return doc;
}

std::string exported(const model::Rig& rig, const std::string& name)
{
    io::ExportOptions options;
    options.controllers = true;
    options.rangeOfMotion = true;
    const std::string path = test::temporaryPath(name);
    const Diagnostics problems = io::exportRig(rig, path, options);
    EXPECT_TRUE(problems.empty()) << formatAll(problems);
    return test::readFileBytes(path);
}

TEST(RebuildExport, AFreshBuildAndASessionRebuildExportByteIdenticalGlbAndFbx)
{
    const model::GuideDocument doc = bipedWithOverrides();
    const model::Rig fresh = rigging::buildRig(doc, test::builtinTemplates());
    ASSERT_EQ(fresh.nodes[*fresh.find(NodeKey{doc.instanceNamed("arm")->id, "L", "ctrls.fk.0"})].name, "upper_arm_fk_L");

    session::Session s(std::make_shared<templates::TemplateRegistry>(test::builtinTemplates()));
    s.replaceDocument(doc);
    s.build();
    // Edits that change the rig, then undone: the session rebuilds from its cache.
    const model::InstanceId spine = s.document().instanceNamed("spine")->id;
    ASSERT_TRUE(s.setOption(spine, "stretch", Value(false)).ok());
    const model::JointId elbow = s.document().instanceNamed("arm")->joints[2].id;
    Mat4 moved = s.document().jointWorldMatrix(elbow);
    moved[3][1] += 0.05;
    ASSERT_TRUE(s.moveGuideJoints(elbow, moved, "move elbow").ok());
    s.history().undo();
    s.history().undo();
    ASSERT_NE(s.rig(), nullptr);
    ASSERT_EQ(s.document(), doc);

    for (const char* extension : {".glb", ".fbx"}) {
        SCOPED_TRACE(extension);
        const std::string a = exported(fresh, std::string("rebuild-fresh") + extension);
        const std::string b = exported(*s.rig(), std::string("rebuild-session") + extension);
        ASSERT_GT(a.size(), 10000u);
        EXPECT_TRUE(a == b) << "the session's rebuild exports other bytes than a fresh build";
    }
}


// The seed's "controller default values": what the rig resets to is what the
// exported nodes rest in; the bind (inverse bind matrices) stays the build's rest.
TEST(RebuildExport, DefaultValuesAreThePoseTheExportedNodesRestIn)
{
    model::GuideDocument doc = io::readGuideFile(test::samplePath("biped")).take();
    io::ExportOptions options;
    options.controllers = true;
    const model::Rig plain = rigging::buildRig(doc, test::builtinTemplates());
    const io::PreparedExport before = io::prepareExport(plain, options);
    ASSERT_TRUE(before.scene) << formatAll(before.report);
    for (const io::ExportJoint& joint : before.scene->joints)
        EXPECT_TRUE(joint.poseLocal == joint.bindLocal) << joint.name << ": no default moves it, so it rests at its bind exactly";

    const NodeKey move{doc.instanceNamed("world")->id, "", "ctrls.move"};
    doc.overrides[move].defaults["ty"] = 0.3;
    const model::Rig rig = rigging::buildRig(doc, test::builtinTemplates());
    const io::PreparedExport after = io::prepareExport(rig, options);
    ASSERT_TRUE(after.scene) << formatAll(after.report);
    ASSERT_EQ(after.scene->joints.size(), before.scene->joints.size());
    const io::ExportJoint& root = after.scene->joints.front();
    EXPECT_TRUE(root.bindWorld == before.scene->joints.front().bindWorld) << "the bind is the build's rest";
    EXPECT_NEAR(translationOf(root.poseLocal).y - translationOf(root.bindLocal).y, 0.3, 1e-9) << root.name;
    for (std::size_t j = 1; j < after.scene->joints.size(); ++j)
        EXPECT_LT(maxAbsDifference(after.scene->joints[j].poseLocal, before.scene->joints[j].poseLocal), 1e-9)
            << after.scene->joints[j].name << ": below the root, nothing else moved";
    const std::string moveName = rig.nodes[*rig.find(move)].name;
    bool found = false;
    for (const io::ExportController& c : after.scene->controllers)
        if (c.name == moveName) {
            found = true;
            EXPECT_NEAR(translationOf(c.poseLocal).y, 0.3, 1e-9) << "the move controller rests at its default";
        }
    EXPECT_TRUE(found) << moveName;
}

} // namespace
} // namespace rs
