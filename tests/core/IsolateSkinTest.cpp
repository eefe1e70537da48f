// The common option `isolate_skin` (issue 22 item 1, Mikan's `sk_` skeleton
// under `::bind`), checked the way a rigger would on the built and evaluated
// biped: the skin joints form a hierarchy of their own, every pose an animator
// can make moves them exactly as before, and the export does not change.
#include "core/IncrementalCheck.h"
#include "EvalTestSupport.h"

#include "io/RigDump.h"
#include "io/RigExport.h"
#include "model/Skeleton.h"
#include "rigging/BuildCache.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

namespace rs {
namespace {

bool isSkinJoint(const model::RigNode& node) { return node.kind == model::RigNodeKind::Joint && node.domain() == "skin"; }

// The biped with `isolate_skin` on the named instances (every one when empty).
model::GuideDocument isolatedBiped(const std::vector<std::string>& names = {})
{
    model::GuideDocument guide = test::loadSample("biped");
    std::vector<model::InstanceId> ids;
    for (const auto& instance : guide.instances())
        if (names.empty() || std::find(names.begin(), names.end(), instance.name) != names.end())
            ids.push_back(instance.id);
    for (model::InstanceId id : ids)
        guide.instance(id)->options["isolate_skin"] = Value(true);
    return guide;
}

// A pose an animator could make: every unlocked channel at a random value
// (translations to 30 cm, rotations to 90 degrees, each scale axis apart from
// 0.6 to 1.4, custom channels across their range).
eval::Pose randomPose(const eval::ChannelLayout& layout, std::mt19937& random)
{
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    eval::Pose pose = layout.defaults();
    for (std::size_t i = 0; i < layout.size(); ++i) {
        const eval::Channel& c = layout[i];
        if (c.transform == eval::kRotateOrderChannel || c.locked)
            continue;
        const double s = unit(random);
        double value = c.transform < 0 ? c.defaultValue + s : c.transform < 3 ? 0.3 * s : c.transform < 6 ? 90.0 * s : 1.0 + 0.4 * s;
        if (c.transform < 0 && c.min > 0.0) // a scale factor (post_scale)
            value = c.defaultValue * (1.0 + 0.3 * s);
        else if (c.transform < 0 && c.limited)
            value = c.min + (c.max - c.min) * (0.5 + 0.5 * s);
        pose[i] = layout.clamp(int(i), value);
    }
    return pose;
}

// Poses both rigs alike (their channels are the same: isolation adds none) and
// checks every skin joint of `plain` sits where it does in `isolated`.
void expectSamePoses(test::PosedRig& plain, test::PosedRig& isolated, int poses)
{
    ASSERT_EQ(plain.program->channels().size(), isolated.program->channels().size());
    for (std::size_t i = 0; i < plain.program->channels().size(); ++i)
        ASSERT_EQ(plain.rig.nodes[plain.program->channels()[i].node].path,
                  isolated.rig.nodes[isolated.program->channels()[i].node].path);
    std::mt19937 random(22);
    for (int p = 0; p < poses; ++p) {
        const eval::Pose pose = randomPose(plain.program->channels(), random);
        const eval::EvalState& a = plain.evaluate(pose);
        const eval::EvalState& b = isolated.evaluate(pose);
        std::size_t compared = 0;
        for (model::RigNodeIndex i = 0; i < plain.rig.nodes.size(); ++i) {
            if (!isSkinJoint(plain.rig.nodes[i]))
                continue;
            const model::RigNodeIndex j = isolated.index(plain.rig.nodes[i].path);
            EXPECT_LT(maxAbsDifference(a.worldMatrix(i), b.worldMatrix(j)), 1e-9) << "pose " << p << ": " << plain.rig.nodes[i].path;
            ++compared;
        }
        ASSERT_GT(compared, 0u);
    }
}

} // namespace

TEST(IsolateSkin, EverySkinJointHangsFromASkinJointOrTheJointGroup)
{
    test::PosedRig r(isolatedBiped());
    ASSERT_TRUE(r.ok());
    EXPECT_FALSE(hasErrors(r.rig.diagnostics)) << formatAll(r.rig.diagnostics);
    const model::RigNodeIndex jointGroup = r.index("world::grps.joint");
    std::size_t skin = 0;
    for (const model::RigNode& node : r.rig.nodes) {
        if (!isSkinJoint(node))
            continue;
        ++skin;
        const model::RigNode& parent = r.rig.nodes[node.parent];
        EXPECT_TRUE(isSkinJoint(parent) || node.parent == jointGroup) << node.path << " hangs under " << parent.path;
        // Skin to skin along the export skeleton: the physical parent is the nearest skin joint above it there.
        if (node.virtualParent != model::kNoNode && isSkinJoint(r.rig.nodes[node.virtualParent]))
            EXPECT_EQ(node.parent, node.virtualParent) << node.path;
    }
    EXPECT_EQ(skin, r.rig.skinJointCount());
    EXPECT_EQ(r.rig.nodes[r.index("spine::skin.0")].parent, r.index("world::skin.root"));
    EXPECT_EQ(r.rig.nodes[r.index("arm.L::skin.clavicle")].parent, r.index("spine::skin.4"));
}

TEST(IsolateSkin, IsOffByDefaultAndTheSkinJointsHangUnderTheirControllers)
{
    test::PosedRig r("biped");
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.rig.nodes[r.index("spine::skin.0")].parent, r.index("spine::ctrls.hips"));
}

