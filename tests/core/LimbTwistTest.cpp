// A limb's advanced twist as an animator checks it on the built and evaluated
// biped (issue 22; option `advanced_twist` of arm.limb, leg.limb, quad.leg):
// nothing moves at the attributes' defaults, twist_start / twist_mid /
// twist_end roll the twist joints linearly over the segments they bound,
// twist_bias reshapes how the twist joints share their segment's twist, the
// right side is the exact mirror of the left, and an incremental rebuild
// makes what a full build makes.
#include "EvalTestSupport.h"
#include "IncrementalCheck.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

const char* const kLimbs[] = {"arm.L", "arm.R", "leg.L", "leg.R"};

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

Mat4 reflected(const Mat4& m)
{
    const Mat4 mirror = glm::scale(Mat4(1.0), Vec3(-1.0, 1.0, 1.0));
    return mirror * m * mirror;
}

Mat3 rotationAt(const PosedRig& r, const std::string& id) { return r.state().world[r.index(id)].rotation(); }

// How far `id` turned about its own X axis (its bone) from `before`, in degrees.
double rollDegrees(const PosedRig& r, const std::string& id, const Mat3& before)
{
    const Vec3 axis = glm::normalize(before[0]);
    Quat q = glm::quat_cast(rotationAt(r, id) * glm::transpose(before));
    if (q.w < 0.0)
        q = -q;
    return glm::degrees(2.0 * std::atan2(glm::dot(Vec3(q.x, q.y, q.z), axis), q.w));
}

// A pose that bends every limb in IK and moves what hangs above: the twists
// have something to share.
Pose bentPose(PosedRig& r, bool turnTheBody = true)
{
    Pose pose = r.defaults();
    for (const std::string limb : kLimbs) {
        pose[r.channel(limb + "::ctrls.switch", "ik_blend")] = 1.0;
        pose = r.moveTo(pose, limb + "::ctrls.ik", r.restPosition(limb + "::ik.2") + Vec3(0.05, 0.12, 0.08), limb + "::ik.2");
        pose[r.channel(limb + "::ctrls.ik", "ry")] = 35.0;
        pose[r.channel(limb + "::ctrls.ik", "rx")] = -20.0;
    }
    if (turnTheBody)
        pose[r.channel("spine::ctrls.cog", "ry")] = 15.0;
    return pose;
}

std::map<std::string, Mat3> rotationsOf(const PosedRig& r, const std::string& limb)
{
    std::map<std::string, Mat3> out;
    for (const auto& node : r.rig.nodes)
        if (startsWith(node.path, limb + "::skin."))
            out[node.path] = rotationAt(r, node.path);
    return out;
}

TEST(LimbTwist, AdvancedTwistAtItsDefaultsMovesNoJointAtRestOrPosed)
{
    PosedRig plain(test::bipedLimbsWith({{"advanced_twist", Value(false)}})), advanced(test::bipedLimbsWith({{"advanced_twist", Value(true)}}));
    ASSERT_TRUE(plain.ok() && advanced.ok());
    for (const std::string limb : kLimbs)
        for (const char* attribute : {"twist_start", "twist_mid", "twist_end", "twist_bias"})
            EXPECT_EQ(advanced.defaults()[advanced.channel(limb + "::ctrls.switch", attribute)], 0.0) << limb << " " << attribute;
    EXPECT_EQ(plain.rig.nodes.size(), advanced.rig.nodes.size()) << "attributes and drives only";
    for (const bool posed : {false, true}) {
        plain.evaluate(posed ? bentPose(plain) : plain.defaults());
        advanced.evaluate(posed ? bentPose(advanced) : advanced.defaults());
        int compared = 0;
        for (model::RigNodeIndex i = 0; i < plain.rig.nodes.size(); ++i) {
            const auto twin = advanced.rig.findPath(plain.rig.nodes[i].path);
            ASSERT_TRUE(twin.has_value()) << plain.rig.nodes[i].path;
            EXPECT_LT(maxAbsDifference(advanced.state().worldMatrix(*twin), plain.state().worldMatrix(i)), 1e-12)
                << plain.rig.nodes[i].path << (posed ? " posed" : " at rest");
            ++compared;
        }
        EXPECT_GT(compared, 300);
    }
}

