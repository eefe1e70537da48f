// Limb spaces as an animator checks them on the built and evaluated biped and
// quadruped (issue 22): FK orientation isolation (`fk_space`: the FK arm or
// leg keeps its place on the clavicle or pelvis and its orientation from the
// chosen space, switchable live by the first FK control's `space` attribute),
// mirrored on the right branch, and `space_switch` off giving the IK control,
// the pole and the first FK control no switch but their option's space; a
// leg without its reverse foot (`reverse_lock` off); the end joint's
// orientation (`effector_plane`).
#include "EvalTestSupport.h"
#include "core/IncrementalCheck.h"

#include "rigging/BuildCache.h"

#include <gtest/gtest.h>

#include <map>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

const char* const kLimbs[] = {"arm.L", "arm.R", "leg.L", "leg.R"};

model::GuideDocument sampleWith(const std::string& sample, const std::map<std::string, std::map<std::string, Value>>& options)
{
    model::GuideDocument guide = test::loadSample(sample);
    for (const auto& i : guide.instances())
        if (auto it = options.find(i.name); it != options.end())
            for (const auto& [name, value] : it->second)
                guide.instance(i.id)->options[name] = value;
    return guide;
}

Mat3 rotationAt(const PosedRig& r, const std::string& id) { return r.state().world[r.index(id)].rotation(); }

double largestDifference(const Mat3& a, const Mat3& b)
{
    double most = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int row = 0; row < 3; ++row)
            most = std::max(most, std::abs(a[c][row] - b[c][row]));
    return most;
}

// How `node` moved from its rest place: its evaluated world times its inverse rest world.
eval::Affine motionOf(const PosedRig& r, const std::string& id)
{
    const auto n = r.index(id);
    return r.state().world[n] * r.program->restWorld(n).inverse();
}

// Every limb in FK; the COG 0.3 m forward and turned `degrees` about Y.
Pose fkPose(const PosedRig& r, double degrees)
{
    Pose pose = r.defaults();
    for (const char* limb : kLimbs)
        pose[r.channel(std::string(limb) + "::ctrls.switch", "ik_blend")] = 0.0;
    pose[r.channel("spine::ctrls.cog", "tz")] = 0.3;
    pose[r.channel("spine::ctrls.cog", "ry")] = degrees;
    return pose;
}

TEST(LimbRig, FkWorldSpaceKeepsTheUpperArmAndThighWorldOrientationWhileTheirPlaceFollowsTheBody)
{
    PosedRig r(sampleWith("biped", {{"arm", {{"fk_space", std::string("world")}}}, {"leg", {{"fk_space", std::string("world")}}}}));
    ASSERT_TRUE(r.ok());
    for (const char* limb : kLimbs) {
        const std::string fk = std::string(limb) + "::ctrls.fk.0", blend = std::string(limb) + "::blend.0";
        r.evaluate(fkPose(r, 0.0));
        const Mat3 before = rotationAt(r, fk);
        Pose pose = fkPose(r, 90.0);
        pose[r.channel("spine::ctrls.ik_chest", "rz")] = 25.0; // the chest and the clavicle turn too
        if (r.rig.findPath(std::string(limb) + "::ctrls.clavicle"))
            pose[r.channel(std::string(limb) + "::ctrls.clavicle", "rz")] = 20.0;
        r.evaluate(pose);
        EXPECT_LT(largestDifference(rotationAt(r, fk), before), 1e-9) << limb;
        EXPECT_LT(largestDifference(rotationAt(r, blend), before), 1e-9) << limb << ": the deforming chain";
        // Its place rides on what the limb hangs from.
        const std::string group = std::string(limb) + "::grps.limb";
        EXPECT_LT(glm::length(r.position(fk) - motionOf(r, group).apply(r.restPosition(fk))), 1e-9) << limb;
        EXPECT_GT(glm::length(r.position(fk) - r.restPosition(fk)), 0.1) << limb << " did not travel with the body";
    }
}

