// core.xform's orientation and node options as a rigger checks them on the
// built, evaluated and exported rig: joint (a joint the export carries even
// without do_skin), copy_orient (the guide's turn or the world axes) and
// flip_orient (a mirrored controller that mirrors with negated translations).
#include "EvalTestSupport.h"
#include "core/IncrementalCheck.h"
#include "core/TestSupport.h"
#include "io/ExportScene.h"
#include "rigging/RigBuilder.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace rs {
namespace {

using test::PosedRig;

// A prop part off the mirror plane, turned, with [L, R] branches.
model::GuideDocument turnedPart(const std::map<std::string, Value>& options)
{
    model::GuideDocument doc;
    std::map<std::string, Value> all = options;
    all["branches"] = Value(std::string("[L, R]"));
    const model::TemplateInstance part = test::addInstance(doc, "core.xform", model::kNoId, all);
    auto& joint = doc.instance(part.id)->joints.front();
    joint.local.translate = Vec3(0.4, 1.1, 0.2);
    joint.local.rotateDegrees = Vec3(20.0, 35.0, -10.0);
    return doc;
}

bool exports(const model::Rig& rig, const std::string& id)
{
    const io::PreparedExport prepared = io::prepareExport(rig, io::ExportOptions{});
    EXPECT_TRUE(prepared.scene.has_value()) << formatAll(prepared.report);
    return prepared.scene && std::any_of(prepared.scene->joints.begin(), prepared.scene->joints.end(),
                                         [&](const io::ExportJoint& j) { return j.id == id; });
}

TEST(CoreTemplates, XformJointOptionMakesAJointTheExportCarriesWithoutDoSkin)
{
    model::GuideDocument doc;
    const model::TemplateInstance root = test::addInstance(doc, "core.xform", model::kNoId);
    const model::TemplateInstance plain = test::addInstance(doc, "core.group", root.joints.front().id);
    const model::TemplateInstance bone = test::addInstance(doc, "core.group", root.joints.front().id, {{"joint", Value(true)}});
    const model::TemplateInstance locator =
        test::addInstance(doc, "core.xform", root.joints.front().id, {{"do_skin", Value(false)}, {"joint", Value(true)}});
    PosedRig r(doc);
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.rig.diagnostics.empty()) << formatAll(r.rig.diagnostics);
    EXPECT_FALSE(r.rig.findPath(plain.name + "::skin.xform")) << "a group makes no joint by default";
    EXPECT_TRUE(exports(r.rig, bone.name + "::skin.xform")) << "a group with joint on is a bone of the export";
    EXPECT_TRUE(exports(r.rig, locator.name + "::skin.xform")) << "so is an xform with do_skin off and joint on";
    EXPECT_TRUE(exports(r.rig, root.name + "::skin.xform"));
    // The joint rides on the group: moving the root carries it.
    eval::Pose pose = r.defaults();
    pose[r.channel(root.name + "::ctrls.xform", "tx")] = 0.5;
    r.evaluate(pose);
    EXPECT_LT(glm::length(r.position(bone.name + "::skin.xform") - (r.restPosition(bone.name + "::skin.xform") + Vec3(0.5, 0, 0))), 1e-12);
}

TEST(CoreTemplates, XformCopyOrientOffKeepsTheWorldAxesAtTheGuide)
{
    const model::Rig copied = rigging::buildRig(turnedPart({}), test::builtinTemplates());
    const model::Rig world = rigging::buildRig(turnedPart({{"copy_orient", Value(false)}}), test::builtinTemplates());
    const std::string ctrl = "xform.L::ctrls.xform";
    const Mat4 guideTurned = test::node(copied, ctrl).worldMatrix;
    const Mat4 worldAxes = test::node(world, ctrl).worldMatrix;
    EXPECT_LT(glm::length(Vec3(guideTurned[3]) - Vec3(worldAxes[3])), 1e-12) << "at the guide either way";
    EXPECT_LT(maxAbsDifference(Mat4(Mat3(worldAxes)), Mat4(1.0)), 1e-12) << "the world axes";
    EXPECT_GT(maxAbsDifference(Mat4(Mat3(guideTurned)), Mat4(1.0)), 0.1) << "the guide's turn by default";
    EXPECT_LT(maxAbsDifference(Mat4(Mat3(test::node(world, "xform.L::skin.xform").worldMatrix)), Mat4(1.0)), 1e-12);
}

