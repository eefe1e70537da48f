// Issue 23 item 3: mods change the built and evaluated rig the way an animator
// checks it: a new space follows its target, a constraint and a new parent
// move the node, hide takes a controller away, a plug makes or sets a channel
// or connects one, driven keys follow their curve, vdag changes pickwalk.
#include "ModsTestSupport.h"

#include "eval/DrivenKeys.h"
#include "eval/Pickwalk.h"
#include "model/Skeleton.h"

#include <gtest/gtest.h>

using namespace rs;
using test::ModdedRig;

namespace {

constexpr double kTolerance = 1e-9;

model::GuideDocument bipedWith(std::initializer_list<std::pair<std::string, std::string>> mods)
{
    model::GuideDocument guide = test::loadSample("biped");
    for (const auto& [owner, text] : mods)
        guide.mods.push_back(test::modFromText(guide, owner, text));
    return guide;
}

void expectNear(const Vec3& a, const Vec3& b, double tolerance = 1e-6)
{
    EXPECT_NEAR(glm::length(a - b), 0.0, tolerance) << "(" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x << ", "
                                                     << b.y << ", " << b.z << ")";
}

// How far `follower` moves when the left leg's IK control is raised 0.2 m, in `values`' pose.
Vec3 followsLegIk(ModdedRig& r, const std::string& follower, std::initializer_list<std::tuple<std::string, std::string, double>> values)
{
    std::vector<std::tuple<std::string, std::string, double>> raised(values);
    r.evaluate(values);
    const Vec3 before = r.position(follower);
    const Vec3 legBefore = r.position("leg.L::ctrls.ik");
    auto pose = r.pose;
    pose[r.channel("leg.L::ctrls.ik", "ty")] += 0.2;
    r.program->evaluate(pose, r.state);
    const Vec3 legDelta = r.position("leg.L::ctrls.ik") - legBefore;
    EXPECT_GT(glm::length(legDelta), 0.1);
    return r.position(follower) - before - legDelta; // zero when it follows the leg exactly
}

} // namespace

TEST(Mods, ASpaceModAddsALabelAndSwitchingToItFollowsTheNewTarget)
{
    // An instance's mod on the branched arm: each copy gets its own leg's IK control.
    ModdedRig r(bipedWith({{"arm", "space: {node: ctrls.ik, target: 'leg::ctrls.ik', label: foot}"}}));
    ASSERT_TRUE(r.program) << r.log();
    for (const char* side : {"L", "R"}) {
        const model::RigAttribute* space = r.rig.nodes[r.index(std::string("arm.") + side + "::ctrls.ik")].attribute("space");
        ASSERT_TRUE(space);
        EXPECT_EQ(space->labels.back(), "foot");
        EXPECT_EQ(space->max, 5.0);
    }
    const ModdedRig plain(test::loadSample("biped"));
    r.evaluate();
    expectNear(r.position("arm.L::ctrls.ik"), translationOf(plain.rig.nodes[plain.index("arm.L::ctrls.ik")].worldMatrix));
    const Vec3 inWorld = followsLegIk(r, "arm.L::ctrls.ik", {});
    EXPECT_GT(glm::length(inWorld), 0.1); // in world space it stays where it was
    expectNear(followsLegIk(r, "arm.L::ctrls.ik", {{"arm.L::ctrls.ik", "space", 5.0}}), Vec3(0.0));
    // The right arm's new space is the right leg.
    const auto& spaceOfR = r.rig.constraints;
    const auto it = std::find_if(spaceOfR.begin(), spaceOfR.end(), [&](auto& c) { return c.path == "arm.R::cns.ik_space"; });
    ASSERT_NE(it, spaceOfR.end());
    EXPECT_EQ(it->targets.back(), r.index("leg.R::ctrls.ik"));
}

TEST(Mods, ASpaceModMakesASwitchOnAControlThatHasNone)
{
    ModdedRig r(bipedWith({{"", "space: {node: 'hand.L::ctrls.hand', target: 'leg.L::ctrls.ik', label: foot}"}}));
    ASSERT_TRUE(r.program) << r.log();
    const model::RigAttribute* space = r.rig.nodes[r.index("hand.L::ctrls.hand")].attribute("space");
    ASSERT_TRUE(space);
    EXPECT_EQ(space->labels, (std::vector<std::string>{"parent", "foot"}));
    expectNear(followsLegIk(r, "hand.L::ctrls.hand", {{"hand.L::ctrls.hand", "space", 1.0}}), Vec3(0.0));
    EXPECT_GT(glm::length(followsLegIk(r, "hand.L::ctrls.hand", {})), 0.1); // space 0 ("parent"): as before
}

