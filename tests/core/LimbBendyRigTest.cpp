// Bendy limbs with the rest of the rig (issue 22, item 2; option `bendy` of
// arm.limb, leg.limb and quad.leg): the twist is still shared linearly along
// the bent segment, the right side is the exact mirror of the left at rest
// and posed, IK/FK snapping keeps every joint within 10 micrometres, the bend
// controls show in pickwalk under the switch and only move and turn, the
// volume compensation's power (`stomp_power`), a warning when there are no
// twist joints to bend, and an incremental build equal to a full one.
#include "EvalTestSupport.h"
#include "IncrementalCheck.h"
#include "LimbBendySupport.h"
#include "io/RigDump.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;
using namespace test::bendy;

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

double twistDegrees(const PosedRig& r, const std::string& id, const Vec3& axis)
{
    const Mat3 rest = eval::Affine::fromMatrix(r.rig.nodes[r.index(id)].worldMatrix).rotation();
    Quat q = glm::quat_cast(r.state().world[r.index(id)].rotation() * glm::transpose(rest));
    if (q.w < 0.0)
        q = -q;
    return glm::degrees(2.0 * std::atan2(glm::dot(Vec3(q.x, q.y, q.z), axis), q.w));
}

TEST(LimbBendy, TwistIsStillSharedLinearlyAlongTheBentSegment)
{
    PosedRig r(bendyBiped());
    ASSERT_TRUE(r.ok());
    for (const std::string limb : kLimbs) {
        const Vec3 elbow = r.restPosition(limb + "::blend.1"), wrist = r.restPosition(limb + "::blend.2");
        const Vec3 lower = glm::normalize(wrist - elbow);
        // The lower bend control pulled 3 cm off, then the end turned 90 degrees about the lower bone.
        Pose pose = r.defaults();
        pose[r.channel(limb + "::ctrls.switch", "ik_blend")] = 0.0;
        const std::string bend = limb + "::ctrls.bend.dn";
        pose = r.moveTo(pose, bend, r.restPosition(bend) + bendNormal(r, limb) * 0.03, bend);
        Mat4 world = r.evaluate(pose).worldMatrix(r.index(limb + "::ctrls.fk.2"));
        const Vec3 at(world[3]);
        world = Mat4(glm::mat3_cast(glm::angleAxis(glm::radians(90.0), lower)) * Mat3(world));
        world[3] = Vec4(at, 1.0);
        const Pose twisted = r.posing->placeAt(pose, r.index(limb + "::ctrls.fk.2"), world);
        // Each twist joint's roll about its own aim, the bow taken out: its
        // twist with the end turned minus without.
        r.evaluate(pose);
        std::vector<Mat3> bowed;
        for (int t = 0; t < 2; ++t) bowed.push_back(r.state().world[r.index(limb + "::skin.dn." + std::to_string(t))].rotation());
        r.evaluate(twisted);
        for (int t = 0; t < 2; ++t) {
            const std::string joint = limb + "::skin.dn." + std::to_string(t);
            const Mat3 now = r.state().world[r.index(joint)].rotation();
            Quat q = glm::quat_cast(now * glm::transpose(bowed[t]));
            if (q.w < 0.0) q = -q;
            const Vec3 aim = Vec3(now[0]) * aimSign(r, joint, lower);
            const double degrees = glm::degrees(2.0 * std::atan2(glm::dot(Vec3(q.x, q.y, q.z), aim), q.w));
            EXPECT_NEAR(degrees, 90.0 * (t + 1) / 3.0, 0.5) << joint;
        }
        EXPECT_NEAR(twistDegrees(r, limb + "::skin.limb.1", lower), 0.0, 0.5) << limb;
    }
}

Mat4 reflected(const Mat4& m)
{
    const Mat4 mirror = glm::scale(Mat4(1.0), Vec3(-1.0, 1.0, 1.0));
    return mirror * m * mirror;
}