TEST(LimbRig, FkParentSpaceTurnsTheUpperArmWithTheBodyAsBefore)
{
    PosedRig r(sampleWith("biped", {{"arm", {{"fk_space", std::string("parent")}}}})); // the sample's arms use chest
    ASSERT_TRUE(r.ok());
    for (const char* limb : kLimbs) {
        const std::string fk = std::string(limb) + "::ctrls.fk.0";
        EXPECT_EQ(r.program->channels().defaults()[r.channel(fk, "space")], 0.0) << limb << ": parent is the default";
        r.evaluate(fkPose(r, 90.0));
        const Mat3 carried = motionOf(r, std::string(limb) + "::grps.limb").rotation() * r.program->restWorld(r.index(fk)).rotation();
        EXPECT_LT(largestDifference(rotationAt(r, fk), carried), 1e-9) << limb;
        EXPECT_GT(largestDifference(rotationAt(r, fk), r.program->restWorld(r.index(fk)).rotation()), 0.5) << limb;
    }
}

TEST(LimbRig, FkChestSpaceFollowsTheChestButNotTheClavicle)
{
    PosedRig r(sampleWith("biped", {{"arm", {{"fk_space", std::string("chest")}}}}));
    ASSERT_TRUE(r.ok());
    Pose pose = fkPose(r, 30.0);
    pose[r.channel("spine::ctrls.ik_chest", "ry")] = 40.0;
    for (const char* arm : {"arm.L", "arm.R"})
        pose[r.channel(std::string(arm) + "::ctrls.clavicle", "rz")] = 25.0;
    r.evaluate(pose);
    const Mat3 chest = motionOf(r, "spine::blend.4").rotation();
    for (const char* arm : {"arm.L", "arm.R"}) {
        const std::string fk = std::string(arm) + "::ctrls.fk.0";
        const Mat3 rest = r.program->restWorld(r.index(fk)).rotation();
        EXPECT_LT(largestDifference(rotationAt(r, fk), chest * rest), 1e-9) << arm;
        const Mat3 withClavicle = motionOf(r, std::string(arm) + "::grps.limb").rotation() * rest;
        EXPECT_GT(largestDifference(rotationAt(r, fk), withClavicle), 0.1) << arm << ": the clavicle's turn leaked in";
    }
}

TEST(LimbRig, TheFkSpaceSwitchesLiveAndMatchingKeepsTheArmInPlace)
{
    PosedRig r("biped");
    ASSERT_TRUE(r.ok());
    const std::string fk = "arm.L::ctrls.fk.0";
    const int space = r.channel(fk, "space");
    const auto& labels = r.rig.nodes[r.index(fk)].attributes;
    ASSERT_FALSE(labels.empty());
    r.evaluate(fkPose(r, 0.0));
    const Mat3 rest = rotationAt(r, fk);
    Pose pose = fkPose(r, 90.0);
    pose[space] = 3.0; // [parent, chest, cog, world, root]
    r.evaluate(pose);
    EXPECT_LT(largestDifference(rotationAt(r, fk), rest), 1e-9) << "world while animating";
    pose[space] = 2.0; // cog: turns with the COG
    r.evaluate(pose);
    EXPECT_LT(largestDifference(rotationAt(r, fk), motionOf(r, "spine::ctrls.cog").rotation() * rest), 1e-9) << "cog";

    // Back to parent with Match on switch: the arm stays where it is.
    pose[r.channel(fk, "rz")] = 35.0;
    pose[r.channel("arm.L::ctrls.clavicle", "rz")] = 15.0;
    pose[space] = 3.0;
    r.evaluate(pose);
    const Mat4 before = r.state().worldMatrix(r.index(fk));
    const Vec3 hand = r.position("arm.L::blend.2");
    const Pose switched = r.posing->switchSpace(pose, space, 0.0, true);
    EXPECT_EQ(switched[space], 0.0);
    r.evaluate(switched);
    EXPECT_LT(largestDifference(Mat3(r.state().worldMatrix(r.index(fk))), Mat3(before)), 1e-9);
    EXPECT_LT(glm::length(r.position("arm.L::blend.2") - hand), 1e-9);
}