TEST(Mods, AConstraintModMakesTheNodeFollowItsTargetsKeepingItsRest)
{
    ModdedRig r(bipedWith({{"", "constraint: {kind: point, node: 'hand.L::roots.hand', targets: ['leg.L::ctrls.ik']}"}}));
    ASSERT_TRUE(r.program) << r.log();
    const ModdedRig plain(test::loadSample("biped"));
    r.evaluate();
    expectNear(r.position("hand.L::ctrls.hand"), translationOf(plain.rig.nodes[plain.index("hand.L::ctrls.hand")].worldMatrix));
    expectNear(followsLegIk(r, "hand.L::ctrls.hand", {}), Vec3(0.0));
}

TEST(Mods, AParentModKeepsTheWorldRestAndTheChildFollowsItsNewParent)
{
    ModdedRig r(bipedWith({{"", "parent: {node: 'hand.L::roots.hand', parent: 'leg.L::ctrls.ik'}"}}));
    ASSERT_TRUE(r.program) << r.log();
    const ModdedRig plain(test::loadSample("biped"));
    const model::RigNode& root = r.rig.nodes[r.index("hand.L::roots.hand")];
    EXPECT_EQ(root.parent, r.index("leg.L::ctrls.ik"));
    EXPECT_LT(maxAbsDifference(root.worldMatrix, plain.rig.nodes[plain.index("hand.L::roots.hand")].worldMatrix), kTolerance);
    expectNear(followsLegIk(r, "hand.L::ctrls.hand", {}), Vec3(0.0));
    // Bending the elbow no longer moves the hand.
    r.evaluate();
    const Vec3 rest = r.position("hand.L::ctrls.hand");
    r.evaluate({{"arm.L::ctrls.fk.1", "rz", 40.0}});
    expectNear(r.position("hand.L::ctrls.hand"), rest);
}

TEST(Mods, AParentModUnderALaterNodeKeepsTheNodesParentsFirst)
{
    ModdedRig r(bipedWith({{"", "parent: {node: 'neck::roots.fk.0', parent: 'leg.L::ctrls.ik'}"}}));
    ASSERT_TRUE(r.program) << r.log();
    EXPECT_EQ(r.log().find("mod"), std::string::npos) << r.log();
    for (model::RigNodeIndex i = 1; i < r.rig.nodes.size(); ++i) {
        ASSERT_LT(r.rig.nodes[i].parent, i) << r.rig.nodes[i].path;
        EXPECT_EQ(*r.rig.find(r.rig.nodes[i].key), i);
    }
    EXPECT_EQ(r.rig.nodes[r.index("neck::roots.fk.0")].parent, r.index("leg.L::ctrls.ik"));
    expectNear(followsLegIk(r, "neck::ctrls.fk.1", {}), Vec3(0.0)); // the neck's FK now hangs from the foot
}

TEST(Mods, AParentModThatWouldMakeACycleIsAWarningAndChangesNothing)
{
    // The arm's IK control can follow the head (a space), which hangs below the neck's FK.
    ModdedRig r(bipedWith({{"", "parent: {node: 'neck::roots.fk.0', parent: 'hand.L::ctrls.hand'}"}}));
    ASSERT_TRUE(r.program) << r.log();
    EXPECT_NE(r.log().find("global parent mod: 'hand.L::ctrls.hand' follows 'neck::roots.fk.0' (a cycle)"), std::string::npos) << r.log();
    const ModdedRig plain(test::loadSample("biped"));
    EXPECT_EQ(r.rig.nodes[r.index("neck::roots.fk.0")].parent, plain.rig.nodes[plain.index("neck::roots.fk.0")].parent);
}