TEST(LimbTwist, TheEndMidAndStartRollsSpreadLinearlyOverTheTwistJoints)
{
    PosedRig r(test::bipedLimbsWith({{"advanced_twist", Value(true)}, {"twist_upper", Value(3LL)}}));
    ASSERT_TRUE(r.ok());
    const Pose base = bentPose(r);
    for (const std::string limb : kLimbs) {
        r.evaluate(base);
        const auto before = rotationsOf(r, limb);
        // Each roll alone, then all three at once: the rolls add up.
        struct Case {
            double start, mid, end;
        };
        for (const Case c : {Case{0.0, 0.0, 40.0}, Case{0.0, 30.0, 0.0}, Case{-25.0, 0.0, 0.0}, Case{-25.0, 30.0, 40.0}}) {
            Pose pose = base;
            pose[r.channel(limb + "::ctrls.switch", "twist_start")] = c.start;
            pose[r.channel(limb + "::ctrls.switch", "twist_mid")] = c.mid;
            pose[r.channel(limb + "::ctrls.switch", "twist_end")] = c.end;
            r.evaluate(pose);
            // About each joint's own bone axis (X): on the mirrored side the
            // same value rolls the mirror way, as that axis is mirrored too.
            const std::string how = " (" + std::to_string(c.start) + ", " + std::to_string(c.mid) + ", " + std::to_string(c.end) + ")";
            for (int t = 0; t < 3; ++t) { // the upper twist joints at 1/4, 2/4, 3/4
                const std::string id = limb + "::skin.up." + std::to_string(t);
                const double f = (t + 1) / 4.0;
                EXPECT_NEAR(rollDegrees(r, id, before.at(id)), (1.0 - f) * c.start + f * c.mid, 1e-6) << id << how;
            }
            for (int t = 0; t < 2; ++t) { // the lower ones at 1/3, 2/3: 0..40 degrees for a 40 degree twist_end
                const std::string id = limb + "::skin.dn." + std::to_string(t);
                const double f = (t + 1) / 3.0;
                EXPECT_NEAR(rollDegrees(r, id, before.at(id)), (1.0 - f) * c.mid + f * c.end, 1e-6) << id << how;
            }
            const std::string upper = limb + "::skin.limb.0", lower = limb + "::skin.limb.1", end = limb + "::skin.limb.2";
            EXPECT_NEAR(rollDegrees(r, upper, before.at(upper)), c.start, 1e-6) << upper << how;
            EXPECT_NEAR(rollDegrees(r, lower, before.at(lower)), c.mid, 1e-6) << lower << how;
            // The hand or foot and everything off the skin chain stay put.
            EXPECT_LT(maxAbsDifference(Mat4(rotationAt(r, end)), Mat4(before.at(end))), 1e-12) << end << how;
            std::vector<Vec3> off;
            for (const char* id : {"::blend.0", "::blend.1", "::blend.2", "::skin.mid.0", "::skin.mid.1"})
                off.push_back(r.position(limb + id));
            r.evaluate(base);
            int k = 0;
            for (const char* id : {"::blend.0", "::blend.1", "::blend.2", "::skin.mid.0", "::skin.mid.1"}) {
                EXPECT_LT(glm::length(off[std::size_t(k)] - r.position(limb + id)), 1e-12) << limb << id << how;
                ++k;
            }
        }
    }
}


// How far `joint` turned since `rest` relative to its segment's start joint
// `start` (which carries the rest of the pose), in degrees.
double turnFrom(const PosedRig& r, const std::string& start, const std::string& joint, const std::map<std::string, Mat3>& rest)
{
    const Mat3 now = glm::transpose(rotationAt(r, start)) * rotationAt(r, joint);
    const Mat3 then = glm::transpose(rest.at(start)) * rest.at(joint);
    Quat q = glm::quat_cast(now * glm::transpose(then));
    if (q.w < 0.0)
        q = -q;
    return glm::degrees(2.0 * std::atan2(glm::length(Vec3(q.x, q.y, q.z)), q.w));
}