TEST(LimbBendy, TheRightSideIsTheExactMirrorOfTheLeftAtRestAndPosed)
{
    PosedRig r(bendyBiped());
    ASSERT_TRUE(r.ok());
    std::mt19937 random(22);
    std::uniform_real_distribution<double> offset(-0.05, 0.05), angle(-30.0, 30.0);
    Pose pose = r.defaults();
    std::vector<model::RigNodeIndex> left;
    for (const char* limb : {"arm.L", "leg.L"})
        for (const char* control : {"ctrls.tweak", "ctrls.bend.up", "ctrls.bend.dn", "ctrls.fk.1", "ctrls.ik"}) {
            const std::string id = std::string(limb) + "::" + control;
            left.push_back(r.index(id));
            for (const char* c : {"tx", "ty", "tz"})
                if (auto channel = r.program->channels().find(r.index(id), c); channel && !r.program->channels()[*channel].locked)
                    pose[*channel] = offset(random);
            for (const char* c : {"rx", "ry", "rz"})
                if (auto channel = r.program->channels().find(r.index(id), c); channel && !r.program->channels()[*channel].locked)
                    pose[*channel] = angle(random);
        }
    int pairs = 0;
    for (const bool posed : {false, true}) {
        const auto& state = r.evaluate(posed ? r.posing->mirror(pose, left) : r.defaults());
        for (model::RigNodeIndex i = 0; i < r.rig.nodes.size(); ++i) {
            const auto& node = r.rig.nodes[i];
            if (node.twin == model::kNoNode || !(startsWith(node.path, "arm.L::") || startsWith(node.path, "leg.L::")))
                continue;
            ++pairs;
            EXPECT_LT(maxAbsDifference(state.worldMatrix(node.twin), reflected(state.worldMatrix(i))), 1e-6)
                << node.path << (posed ? " posed" : " at rest");
        }
    }
    EXPECT_GT(pairs, 60);
}

TEST(LimbBendy, IkFkSnapKeepsEveryJointWithinTenMicrometresWithBentSegments)
{
    for (const char* sample : {"biped", "quadruped"}) {
        model::GuideDocument guide = test::loadSample(sample);
        std::vector<std::string> limbs;
        for (const auto& i : guide.instances())
            if (i.templateId == "arm.limb" || i.templateId == "leg.limb" || i.templateId == "quad.leg") {
                guide.instance(i.id)->options["bendy"] = Value(true);
                limbs.push_back(i.name);
            }
        PosedRig r(guide);
        ASSERT_TRUE(r.ok());
        for (model::RigNodeIndex switchNode = 0; switchNode < r.rig.nodes.size(); ++switchNode) {
            const std::string& path = r.rig.nodes[switchNode].path;
            if (path.size() < 15 || path.compare(path.size() - 14, 14, "::ctrls.switch") != 0)
                continue;
            const std::string limb = path.substr(0, path.size() - 14);
            std::vector<model::RigNodeIndex> joints;
            for (model::RigNodeIndex i = 0; i < r.rig.nodes.size(); ++i)
                if (startsWith(r.rig.nodes[i].path, limb + "::skin."))
                    joints.push_back(i);
            Pose pose = r.defaults();
            for (const char* bend : {"ctrls.bend.up", "ctrls.bend.dn", "ctrls.tweak"})
                pose = r.moveTo(pose, limb + "::" + bend, r.restPosition(limb + "::" + bend) + Vec3(0.02, -0.01, 0.03), limb + "::" + bend);
            pose[r.channel(limb + "::ctrls.switch", "ik_blend")] = 1.0;
            pose = r.moveTo(pose, limb + "::ctrls.ik", r.restPosition(limb + "::ctrls.ik") + Vec3(0.03, 0.08, 0.05), limb + "::ctrls.ik");
            r.evaluate(pose);
            std::vector<Vec3> before;
            for (auto j : joints) before.push_back(r.state().world[j].translation);
            auto fk = r.posing->ikToFk(pose, switchNode);
            ASSERT_TRUE(fk) << formatAll(fk.diagnostics());
            r.evaluate(*fk);
            for (std::size_t k = 0; k < joints.size(); ++k)
                EXPECT_LT(glm::length(r.state().world[joints[k]].translation - before[k]), 1e-5) << r.rig.nodes[joints[k]].path << " IK to FK";
            auto back = r.posing->fkToIk(*fk, switchNode);
            ASSERT_TRUE(back) << formatAll(back.diagnostics());
            r.evaluate(*back);
            for (std::size_t k = 0; k < joints.size(); ++k)
                EXPECT_LT(glm::length(r.state().world[joints[k]].translation - before[k]), 1e-5) << r.rig.nodes[joints[k]].path << " FK to IK";
        }
    }
}