TEST(Mods, AHideModTakesTheControllerAwayFromTheAnimator)
{
    ModdedRig r(bipedWith({{"arm", "hide: [ctrls.pole]"}}));
    ASSERT_TRUE(r.program) << r.log();
    const auto& controllers = r.rig.sets.at("controllers");
    for (const char* id : {"arm.L::ctrls.pole", "arm.R::ctrls.pole"}) {
        const model::RigNode& pole = r.rig.nodes[r.index(id)];
        EXPECT_TRUE(pole.hidden) << id;
        for (const model::ControllerCurve& curve : pole.curves)
            EXPECT_FALSE(curve.visible) << id; // neither drawn nor picked
        EXPECT_EQ(std::count(controllers.begin(), controllers.end(), r.index(id)), 0) << id;
        EXPECT_TRUE(r.program->channels()[r.channel(id, "tx")].locked) << id;
    }
    // Pickwalk passes it by: from the IK control down goes elsewhere, or nowhere.
    r.evaluate();
    const auto ik = r.index("arm.L::ctrls.ik");
    EXPECT_NE(eval::pickwalk(r.rig, ik, eval::WalkDirection::Down, &r.state.visible), r.index("arm.L::ctrls.pole"));
    EXPECT_NE(eval::pickwalk(r.rig, ik, eval::WalkDirection::Right, &r.state.visible), r.index("arm.L::ctrls.pole"));
}

TEST(Mods, APlugModCreatesACustomChannelWithItsSettings)
{
    ModdedRig r(bipedWith({{"arm", "plug: {channel: ctrls.ik@fist, type: float, min: 0, max: 10, default: 2, keyable: off}"},
                           {"", "plug: {channel: 'spine::ctrls.cog@mode', type: enum, labels: [walk, run, jump], default: 1}"},
                           {"", "plug: {channel: 'arm.L::ctrls.fk.0@rz', default: 20}"}}));
    ASSERT_TRUE(r.program) << r.log();
    for (const char* id : {"arm.L::ctrls.ik", "arm.R::ctrls.ik"}) {
        const eval::Channel& fist = r.program->channels()[r.channel(id, "fist")];
        EXPECT_EQ(fist.defaultValue, 2.0);
        EXPECT_EQ(fist.min, 0.0);
        EXPECT_EQ(fist.max, 10.0);
        EXPECT_FALSE(fist.keyable);
        EXPECT_FALSE(fist.locked);
    }
    const eval::Channel& mode = r.program->channels()[r.channel("spine::ctrls.cog", "mode")];
    ASSERT_TRUE(mode.isEnum());
    EXPECT_EQ(*mode.labels, (std::vector<std::string>{"walk", "run", "jump"}));
    EXPECT_EQ(mode.defaultValue, 1.0);
    // A transform channel's default: the rest pose (what reset returns to) turns the shoulder.
    EXPECT_EQ(r.program->channels()[r.channel("arm.L::ctrls.fk.0", "rz")].defaultValue, 20.0);
    const ModdedRig plain(test::loadSample("biped"));
    r.evaluate();
    EXPECT_GT(glm::length(r.position("arm.L::ctrls.fk.2") - translationOf(plain.rig.nodes[plain.index("arm.L::ctrls.fk.2")].worldMatrix)), 0.05);
}

TEST(Mods, APlugModConnectsOneChannelToAnother)
{
    ModdedRig r(bipedWith({{"", "plug: {channel: 'arm.R::ctrls.switch@ik_blend', from: 'arm.L::ctrls.switch@ik_blend'}"}}));
    ASSERT_TRUE(r.program) << r.log();
    EXPECT_TRUE(r.program->channels()[r.channel("arm.R::ctrls.switch", "ik_blend")].locked); // driven: not for animators
    for (double blend : {0.0, 1.0}) {
        r.evaluate({{"arm.L::ctrls.switch", "ik_blend", blend}});
        EXPECT_EQ(r.state.channels[r.channel("arm.R::ctrls.switch", "ik_blend")], blend);
        // The right arm shows its FK controls only while its blend (the left's) is below 1.
        EXPECT_EQ(r.state.isVisible(r.index("arm.R::ctrls.fk.0")), blend < 1.0);
    }
}

