// The strider sample (resources/samples/strider.yml) as an animator checks it:
// a mechanical walker, a hull on two pairs of four-segment legs (quad.leg,
// L/R) that stand on their toe tips with the legs bent. The legs are rigid
// (stretch off: pulled past reach a leg straightens and stops), have no foot to
// roll (reverse_lock off: the IK control carries the leg's end, no roll or bank
// attributes), no blend joints at the bends, no twist joints and no twist
// flesh (non_rolling off: the thigh's skin joint turns with the thigh). Where a
// test shows what an option changes, it builds the strider with that option at
// its default beside it (test::sampleWith).
#include "EvalTestSupport.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

constexpr const char* kLegInstances[] = {"front_leg", "hind_leg"};
const std::string kLegs[] = {"front_leg.L", "front_leg.R", "hind_leg.L", "hind_leg.R"};

std::size_t countPrefixed(const model::Rig& rig, const std::string& prefix)
{
    std::size_t n = 0;
    for (const auto& node : rig.nodes)
        n += node.path.rfind(prefix, 0) == 0 ? 1 : 0;
    return n;
}

// The lengths of a leg's four segments (hip to stifle, stifle to hock, hock to
// fetlock, fetlock to ball) in the last evaluation.
std::vector<double> segmentLengths(const PosedRig& r, const std::string& leg)
{
    const std::string ids[] = {leg + "::blend.0", leg + "::blend.1", leg + "::blend.2", leg + "::blend.3", leg + "::blend.ball"};
    std::vector<double> lengths;
    for (std::size_t i = 0; i + 1 < std::size(ids); ++i)
        lengths.push_back(glm::length(r.position(ids[i + 1]) - r.position(ids[i])));
    return lengths;
}

// How far `id` turned about the unit `axis` since rest, in degrees.
double turnAbout(const PosedRig& r, const std::string& id, const Vec3& axis)
{
    const Mat3 rest = r.rig.nodes[r.index(id)].worldMatrix;
    Quat q = glm::quat_cast(r.state().world[r.index(id)].rotation() * glm::transpose(rest));
    if (q.w < 0.0)
        q = -q;
    return glm::degrees(2.0 * std::atan2(glm::dot(Vec3(q.x, q.y, q.z), axis), q.w));
}

TEST(Strider, SampleBuildsWithoutDiagnostics)
{
    PosedRig r("strider");
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.rig.diagnostics.empty()) << formatAll(r.rig.diagnostics);
}

// At rest the toe tips touch the ground and the legs are bent, short of full
// reach: the default pose is the rest pose (nothing pops), and raising the hull
// 3 cm still leaves every leg's end on its planted IK control.
TEST(Strider, TheToeTipsStandOnTheGroundWithTheLegsBentShortOfReach)
{
    const model::GuideDocument guide = test::loadSample("strider");
    for (const char* name : kLegInstances) {
        const model::TemplateInstance* leg = guide.instanceNamed(name);
        ASSERT_TRUE(leg) << name;
        ASSERT_EQ(leg->joints.size(), 10u) << name << ": pelvis, four segments, ball, toe, heel and bank guides";
        const Vec3 toe(guide.jointWorldMatrix(leg->joints[6].id)[3]);
        EXPECT_NEAR(toe.y, 0.0, 1e-9) << name << ": the toe tip is on the ground";
    }
    PosedRig r("strider");
    ASSERT_TRUE(r.ok());
    const Pose rest = r.defaults();
    r.evaluate(rest);
    for (const std::string& leg : kLegs) {
        for (const char* joint : {"blend.0", "blend.1", "blend.2", "blend.3", "blend.ball"})
            EXPECT_LT(glm::length(r.position(leg + "::" + joint) - r.restPosition(leg + "::" + joint)), 1e-9) << leg << ' ' << joint;
        // The IK keeps the hock's angle: full reach is the thigh plus the stifle-to-fetlock distance.
        const Vec3 hip = r.restPosition(leg + "::blend.0"), stifle = r.restPosition(leg + "::blend.1");
        const Vec3 fetlock = r.restPosition(leg + "::blend.3");
        const double reach = glm::length(stifle - hip) + glm::length(fetlock - stifle);
        EXPECT_LT(glm::length(fetlock - hip), reach - 0.03) << leg << ": bent at rest";
    }
    Pose raised = rest;
    raised[r.channel("hull::ctrls.xform", "ty")] += 0.03;
    r.evaluate(raised);
    for (const std::string& leg : kLegs) {
        EXPECT_LT(glm::length(r.position(leg + "::blend.3") - r.restPosition(leg + "::blend.3")), 1e-6) << leg << " stays planted";
        EXPECT_NEAR(r.position(leg + "::blend.0").y - r.restPosition(leg + "::blend.0").y, 0.03, 1e-9) << leg;
    }
}

