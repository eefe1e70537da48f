// Issue 23's round trip: the same guide, overrides included, gives byte-identical
// glb and fbx exports whether it is built fresh or rebuilt by a session after
// edits that were undone (the incremental build replays cached fragments).
#include "core/FbxReader.h"
#include "core/TestSupport.h"
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

} // namespace
} // namespace rs