TEST(LimbTwist, TwistBiasLeavesMoreOfTheTwistToTheEndOrMovesItTowardsTheStart)
{
    PosedRig r(test::bipedLimbsWith({{"advanced_twist", Value(true)}}));
    ASSERT_TRUE(r.ok());
    for (const std::string limb : kLimbs) {
        const Vec3 shoulder = r.restPosition(limb + "::blend.0"), elbow = r.restPosition(limb + "::blend.1");
        const Vec3 wrist = r.restPosition(limb + "::blend.2");
        const Vec3 upper = glm::normalize(elbow - shoulder), lower = glm::normalize(wrist - elbow);
        Pose fk = r.defaults();
        fk[r.channel(limb + "::ctrls.switch", "ik_blend")] = 0.0;
        r.evaluate(fk);
        const auto rest = rotationsOf(r, limb);
        // The end turned 60 degrees about the forearm or shin, the upper bone
        // rolled 60 degrees about itself (non-rolling: the upper twist joints
        // share the roll from none at the start to all of it at the elbow).
        Pose twisted = test::turned(r, fk, limb + "::ctrls.fk.2", lower, 60.0);
        twisted = test::turned(r, twisted, limb + "::ctrls.fk.0", upper, 60.0);
        for (const double bias : {0.0, 1.0, -1.0, 0.5}) {
            twisted[r.channel(limb + "::ctrls.switch", "twist_bias")] = bias;
            r.evaluate(twisted);
            for (int t = 0; t < 2; ++t) {
                const double f = (t + 1) / 3.0, share = std::pow(f, std::exp2(bias));
                for (const auto& [segment, start] : {std::pair{"dn", "skin.limb.1"}, std::pair{"up", "skin.limb.0"}}) {
                    const std::string id = limb + "::skin." + segment + "." + std::to_string(t);
                    EXPECT_NEAR(turnFrom(r, limb + "::" + start, id, rest), 60.0 * share, 1e-6) << id << " bias " << bias;
                }
            }
        }
        if (limb == "arm.L") { // bias 1: a third of the way down the forearm takes a ninth of the twist, not a third
            EXPECT_NEAR(std::pow(1.0 / 3.0, std::exp2(1.0)), 1.0 / 9.0, 1e-12);
            EXPECT_NEAR(std::pow(1.0 / 3.0, std::exp2(-1.0)), std::sqrt(1.0 / 3.0), 1e-12);
        }
    }
}

TEST(LimbTwist, TheRightSideRollsAsTheMirrorOfTheLeft)
{
    PosedRig r(test::bipedLimbsWith({{"advanced_twist", Value(true)}, {"add_chains", Value(std::string("[sleeve]"))}}));
    ASSERT_TRUE(r.ok());
    Pose pose = bentPose(r, false); // the body still, so both sides can mirror
    std::vector<model::RigNodeIndex> left;
    for (const char* limb : {"arm.L", "leg.L"}) {
        const std::string settings = std::string(limb) + "::ctrls.switch";
        left.push_back(r.index(settings));
        pose[r.channel(settings, "twist_start")] = 17.0;
        pose[r.channel(settings, "twist_mid")] = -23.0;
        pose[r.channel(settings, "twist_end")] = 41.0;
        pose[r.channel(settings, "twist_bias")] = 0.6;
        const std::string tweak = std::string(limb) + "::ctrls.dn.sleeve.1";
        left.push_back(r.index(tweak));
        pose[r.channel(tweak, "ty")] = 0.02;
        pose[r.channel(tweak, "rx")] = 12.0;
        pose[r.channel(tweak, "sy")] = 1.3;
        for (const char* id : {"::ctrls.ik", "::ctrls.fk.0", "::ctrls.fk.1"})
            left.push_back(r.index(std::string(limb) + id));
    }
    const auto& state = r.evaluate(r.posing->mirror(pose, left));
    int pairs = 0;
    for (model::RigNodeIndex i = 0; i < r.rig.nodes.size(); ++i) {
        const auto& node = r.rig.nodes[i];
        if (node.twin == model::kNoNode || !(startsWith(node.path, "arm.L::skin.") || startsWith(node.path, "leg.L::skin.")))
            continue;
        ++pairs;
        EXPECT_LT(maxAbsDifference(state.worldMatrix(node.twin), reflected(state.worldMatrix(i))), 1e-6) << node.path;
    }
    EXPECT_EQ(pairs, 28); // per side: 14 arm and 14 leg skin joints
    // And the pose did something: the left forearm's twist joints rolled.
    PosedRig plain(test::bipedLimbsWith({{"advanced_twist", Value(true)}, {"add_chains", Value(std::string("[sleeve]"))}}));
    plain.evaluate(bentPose(plain, false));
    EXPECT_GT(maxAbsDifference(state.worldMatrix(r.index("arm.R::skin.dn.1")), plain.state().worldMatrix(plain.index("arm.R::skin.dn.1"))),
              0.1);
}