// Rigid segments (stretch off: the IK control's stretch attribute is 0 by
// default): the IK control pulled 0.5 m below the ground straightens the leg,
// which stops at full reach, every segment its rest length. The same pull on
// the strider with stretch on lengthens them.
TEST(Strider, ALegPulledPastReachKeepsEachSegmentItsRestLength)
{
    PosedRig r("strider"), stretchy(test::sampleWith("strider", {"front_leg", "hind_leg"}, "stretch", Value(true)));
    ASSERT_TRUE(r.ok());
    ASSERT_TRUE(stretchy.ok());
    for (const std::string& leg : kLegs) {
        EXPECT_EQ(r.defaults()[r.channel(leg + "::ctrls.ik", "stretch")], 0.0) << leg << ": the stretch attribute is off";
        EXPECT_EQ(stretchy.defaults()[stretchy.channel(leg + "::ctrls.ik", "stretch")], 1.0) << leg;
    }
    for (PosedRig* rig : {&r, &stretchy}) {
        const bool rigid = rig == &r;
        rig->evaluate(rig->defaults());
        std::map<std::string, std::vector<double>> rest;
        for (const std::string& leg : kLegs)
            rest[leg] = segmentLengths(*rig, leg);
        Pose pose = rig->defaults();
        for (const std::string& leg : kLegs)
            pose[rig->channel(leg + "::ctrls.ik", "ty")] -= 0.5;
        rig->evaluate(pose);
        for (const std::string& leg : kLegs) {
            const std::vector<double> pulled = segmentLengths(*rig, leg);
            const double ikGap = glm::length(rig->position(leg + "::blend.3") - rig->position(leg + "::ctrls.ik"));
            if (rigid) {
                for (std::size_t i = 0; i < pulled.size(); ++i)
                    EXPECT_NEAR(pulled[i], rest[leg][i], 1e-6) << leg << " segment " << i;
                EXPECT_GT(ikGap, 0.3) << leg << ": the leg stops short of the pulled control";
            } else {
                EXPECT_GT(pulled[0], rest[leg][0] + 0.05) << leg << ": with stretch the thigh lengthens";
                EXPECT_LT(ikGap, 1e-6) << leg << ": with stretch the leg reaches the control";
            }
        }
    }
}