// The R controller posed with the L values, translations negated: with
// flip_orient its skin joint is the exact mirror of L's; without, it is not.
double mirrorErrorOfNegatedTranslations(const model::GuideDocument& doc)
{
    PosedRig r(doc);
    EXPECT_TRUE(r.ok());
    const double t[] = {0.1, -0.2, 0.3}, rot[] = {15.0, -25.0, 40.0};
    const char* translations[] = {"tx", "ty", "tz"};
    const char* rotations[] = {"rx", "ry", "rz"};
    eval::Pose pose = r.defaults();
    for (int a = 0; a < 3; ++a) {
        pose[r.channel("xform.L::ctrls.xform", translations[a])] = t[a];
        pose[r.channel("xform.R::ctrls.xform", translations[a])] = -t[a];
        pose[r.channel("xform.L::ctrls.xform", rotations[a])] = rot[a];
        pose[r.channel("xform.R::ctrls.xform", rotations[a])] = rot[a];
    }
    const auto& state = r.evaluate(pose);
    Mat4 mirror(1.0);
    mirror[0][0] = -1.0;
    return maxAbsDifference(state.worldMatrix(r.index("xform.R::skin.xform")),
                            mirror * state.worldMatrix(r.index("xform.L::skin.xform")) * mirror);
}

TEST(CoreTemplates, XformFlipOrientMirrorsNegatedTranslationsOnTheRightBranch)
{
    EXPECT_LT(mirrorErrorOfNegatedTranslations(turnedPart({{"flip_orient", Value(true)}})), 1e-9);
    EXPECT_GT(mirrorErrorOfNegatedTranslations(turnedPart({})), 0.05) << "without it the same pose is no mirror";
    // At rest the skin joints stay exact mirrors; only R's controller is turned.
    const model::Rig rig = rigging::buildRig(turnedPart({{"flip_orient", Value(true)}}), test::builtinTemplates());
    Mat4 mirror(1.0);
    mirror[0][0] = -1.0;
    const Mat4 left = test::node(rig, "xform.L::skin.xform").worldMatrix, right = test::node(rig, "xform.R::skin.xform").worldMatrix;
    EXPECT_LT(maxAbsDifference(right, mirror * left * mirror), 1e-12);
    const Mat4 leftCtrl = test::node(rig, "xform.L::ctrls.xform").worldMatrix;
    EXPECT_LT(maxAbsDifference(test::node(rig, "xform.L::ctrls.xform").worldMatrix, left), 1e-12) << "L is not flipped";
    EXPECT_GT(maxAbsDifference(test::node(rig, "xform.R::ctrls.xform").worldMatrix, mirror * leftCtrl * mirror), 0.5);
}

TEST(CoreTemplates, XformOptionsRebuildIncrementallyAsAFullBuild)
{
    model::GuideDocument doc = turnedPart({});
    const model::InstanceId part = doc.instances().front().id;
    rigging::BuildCache cache;
    test::buildAndCompare(doc, cache, "first build");
    for (const char* option : {"flip_orient", "joint"}) {
        doc.instance(part)->options[option] = Value(true);
        test::buildAndCompare(doc, cache, option);
    }
    doc.instance(part)->options["do_skin"] = Value(false);
    test::buildAndCompare(doc, cache, "joint without do_skin");
    doc.instance(part)->options["copy_orient"] = Value(false);
    test::buildAndCompare(doc, cache, "copy_orient off");
}

} // namespace
} // namespace rs