TEST(LimbBendy, BendControlsAreShownInIkAndFkPickwalkUnderTheSwitchAndMoveAndTurnOnly)
{
    model::GuideDocument guide = bendyBiped();
    guide.build.cleanup = true;
    PosedRig r(guide);
    ASSERT_TRUE(r.ok());
    for (const std::string limb : kLimbs) {
        const auto tweak = r.index(limb + "::ctrls.tweak");
        EXPECT_EQ(r.rig.nodes[tweak].virtualParent, r.index(limb + "::ctrls.switch")) << limb;
        for (const char* segment : {"up", "dn"}) {
            const auto bend = r.index(limb + "::ctrls.bend." + segment);
            EXPECT_EQ(r.rig.nodes[bend].virtualParent, tweak) << limb;
            EXPECT_FALSE(r.rig.nodes[bend].curves.empty()) << limb << " has a shape";
            const auto& channels = r.rig.nodes[bend].channels;
            for (int c : {0, 1, 2, 3, 4, 5}) EXPECT_FALSE(channels.isLocked(c)) << limb << " translate and rotate, channel " << c;
            EXPECT_TRUE(channels.isLocked(6)) << limb << " scale means nothing to a curve point";
        }
        for (const double blend : {0.0, 1.0}) {
            Pose pose = r.defaults();
            pose[r.channel(limb + "::ctrls.switch", "ik_blend")] = blend;
            const auto& state = r.evaluate(pose);
            for (const char* id : {"ctrls.tweak", "ctrls.bend.up", "ctrls.bend.dn"})
                EXPECT_TRUE(state.isVisible(r.index(limb + "::" + id))) << limb << " " << id << " at ik_blend " << blend;
        }
    }
}

TEST(LimbBendy, StompPowerSetsTheVolumeCompensation)
{
    for (const double power : {-0.5, -1.0, 0.0}) {
        PosedRig r(bipedWith({{"volume", Value(true)}, {"stomp_power", Value(power)}}));
        ASSERT_TRUE(r.ok());
        const std::string limb = "arm.L";
        const Vec3 root = r.restPosition(limb + "::ik.0"), mid = r.restPosition(limb + "::ik.1"), end = r.restPosition(limb + "::ik.2");
        const double reach = glm::length(mid - root) + glm::length(end - mid);
        Pose pose = r.defaults();
        pose[r.channel(limb + "::ctrls.switch", "ik_blend")] = 1.0;
        r.evaluate(r.moveTo(pose, limb + "::ctrls.ik", root + glm::normalize(end - root) * reach * 1.44, limb + "::ik.2"));
        const Vec3 scale = r.state().world[r.index(limb + "::ik.0")].scale();
        const double rest = eval::Affine::fromMatrix(r.rig.nodes[r.index(limb + "::ik.0")].worldMatrix).scale().y;
        EXPECT_NEAR(scale.y / rest, std::pow(1.44, power), 1e-6) << "stomp_power " << power;
    }
    PosedRig clamped(bipedWith({{"stomp_power", Value(-2.0)}}));
    bool warned = false;
    for (const auto& d : clamped.rig.diagnostics)
        warned = warned || d.message.find("option 'stomp_power' = -2.0 is out of range, using -1.0") != std::string::npos;
    EXPECT_TRUE(warned) << formatAll(clamped.rig.diagnostics);
}

TEST(LimbBendy, BendyWithoutTwistJointsWarnsThatNothingBends)
{
    const model::Rig rig = rigging::buildRig(bendyBiped({{"twist_upper", Value(0LL)}, {"twist_lower", Value(0LL)}}),
                                             test::builtinTemplates());
    int warnings = 0;
    for (const auto& d : rig.diagnostics)
        warnings += d.message.find("no joint rides the bend controls' curves") != std::string::npos ? 1 : 0;
    EXPECT_EQ(warnings, 4) << formatAll(rig.diagnostics); // each arm and leg copy
}

TEST(LimbBendy, IncrementalBuildMakesWhatAFullBuildMakes)
{
    model::GuideDocument guide = bendyBiped();
    rigging::BuildCache cache;
    test::buildAndCompare(guide, cache, "first build");
    for (const auto& i : guide.instances())
        if (i.name == "arm")
            guide.instance(i.id)->options["smooth_type"] = Value(std::string("parametric"));
    test::buildAndCompare(guide, cache, "smooth_type changed");
    for (const auto& i : guide.instances())
        if (i.name == "leg")
            guide.instance(i.id)->options["bendy"] = Value(false);
    test::buildAndCompare(guide, cache, "bendy off on the legs");
}

} // namespace
} // namespace rs