TEST(LimbRig, TheRightFkArmIsIsolatedAsTheMirrorOfTheLeft)
{
    PosedRig r(sampleWith("biped", {{"arm", {{"fk_space", std::string("world")}}}}));
    ASSERT_TRUE(r.ok());
    Pose pose = fkPose(r, 0.0);
    pose[r.channel("arm.L::ctrls.fk.0", "rx")] = 20.0;
    pose[r.channel("arm.L::ctrls.fk.0", "ry")] = 30.0;
    pose[r.channel("arm.L::ctrls.fk.0", "rz")] = -40.0;
    pose[r.channel("arm.L::ctrls.fk.1", "rz")] = 50.0;
    pose = r.posing->mirror(pose, {r.index("arm.L::ctrls.fk.0"), r.index("arm.L::ctrls.fk.1")});
    r.evaluate(pose);
    const Mat3 left = rotationAt(r, "arm.L::ctrls.fk.0"), right = rotationAt(r, "arm.R::ctrls.fk.0");
    // A pitch of the COG keeps the body symmetric about X: both arms keep their orientation and mirror each other.
    pose[r.channel("spine::ctrls.cog", "rx")] = 40.0;
    r.evaluate(pose);
    EXPECT_LT(largestDifference(rotationAt(r, "arm.L::ctrls.fk.0"), left), 1e-9);
    EXPECT_LT(largestDifference(rotationAt(r, "arm.R::ctrls.fk.0"), right), 1e-9);
    const Vec3 mirror(-1.0, 1.0, 1.0);
    for (const char* joint : {"blend.1", "blend.2"}) {
        const Vec3 l = r.position(std::string("arm.L::") + joint), rr = r.position(std::string("arm.R::") + joint);
        EXPECT_LT(glm::length(rr - l * mirror), 1e-9) << joint;
    }
}

TEST(LimbRig, TheBipedAndQuadrupedBuildCleanWithEveryFkSpace)
{
    const std::pair<const char*, std::vector<std::string>> samples[] = {{"biped", {"arm", "leg"}},
                                                                        {"quadruped", {"front_leg", "hind_leg"}}};
    for (const auto& [sample, limbs] : samples)
        for (const char* space : {"parent", "chest", "cog", "world", "root"}) {
            std::map<std::string, std::map<std::string, Value>> options;
            for (const std::string& limb : limbs)
                options[limb] = {{"fk_space", std::string(space)}};
            const model::GuideDocument guide = sampleWith(sample, options);
            const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
            EXPECT_TRUE(rig.diagnostics.empty()) << sample << " " << space << ": " << formatAll(rig.diagnostics);
            auto program = eval::RigProgram::compile(rig);
            EXPECT_TRUE(program.ok()) << sample << " " << space;
        }
}

TEST(LimbRig, SpaceSwitchOffGivesTheLimbControlsNoSwitchButTheirOptionsSpaces)
{
    PosedRig r(sampleWith("biped", {{"arm",
                                     {{"space_switch", false},
                                      {"fk_space", std::string("world")},
                                      {"ik_space", std::string("cog")},
                                      {"pv_space", std::string("follow")}}}}));
    ASSERT_TRUE(r.ok());
    for (const char* arm : {"arm.L", "arm.R"}) {
        for (const char* control : {"ctrls.ik", "ctrls.pole", "ctrls.fk.0"})
            EXPECT_FALSE(r.program->channels().find(r.index(std::string(arm) + "::" + control), "space").has_value())
                << arm << " " << control;
        for (const auto& c : r.rig.constraints)
            if (c.key.copy() == r.rig.nodes[r.index(std::string(arm) + "::ctrls.ik")].key.copy())
                EXPECT_NE(c.kind(), model::ConstraintKind::Space) << c.key.tag;
    }
    for (const char* leg : {"leg.L", "leg.R"}) // the legs keep their switches
        for (const char* control : {"ctrls.ik", "ctrls.pole", "ctrls.fk.0"})
            EXPECT_TRUE(r.program->channels().find(r.index(std::string(leg) + "::" + control), "space").has_value()) << leg;

    r.evaluate(fkPose(r, 0.0));
    const Mat3 rest = rotationAt(r, "arm.L::ctrls.fk.0");
    r.evaluate(fkPose(r, 90.0));
    EXPECT_LT(largestDifference(rotationAt(r, "arm.L::ctrls.fk.0"), rest), 1e-9) << "fk_space world, fixed";
    const eval::Affine cog = motionOf(r, "spine::ctrls.cog");
    EXPECT_LT(glm::length(r.position("arm.L::ctrls.ik") - cog.apply(r.restPosition("arm.L::ctrls.ik"))), 1e-9)
        << "ik_space cog, fixed";
    const eval::Affine follow = motionOf(r, "arm.L::spaces.pole_follow");
    EXPECT_LT(glm::length(r.position("arm.L::ctrls.pole") - follow.apply(r.restPosition("arm.L::ctrls.pole"))), 1e-9)
        << "pv_space follow, fixed";
}