// No foot to roll (reverse_lock off): no reverse-foot pivots and no roll, bank
// or toe attributes on the IK control, which carries the leg's end: moved and
// turned within reach, the fetlock follows it exactly and the toe turns with
// it. With reverse_lock on the same control carries the foot's roll attributes.
TEST(Strider, TheLegEndsOnItsIkControlWithNoFootToRoll)
{
    PosedRig r("strider"), footed(test::sampleWith("strider", {"front_leg", "hind_leg"}, "reverse_lock", Value(true)));
    ASSERT_TRUE(r.ok());
    ASSERT_TRUE(footed.ok());
    for (const std::string& leg : kLegs) {
        EXPECT_FALSE(r.rig.findPath(leg + "::rfoot.heel")) << leg;
        EXPECT_TRUE(footed.rig.findPath(leg + "::rfoot.heel")) << leg;
        for (const char* attribute : {"roll", "roll_break", "bank", "heel_twist", "toe_twist", "toe_tap"}) {
            EXPECT_FALSE(r.program->channels().find(r.index(leg + "::ctrls.ik"), attribute).has_value()) << leg << ' ' << attribute;
            EXPECT_TRUE(footed.program->channels().find(footed.index(leg + "::ctrls.ik"), attribute).has_value()) << leg << ' ' << attribute;
        }
    }
    const Vec3 step(0.06, 0.12, 0.1); // a step forward, lifted, outward for L
    Pose pose = r.defaults();
    for (const std::string& leg : kLegs) {
        const bool left = leg.back() == 'L';
        pose = r.moveTo(pose, leg + "::ctrls.ik", r.restPosition(leg + "::blend.3") + Vec3(left ? step.x : -step.x, step.y, step.z),
                        leg + "::blend.3");
    }
    pose = test::turned(r, pose, "front_leg.L::ctrls.ik", Vec3(0, 1, 0), 25.0);
    r.evaluate(pose);
    for (const std::string& leg : kLegs) {
        const bool left = leg.back() == 'L';
        const Vec3 moved = r.position(leg + "::blend.3") - r.restPosition(leg + "::blend.3");
        EXPECT_LT(glm::length(moved - Vec3(left ? step.x : -step.x, step.y, step.z)), 1e-6) << leg << ": the fetlock is on the control";
    }
    EXPECT_NEAR(turnAbout(r, "front_leg.L::blend.ball", Vec3(0, 1, 0)), 25.0, 1e-6) << "the toe turns with the control";
    EXPECT_NEAR(turnAbout(r, "front_leg.R::blend.ball", Vec3(0, 1, 0)), 0.0, 1e-6) << "the other toe keeps its heading";
}

// Rigid segments skin on one joint each: no blend joints at the bends
// (blend_joints off), no twist joints (twist_upper, twist_lower 0); with
// blend_joints on the same legs get them.
TEST(Strider, TheSkinHasOneJointPerSegmentAndNoBlendOrTwistJoints)
{
    PosedRig r("strider"), blended(test::sampleWith("strider", {"front_leg", "hind_leg"}, "blend_joints", Value(true)));
    ASSERT_TRUE(r.ok());
    ASSERT_TRUE(blended.ok());
    for (const std::string& leg : kLegs) {
        EXPECT_EQ(countPrefixed(r.rig, leg + "::skin.mid."), 0u) << leg << ": no blend joints";
        EXPECT_GT(countPrefixed(blended.rig, leg + "::skin.mid."), 0u) << leg << ": blend_joints on makes them";
        EXPECT_EQ(countPrefixed(r.rig, leg + "::skin.up."), 0u) << leg << ": no thigh twist joints";
        EXPECT_EQ(countPrefixed(r.rig, leg + "::skin.dn."), 0u) << leg << ": no shin twist joints";
        EXPECT_EQ(countPrefixed(r.rig, leg + "::skin."), 5u) << leg << ": four segments and the toe";
    }
}

// No twist flesh (non_rolling off): rolling the FK thigh about its bone turns
// its skin joint fully with it, as a rigid part does; the non-rolling default
// would hold the thigh's skin joint back.
TEST(Strider, TheThighSkinJointRollsWithTheThigh)
{
    PosedRig r("strider"), flesh(test::sampleWith("strider", {"front_leg", "hind_leg"}, "non_rolling", Value(true)));
    ASSERT_TRUE(r.ok());
    ASSERT_TRUE(flesh.ok());
    for (PosedRig* rig : {&r, &flesh}) {
        const Vec3 thigh = glm::normalize(rig->restPosition("hind_leg.L::blend.1") - rig->restPosition("hind_leg.L::blend.0"));
        Pose fk = rig->defaults();
        fk[rig->channel("hind_leg.L::ctrls.switch", "ik_blend")] = 0.0;
        rig->evaluate(test::turned(*rig, fk, "hind_leg.L::ctrls.fk.0", thigh, 40.0));
        EXPECT_NEAR(turnAbout(*rig, "hind_leg.L::blend.0", thigh), 40.0, 1e-6);
        if (rig == &r)
            EXPECT_NEAR(turnAbout(*rig, "hind_leg.L::skin.limb.0", thigh), 40.0, 1e-6) << "rolls with the thigh";
        else
            EXPECT_NEAR(turnAbout(*rig, "hind_leg.L::skin.limb.0", thigh), 0.0, 1e-6) << "non_rolling holds it back";
    }
}

} // namespace
} // namespace rs