TEST(IsolateSkin, RandomPosesMoveEverySkinJointAsWithoutIt)
{
    test::PosedRig plain("biped");
    test::PosedRig isolated(isolatedBiped());
    ASSERT_TRUE(plain.ok() && isolated.ok());
    expectSamePoses(plain, isolated, 40);
}

TEST(IsolateSkin, AMirroredBranchIsolatesLikeItsTwin)
{
    // Only the arms: the spine keeps its joints under its controllers.
    test::PosedRig plain("biped");
    test::PosedRig r(isolatedBiped({"arm"}));
    ASSERT_TRUE(plain.ok() && r.ok());
    EXPECT_EQ(r.rig.nodes[r.index("spine::skin.4")].parent, plain.rig.nodes[plain.index("spine::skin.4")].parent);
    std::size_t checked = 0;
    for (model::RigNodeIndex i = 0; i < r.rig.nodes.size(); ++i) {
        const model::RigNode& left = r.rig.nodes[i];
        if (!isSkinJoint(left) || left.path.rfind("arm.L::", 0) != 0)
            continue;
        ASSERT_NE(left.twin, model::kNoNode) << left.path;
        const model::RigNode& right = r.rig.nodes[left.twin];
        EXPECT_EQ(right.path.rfind("arm.R::", 0), 0u) << right.path;
        const model::RigNode& leftParent = r.rig.nodes[left.parent];
        EXPECT_TRUE(isSkinJoint(leftParent)) << left.path;
        // The right joint hangs from the twin of the left one's parent, or the same centre joint (the chest).
        const model::RigNodeIndex expected = leftParent.twin != model::kNoNode ? leftParent.twin : left.parent;
        EXPECT_EQ(right.parent, expected) << right.path << " under " << r.rig.nodes[right.parent].path;
        ++checked;
    }
    EXPECT_GT(checked, 4u);
    EXPECT_EQ(r.rig.nodes[r.index("arm.R::skin.clavicle")].parent, r.index("spine::skin.4"));
    expectSamePoses(plain, r, 10);
}

TEST(IsolateSkin, AnIncrementalRebuildMakesTheRigAFullBuildMakes)
{
    model::GuideDocument guide = isolatedBiped({"spine", "arm", "leg", "index"});
    rigging::BuildCache cache;
    auto compare = [&](const std::string& what) { test::buildAndCompare(guide, cache, what); };
    compare("first build");
    compare("second build");
    EXPECT_EQ(cache.lastBuild().generated, 0u);
    guide.instance(guide.instanceNamed("arm")->id)->joints.front().local.translate.y += 0.02;
    compare("arm moved");
    EXPECT_GT(cache.lastBuild().replayed, 0u);
    guide.instance(guide.instanceNamed("neck")->id)->options["isolate_skin"] = Value(true);
    compare("neck isolated");
    guide.instance(guide.instanceNamed("arm")->id)->options.erase("isolate_skin");
    compare("arm back under its controllers");
}

TEST(IsolateSkin, TheExportIsUnchanged)
{
    const model::Rig plain = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    const model::Rig isolated = rigging::buildRig(isolatedBiped(), test::builtinTemplates());
    auto a = model::extractSkeleton(plain);
    auto b = model::extractSkeleton(isolated);
    ASSERT_TRUE(a.ok() && b.ok());
    ASSERT_EQ(a->joints.size(), b->joints.size());
    for (std::size_t i = 0; i < a->joints.size(); ++i) {
        EXPECT_EQ(a->joints[i].name, b->joints[i].name);
        EXPECT_EQ(a->joints[i].parent, b->joints[i].parent) << a->joints[i].name;
    }
    // The files themselves: same joints, same bind matrices, byte for byte.
    const std::string dirA = test::temporaryPath("isolate_off"), dirB = test::temporaryPath("isolate_on");
    std::filesystem::create_directories(dirA);
    std::filesystem::create_directories(dirB);
    for (const std::string file : {"biped.gltf", "biped.fbx"}) {
        EXPECT_FALSE(hasErrors(io::exportRig(plain, dirA + "/" + file)));
        EXPECT_FALSE(hasErrors(io::exportRig(isolated, dirB + "/" + file)));
        EXPECT_EQ(test::readText(dirA + "/" + file), test::readText(dirB + "/" + file)) << file;
    }
    EXPECT_EQ(test::readText(dirA + "/biped.bin"), test::readText(dirB + "/biped.bin")) << "the inverse bind matrices";
}

TEST(IsolateSkin, ARigWithoutAJointGroupGetsABindGroup)
{
    // The vehicle's world.default has no joint group: Mikan's `::bind` is made under the rig's root.
    model::GuideDocument guide = test::loadSample("vehicle");
    std::vector<model::InstanceId> ids;
    for (const auto& instance : guide.instances())
        ids.push_back(instance.id);
    for (model::InstanceId id : ids)
        guide.instance(id)->options["isolate_skin"] = Value(true);
    test::PosedRig plain("vehicle");
    test::PosedRig r(guide);
    ASSERT_TRUE(plain.ok() && r.ok());
    const model::RigNodeIndex bind = r.index("::bind");
    EXPECT_EQ(r.rig.nodes[bind].parent, 0u);
    EXPECT_EQ(r.rig.nodes[r.index("world::skin.root")].parent, bind);
    for (const model::RigNode& node : r.rig.nodes)
        if (isSkinJoint(node))
            EXPECT_TRUE(isSkinJoint(r.rig.nodes[node.parent]) || node.parent == bind) << node.path;
    expectSamePoses(plain, r, 10);
}

} // namespace rs