TEST(LimbRig, AnUnknownFkSpaceIsReportedAndTheArmKeepsItsParent)
{
    const model::Rig rig = rigging::buildRig(sampleWith("biped", {{"arm", {{"fk_space", std::string("sideways")}}}}),
                                             test::builtinTemplates());
    const model::Rig parent = rigging::buildRig(sampleWith("biped", {{"arm", {{"fk_space", std::string("parent")}}}}),
                                                test::builtinTemplates());
    ASSERT_EQ(rig.diagnostics.size(), 2u) << formatAll(rig.diagnostics);
    for (const auto& d : rig.diagnostics)
        EXPECT_NE(d.message.find("option 'fk_space' = 'sideways' is not one of its labels, using the default"), std::string::npos)
            << d.message;
    const std::string dump = io::writeRigDump(rig), expected = io::writeRigDump(parent);
    EXPECT_EQ(dump.substr(0, dump.find("diagnostics:")), expected.substr(0, expected.find("diagnostics:")));
}

TEST(LimbRig, FkSpaceAndSpaceSwitchRebuildIncrementallyAsAFullBuild)
{
    model::GuideDocument guide = sampleWith("biped", {{"arm", {{"fk_space", std::string("chest")}}}});
    rigging::BuildCache cache;
    test::buildAndCompare(guide, cache, "first");
    for (const auto& i : guide.instances()) {
        if (i.name == "arm")
            guide.instance(i.id)->options["space_switch"] = false;
        if (i.name == "spine") // the chest the arm follows moves
            guide.instance(i.id)->joints.back().local.translate.y += 0.05;
    }
    test::buildAndCompare(guide, cache, "space_switch off, spine moved");
    for (const auto& i : guide.instances())
        if (i.name == "leg")
            guide.instance(i.id)->options["fk_space"] = std::string("hips");
    test::buildAndCompare(guide, cache, "leg fk_space hips");
    for (const auto& i : guide.instances())
        if (i.name == "leg") {
            guide.instance(i.id)->options["reverse_lock"] = false;
            guide.instance(i.id)->options["effector_plane"] = std::string("ground");
        }
    test::buildAndCompare(guide, cache, "leg without reverse foot, ground effector");
}

TEST(LimbRig, ALegWithoutReverseLockHasNoFootPivotsAndItsIkControlCarriesAnkleAndToe)
{
    PosedRig r(sampleWith("biped", {{"leg", {{"reverse_lock", false}}}}));
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.rig.diagnostics.empty()) << formatAll(r.rig.diagnostics);
    for (const char* leg : {"leg.L", "leg.R"}) {
        const std::string ik = std::string(leg) + "::ctrls.ik";
        for (const auto& node : r.rig.nodes)
            EXPECT_EQ(node.path.rfind(std::string(leg) + "::rfoot.", 0), std::string::npos) << node.path;
        EXPECT_FALSE(r.program->channels().find(r.index(ik), "roll").has_value()) << leg;
        Pose pose = r.defaults();
        pose[r.channel(std::string(leg) + "::ctrls.switch", "ik_blend")] = 1.0;
        pose[r.channel(ik, "ty")] = 0.1;
        pose[r.channel(ik, "rx")] = 30.0;
        pose[r.channel(ik, "ry")] = 20.0;
        r.evaluate(pose);
        const eval::Affine carried = motionOf(r, ik);
        for (const char* joint : {"::blend.2", "::blend.ball"}) {
            const std::string id = std::string(leg) + joint;
            EXPECT_LT(glm::length(r.position(id) - carried.apply(r.restPosition(id))), 1e-9) << id;
            EXPECT_LT(largestDifference(rotationAt(r, id), carried.rotation() * r.program->restWorld(r.index(id)).rotation()), 1e-9)
                << id;
        }
        // IK -> FK and back keep the leg in place.
        auto fk = r.posing->ikToFk(pose, r.index(ik));
        ASSERT_TRUE(fk) << formatAll(fk.diagnostics());
        r.evaluate(*fk);
        const Vec3 ball = r.position(std::string(leg) + "::blend.ball");
        EXPECT_LT(glm::length(ball - carried.apply(r.restPosition(std::string(leg) + "::blend.ball"))), 1e-5) << leg;
        auto back = r.posing->fkToIk(*fk, r.index(std::string(leg) + "::ctrls.fk.1"));
        ASSERT_TRUE(back) << formatAll(back.diagnostics());
        r.evaluate(*back);
        EXPECT_LT(glm::length(r.position(std::string(leg) + "::blend.ball") - ball), 1e-5) << leg;
    }
}