TEST(Mods, ADriveModMovesTheDrivenChannelToTheCurvesValue)
{
    const char* drive = "drive: {driver: 'arm.L::ctrls.fk.1@rz', driven: 'hand.L::ctrls.hand@rx', keys: {0: 0, 90: 30}}";
    ModdedRig r(bipedWith({{"", drive}}));
    ASSERT_TRUE(r.program) << r.log();
    ModdedRig plain(test::loadSample("biped"));
    r.evaluate({{"arm.L::ctrls.fk.1", "rz", 45.0}});
    EXPECT_NEAR(r.state.channels[r.channel("hand.L::ctrls.hand", "rx")], 15.0, kTolerance);
    plain.evaluate({{"arm.L::ctrls.fk.1", "rz", 45.0}, {"hand.L::ctrls.hand", "rx", 15.0}});
    EXPECT_LT(maxAbsDifference(r.world("hand.L::ctrls.hand"), plain.world("hand.L::ctrls.hand")), 1e-9);
    r.evaluate({{"arm.L::ctrls.fk.1", "rz", 120.0}}); // constant after the last key
    EXPECT_NEAR(r.state.channels[r.channel("hand.L::ctrls.hand", "rx")], 30.0, kTolerance);
    EXPECT_TRUE(r.program->channels()[r.channel("hand.L::ctrls.hand", "rx")].locked);
}

TEST(Mods, AVdagModChangesWherePickwalkGoesUp)
{
    ModdedRig r(bipedWith({{"", "vdag: {node: 'hand.L::ctrls.hand', parent: 'spine::ctrls.hips'}"}}));
    ASSERT_TRUE(r.program) << r.log();
    r.evaluate();
    EXPECT_EQ(eval::pickwalk(r.rig, r.index("hand.L::ctrls.hand"), eval::WalkDirection::Up, &r.state.visible),
              r.index("spine::ctrls.hips"));
    const auto children = r.rig.virtualChildren(r.index("spine::ctrls.hips"));
    EXPECT_EQ(std::count(children.begin(), children.end(), r.index("hand.L::ctrls.hand")), 1);
}

TEST(Mods, AVdagModAcrossDomainsOrInACycleIsAWarningAndChangesNothing)
{
    ModdedRig r(bipedWith({{"", "vdag: {node: 'hand.L::ctrls.hand', parent: 'spine::skin.0'}"},
                           {"", "vdag: {node: 'spine::ctrls.cog', parent: 'hand.L::ctrls.hand'}"}}));
    ModdedRig plain(test::loadSample("biped"));
    EXPECT_NE(r.log().find("a virtual parent must be of the same domain"), std::string::npos) << r.log();
    EXPECT_NE(r.log().find("(a cycle)"), std::string::npos) << r.log();
    EXPECT_EQ(r.rig.nodes[r.index("hand.L::ctrls.hand")].virtualParent, plain.rig.nodes[plain.index("hand.L::ctrls.hand")].virtualParent);
}

TEST(Mods, DriveCurvesInterpolateAndExtendAsTold)
{
    using model::CurveInfinity;
    const std::vector<model::CurveKey> keys{{0.0, 0.0}, {10.0, 1.0}, {20.0, 1.0}};
    EXPECT_DOUBLE_EQ(eval::evaluateCurve(keys, {}, CurveInfinity::Constant, CurveInfinity::Constant, 5.0), 0.5);
    EXPECT_DOUBLE_EQ(eval::evaluateCurve(keys, {}, CurveInfinity::Constant, CurveInfinity::Constant, -5.0), 0.0);
    EXPECT_DOUBLE_EQ(eval::evaluateCurve(keys, {}, CurveInfinity::Linear, CurveInfinity::Constant, -5.0), -0.5);
    EXPECT_DOUBLE_EQ(eval::evaluateCurve(keys, {}, CurveInfinity::Constant, CurveInfinity::Cycle, 25.0), 0.5);
    EXPECT_DOUBLE_EQ(eval::evaluateCurve(keys, {}, CurveInfinity::Constant, CurveInfinity::Linear, 30.0), 1.0); // flat end
    // Smooth: through every key, never above the plateau (monotone), eased in between.
    const std::vector<double> tangents = eval::smoothTangents(keys);
    for (double x = 0.0; x <= 20.0; x += 0.5) {
        const double y = eval::evaluateCurve(keys, tangents, CurveInfinity::Constant, CurveInfinity::Constant, x);
        EXPECT_LE(y, 1.0 + 1e-12) << x;
        EXPECT_GE(y, 0.0) << x;
    }
    EXPECT_DOUBLE_EQ(eval::evaluateCurve(keys, tangents, CurveInfinity::Constant, CurveInfinity::Constant, 10.0), 1.0);
    EXPECT_NE(eval::evaluateCurve(keys, tangents, CurveInfinity::Constant, CurveInfinity::Constant, 5.0), 0.5);
    EXPECT_FALSE(eval::checkCurveKeys({{1.0, 0.0}, {1.0, 2.0}}).empty());
    EXPECT_FALSE(eval::checkCurveKeys({}).empty());
}