TEST(LimbTwist, TheQuadrupedsHindLegRollsAtTheHockAndCarriesItsChains)
{
    model::GuideDocument guide = test::loadSample("quadruped");
    for (const auto& i : guide.instances())
        if (i.templateId == "quad.leg") {
            guide.instance(i.id)->options["advanced_twist"] = Value(true);
            guide.instance(i.id)->options["add_chains"] = Value(std::string("[haunch]"));
        }
    PosedRig r(guide);
    ASSERT_TRUE(r.ok());
    EXPECT_FALSE(hasErrors(r.rig.diagnostics)) << formatAll(r.rig.diagnostics);
    // The sample spreads the hock's roll over twist_lower joints (3: a long gaskin), each its even share.
    const model::TemplateInstance* hind = guide.instanceNamed("hind_leg");
    ASSERT_TRUE(hind->options.count("twist_lower"));
    const long long count = std::get<long long>(hind->options.at("twist_lower"));
    ASSERT_GE(count, 2);
    for (const std::string leg : {"hind_leg.L", "hind_leg.R"}) {
        const Pose base = r.defaults();
        r.evaluate(base);
        const auto before = rotationsOf(r, leg);
        Pose pose = base;
        pose[r.channel(leg + "::ctrls.switch", "twist_end")] = 40.0; // at the hock, the lower twisting segment's end
        r.evaluate(pose);
        for (int t = 0; t < count; ++t) {
            const std::string id = leg + "::skin.dn." + std::to_string(t), chain = leg + "::skin.dn.haunch." + std::to_string(t);
            EXPECT_NEAR(rollDegrees(r, id, before.at(id)), 40.0 * double(t + 1) / double(count + 1), 1e-6) << id;
            EXPECT_LT(maxAbsDifference(r.state().worldMatrix(r.index(chain)), r.state().worldMatrix(r.index(id))), 1e-9) << chain;
        }
        const std::string cannon = leg + "::skin.limb.2";
        EXPECT_LT(maxAbsDifference(Mat4(rotationAt(r, cannon)), Mat4(before.at(cannon))), 1e-12) << "the cannon does not roll";
    }
}

TEST(LimbTwist, AdvancedTwistRebuildsIncrementallyAsAFullBuild)
{
    model::GuideDocument guide = test::bipedLimbsWith({{"advanced_twist", Value(false)}});
    rigging::BuildCache cache;
    test::buildAndCompare(guide, cache, "first build");
    for (const auto& i : guide.instances())
        if (i.name == "arm")
            guide.instance(i.id)->options["advanced_twist"] = Value(true);
    test::buildAndCompare(guide, cache, "advanced_twist on the arms");
    for (const auto& i : guide.instances())
        if (i.name == "leg")
            guide.instance(i.id)->options["advanced_twist"] = Value(true);
    test::buildAndCompare(guide, cache, "and the legs");
    for (const auto& i : guide.instances())
        if (i.name == "arm")
            guide.instance(i.id)->options["advanced_twist"] = Value(false);
    test::buildAndCompare(guide, cache, "off on the arms");
}

} // namespace
} // namespace rs