Vec3 restAxis(const PosedRig& r, const std::string& id, int column)
{
    return Vec3(r.rig.nodes[r.index(id)].worldMatrix[column]);
}

TEST(LimbRig, EffectorPlaneGroundLevelsTheFeetAndYTurnsTheHandsUpOnBothSides)
{
    PosedRig r(sampleWith("biped", {{"leg", {{"effector_plane", std::string("ground")}, {"ik_orient", std::string("joint")}}},
                                    {"arm", {{"effector_plane", std::string("y")}}}}));
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.rig.diagnostics.empty()) << formatAll(r.rig.diagnostics);
    PosedRig before("biped");
    const Vec3 up(0.0, 1.0, 0.0);
    for (const char* leg : {"leg.L", "leg.R"})
        for (const char* joint : {"::blend.2", "::blend.ball", "::ctrls.fk.2", "::ctrls.ik"}) {
            const std::string id = std::string(leg) + joint;
            EXPECT_LT(glm::length(restAxis(r, id, 1) - up), 1e-9) << id << ": Y straight up";
            EXPECT_LT(std::abs(restAxis(r, id, 0).y), 1e-9) << id << ": X level";
            EXPECT_LT(glm::length(r.restPosition(id) - before.restPosition(id)), 1e-9) << id << " moved";
        }
    for (const char* arm : {"arm.L", "arm.R"}) {
        const std::string wrist = std::string(arm) + "::blend.2";
        const Vec3 aim = restAxis(before, wrist, 0);
        EXPECT_LT(glm::length(restAxis(r, wrist, 0) - aim), 1e-9) << arm << ": still aimed down the hand";
        EXPECT_LT(glm::length(restAxis(r, wrist, 1) - glm::normalize(up - aim * glm::dot(up, aim))), 1e-9) << arm;
        EXPECT_GT(glm::length(restAxis(before, wrist, 1) - restAxis(r, wrist, 1)), 0.1) << arm << ": auto differs";
    }
    // The leg still matches IK to FK and back with its levelled ankle.
    Pose pose = r.defaults();
    pose[r.channel("leg.L::ctrls.switch", "ik_blend")] = 0.0;
    pose[r.channel("leg.L::ctrls.fk.0", "rx")] = 25.0;
    pose[r.channel("leg.L::ctrls.fk.1", "rz")] = 40.0;
    pose[r.channel("leg.L::ctrls.fk.2", "ry")] = 15.0;
    r.evaluate(pose);
    const Vec3 ball = r.position("leg.L::blend.ball"), ankle = r.position("leg.L::blend.2");
    auto ik = r.posing->fkToIk(pose, r.index("leg.L::ctrls.fk.1"));
    ASSERT_TRUE(ik) << formatAll(ik.diagnostics());
    r.evaluate(*ik);
    EXPECT_LT(glm::length(r.position("leg.L::blend.ball") - ball), 1e-5);
    EXPECT_LT(glm::length(r.position("leg.L::blend.2") - ankle), 1e-5);
}

TEST(LimbRig, AnEffectorPlaneAlongTheAimWarnsAndKeepsTheLimbsPlane)
{
    const model::Rig rig = rigging::buildRig(sampleWith("biped", {{"arm", {{"effector_plane", std::string("x")}}}}),
                                             test::builtinTemplates());
    const model::Rig plain = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    ASSERT_EQ(rig.diagnostics.size(), 2u) << formatAll(rig.diagnostics); // arm.L and arm.R
    EXPECT_NE(rig.diagnostics[0].message.find("effector_plane 'x': the end joint aims along that axis"), std::string::npos)
        << rig.diagnostics[0].message;
    EXPECT_EQ(io::writeRigDump(rig).substr(0, io::writeRigDump(rig).find("diagnostics:")),
              io::writeRigDump(plain).substr(0, io::writeRigDump(plain).find("diagnostics:")));
}

} // namespace
} // namespace rs