TEST(Mods, DrivenKeysThatLoopAreRefusedAndTheRigStillEvaluates)
{
    ModdedRig r(bipedWith({{"", "drive: {driver: 'hand.L::ctrls.hand@rx', driven: 'hand.L::ctrls.hand@ry', keys: {0: 0, 1: 1}}"},
                           {"", "drive: {driver: 'hand.L::ctrls.hand@ry', driven: 'hand.L::ctrls.hand@rx', keys: {0: 0, 1: 1}}"}}));
    ASSERT_TRUE(r.program) << r.log();
    EXPECT_NE(r.log().find("would make a loop of driven keys"), std::string::npos) << r.log();
    r.evaluate({{"hand.L::ctrls.hand", "rx", 10.0}});
    EXPECT_NEAR(r.state.channels[r.channel("hand.L::ctrls.hand", "ry")], 1.0, kTolerance); // past the last key: constant
}

TEST(Mods, AnInstancesModMovesTheMirroredCopyAsTheMirrorImage)
{
    // Authored for the left side; the right copy's curve is the mirror image's.
    ModdedRig r(bipedWith({{"hand", "drive: {driver: 'arm::ctrls.fk.1@rz', driven: ctrls.hand@ry, keys: {0: 0, 90: 30}}"},
                           {"hand", "plug: {channel: ctrls.hand@rz, default: 10}"}}));
    ASSERT_TRUE(r.program) << r.log();
    const Mat4 mirror = glm::scale(Mat4(1.0), Vec3(-1.0, 1.0, 1.0)); // the biped's L/R plane
    r.evaluate({{"arm.L::ctrls.fk.1", "rz", 45.0}, {"arm.R::ctrls.fk.1", "rz", -45.0}}); // a mirrored pose
    EXPECT_NEAR(r.state.channels[r.channel("hand.L::ctrls.hand", "ry")], 15.0, kTolerance);
    EXPECT_NEAR(r.state.channels[r.channel("hand.R::ctrls.hand", "ry")], -15.0, kTolerance);
    EXPECT_EQ(r.program->channels()[r.channel("hand.R::ctrls.hand", "rz")].defaultValue, -10.0);
    EXPECT_LT(maxAbsDifference(mirror * r.world("hand.L::ctrls.hand") * mirror, r.world("hand.R::ctrls.hand")), 1e-6);
}

TEST(Mods, AVdagModOnASkinJointChangesTheExportSkeleton)
{
    ModdedRig r(bipedWith({{"", "vdag: {node: 'index.L::skin.0', parent: 'spine::skin.0'}"}}));
    ASSERT_TRUE(r.program) << r.log();
    auto skeleton = model::extractSkeleton(r.rig);
    ASSERT_TRUE(skeleton.ok()) << formatAll(skeleton.diagnostics());
    const auto joint = [&](const std::string& id) {
        const auto it = std::find_if(skeleton->joints.begin(), skeleton->joints.end(),
                                     [&](const model::SkeletonJoint& j) { return j.node == r.index(id); });
        EXPECT_NE(it, skeleton->joints.end()) << id;
        return int(it - skeleton->joints.begin());
    };
    EXPECT_EQ(skeleton->joints[joint("index.L::skin.0")].parent, joint("spine::skin.0"));
    // The bind pose stays: the joint's world is its rest, only its parent changed.
    EXPECT_LT(maxAbsDifference(skeleton->joints[joint("index.L::skin.0")].bindWorld,
                               r.rig.nodes[r.index("index.L::skin.0")].worldMatrix), 1e-12);
}
