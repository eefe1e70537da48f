// Limbs as an animator checks them on the built and evaluated rigs (issue 22,
// step 2): IK/FK snapping both ways from random poses on every biped and
// quadruped limb, soft IK that does not pop, stretch that reaches and keeps
// the volume, the reverse foot's pivots staying planted, the auto-clavicle,
// the elbow/knee pin and the quadruped front leg in the chest space.
#include "EvalTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// Every skin and blend joint of a limb: what the animator sees move.
std::vector<model::RigNodeIndex> limbJoints(const PosedRig& r, const std::string& limb)
{
    std::vector<model::RigNodeIndex> out;
    for (model::RigNodeIndex i = 0; i < r.rig.nodes.size(); ++i)
        if (startsWith(r.rig.nodes[i].path, limb + "::skin.") || startsWith(r.rig.nodes[i].path, limb + "::blend."))
            out.push_back(i);
    return out;
}

std::vector<Vec3> positionsOf(const PosedRig& r, const std::vector<model::RigNodeIndex>& nodes)
{
    std::vector<Vec3> out;
    for (auto n : nodes) out.push_back(r.state().world[n].translation);
    return out;
}

// Adds a uniform random amount in [-range, range] to a channel, when the node has it.
void jitter(const PosedRig& r, Pose& pose, const std::string& node, const std::string& name, double range, std::mt19937& rng)
{
    const auto index = r.rig.findPath(node);
    if (!index)
        return;
    const auto channel = r.program->channels().find(*index, name);
    if (!channel)
        return;
    pose[*channel] = r.program->channels().clamp(*channel, pose[*channel] + std::uniform_real_distribution<double>(-range, range)(rng));
}

// Moves what the limb hangs from: the body and the clavicle or pelvis.
void jitterParents(const PosedRig& r, Pose& pose, const std::string& limb, std::mt19937& rng)
{
    for (const char* c : {"tx", "ty", "tz"}) jitter(r, pose, "spine::ctrls.cog", c, 0.05, rng);
    for (const char* c : {"rx", "ry", "rz"}) jitter(r, pose, "spine::ctrls.cog", c, 15.0, rng);
    if (r.rig.findPath(limb + "::ctrls.clavicle"))
        jitter(r, pose, limb + "::ctrls.clavicle", "rz", 15.0, rng);
}

void expectStill(const PosedRig& r, const std::vector<model::RigNodeIndex>& joints, const std::vector<Vec3>& before,
                 const std::string& what)
{
    const auto after = positionsOf(r, joints);
    for (std::size_t i = 0; i < joints.size(); ++i)
        EXPECT_LT(glm::length(after[i] - before[i]), 1e-5) << what << ": " << r.rig.nodes[joints[i]].path;
}

TEST(LimbRig, IkFkSnapsBothWaysKeepEveryLimbJointWithinTenMicrometresFromRandomPoses)
{
    const std::pair<const char*, std::vector<std::string>> samples[] = {
        {"biped", {"arm.L", "arm.R", "leg.L", "leg.R"}},
        {"quadruped", {"front_leg.L", "front_leg.R", "hind_leg.L", "hind_leg.R"}}};
    std::mt19937 rng(22);
    for (const auto& [sample, limbs] : samples) {
        PosedRig r(sample);
        ASSERT_TRUE(r.ok());
        for (const std::string& limb : limbs) {
            const auto joints = limbJoints(r, limb);
            ASSERT_GT(joints.size(), 8u) << limb;
            const bool quad = r.rig.findPath(limb + "::ctrls.fk.3").has_value();
            const std::string ik = limb + "::ctrls.ik";
            for (int trial = 0; trial < 4; ++trial) {
                // IK -> FK: an IK pose with the foot rolled, stretch or soft IK, and the pin partly on.
                Pose pose = r.defaults();
                jitterParents(r, pose, limb, rng);
                pose[r.channel(limb + "::ctrls.switch", "ik_blend")] = 1.0;
                for (const char* c : {"tx", "ty", "tz"}) jitter(r, pose, ik, c, 0.08, rng);
                for (const char* c : {"rx", "ry", "rz"}) jitter(r, pose, ik, c, 30.0, rng);
                for (const char* c : {"tx", "ty", "tz"}) jitter(r, pose, limb + "::ctrls.pole", c, 0.1, rng);
                for (const char* c : {"tx", "ty", "tz"}) jitter(r, pose, limb + "::ctrls.pin", c, 0.03, rng);
                jitter(r, pose, ik, "roll", 40.0, rng);
                jitter(r, pose, ik, "bank", 20.0, rng);
                jitter(r, pose, ik, "toe_tap", 20.0, rng);
                jitter(r, pose, ik, "soft_ik", 0.04, rng);
                jitter(r, pose, ik, "pin", 1.0, rng);
                pose[r.channel(ik, "stretch")] = trial % 2;
                r.evaluate(pose);
                auto before = positionsOf(r, joints);
                auto fk = r.posing->ikToFk(pose, r.index(limb + "::ctrls.switch"));
                ASSERT_TRUE(fk) << formatAll(fk.diagnostics());
                EXPECT_EQ((*fk)[r.channel(limb + "::ctrls.switch", "ik_blend")], 0.0);
                r.evaluate(*fk);
                expectStill(r, joints, before, limb + " IK to FK, trial " + std::to_string(trial));

                // FK -> IK: an FK pose (a hind leg's hock keeps its angle to the
                // cannon, the one thing its IK does not drive), IK settings random.
                pose = r.defaults();
                jitterParents(r, pose, limb, rng);
                pose[r.channel(limb + "::ctrls.switch", "ik_blend")] = 0.0;
                for (const char* c : {"rx", "ry", "rz"}) jitter(r, pose, limb + "::ctrls.fk.0", c, 30.0, rng);
                for (const char* c : quad ? std::vector<const char*>{"rz"} : std::vector<const char*>{"rx", "ry", "rz"})
                    jitter(r, pose, limb + "::ctrls.fk.1", c, 30.0, rng);
                for (const char* c : {"rx", "ry", "rz"}) jitter(r, pose, limb + (quad ? "::ctrls.fk.3" : "::ctrls.fk.2"), c, 30.0, rng);
                jitter(r, pose, limb + "::ctrls.fk.ball", "rz", 20.0, rng);
                jitter(r, pose, ik, "roll", 40.0, rng);
                jitter(r, pose, ik, "pin", 1.0, rng);
                // Soft IK with stretch lengthens the bones in the soft zone to
                // keep the end on the control, so an FK pose there has no IK
                // twin: soft IK is tried without stretch (and turned off with
                // it, whatever the limb's soft_ik default).
                pose[r.channel(ik, "stretch")] = trial % 2;
                if (trial % 2 == 0)
                    jitter(r, pose, ik, "soft_ik", 0.04, rng);
                else
                    pose[r.channel(ik, "soft_ik")] = 0.0;
                r.evaluate(pose);
                before = positionsOf(r, joints);
                auto back = r.posing->fkToIk(pose, r.index(limb + "::ctrls.fk.1"));
                ASSERT_TRUE(back) << formatAll(back.diagnostics());
                EXPECT_EQ((*back)[r.channel(limb + "::ctrls.switch", "ik_blend")], 1.0);
                r.evaluate(*back);
                expectStill(r, joints, before, limb + " FK to IK, trial " + std::to_string(trial));
            }
        }
    }
}

// The end and the elbow as the IK control is pulled along the arm's line in
// 1 mm steps from 90% to 110% of the reach: the largest elbow move per step.
double largestElbowStep(PosedRig& r, Pose pose, const std::string& limb)
{
    const Vec3 root = r.restPosition(limb + "::ik.0"), mid = r.restPosition(limb + "::ik.1"), end = r.restPosition(limb + "::ik.2");
    const double reach = glm::length(mid - root) + glm::length(end - mid);
    const Vec3 line = glm::normalize(end - root);
    double largest = 0.0;
    Vec3 lastElbow(0.0), lastEnd(0.0);
    for (int step = 0; step <= 200; ++step) {
        const double distance = reach * 0.9 + step * 0.001;
        r.evaluate(r.moveTo(pose, limb + "::ctrls.ik", root + line * distance, limb + "::ik.2"));
        const Vec3 elbow = r.position(limb + "::ik.1"), wrist = r.position(limb + "::ik.2");
        if (step > 0) {
            largest = std::max(largest, glm::length(elbow - lastElbow) / 0.001);
            EXPECT_LE(glm::length(wrist - lastEnd), 0.001 + 1e-9) << "the end never moves more than the control";
        }
        lastElbow = elbow;
        lastEnd = wrist;
    }
    return largest;
}

TEST(LimbRig, SoftIkMovesTheElbowSmoothlyThroughFullReachWhereHardIkPops)
{
    PosedRig r("biped");
    for (const std::string limb : {"arm.L", "leg.R"}) {
        Pose pose = r.defaults();
        pose[r.channel(limb + "::ctrls.switch", "ik_blend")] = 1.0;
        pose[r.channel(limb + "::ctrls.ik", "stretch")] = 0.0;
        const double hard = largestElbowStep(r, pose, limb);
        EXPECT_GT(hard, 6.0) << limb << ": hard IK pops the elbow (the test can tell)";
        pose[r.channel(limb + "::ctrls.ik", "soft_ik")] = 0.05;
        const double soft = largestElbowStep(r, pose, limb);
        EXPECT_LT(soft, 3.0) << limb << ": with a 5 cm soft zone the elbow moves at most 3 mm per mm of the control";
    }
}

TEST(LimbRig, TheClawsSoftIkKeepsItsBentRestPoseAndEasesTheElbowThroughFullReach)
{
    // The claw's forelimbs are guided with the elbow bent 23 mm short of full reach, so their 2 cm soft zone
    // (soft_ik 0.02, the IK control's default) leaves the rest pose where it is and still eases the reach.
    PosedRig r("claw");
    ASSERT_TRUE(r.ok());
    for (const std::string limb : {"arm.L", "arm.R"}) {
        Pose pose = r.defaults();
        EXPECT_EQ(pose[r.channel(limb + "::ctrls.ik", "soft_ik")], 0.02) << "the option sets the attribute's default";
        pose[r.channel(limb + "::ctrls.switch", "ik_blend")] = 1.0;
        r.evaluate(pose);
        for (const char* joint : {"::ik.1", "::ik.2"})
            EXPECT_LT(glm::length(r.position(limb + joint) - r.restPosition(limb + joint)), 1e-9) << limb << joint << " at rest";
        pose[r.channel(limb + "::ctrls.ik", "stretch")] = 0.0;
        const double soft = largestElbowStep(r, pose, limb);
        pose[r.channel(limb + "::ctrls.ik", "soft_ik")] = 0.0;
        const double hard = largestElbowStep(r, pose, limb);
        EXPECT_GT(hard, 6.0) << limb << ": hard IK pops the elbow (the test can tell)";
        EXPECT_LT(soft, 3.0) << limb << ": with its 2 cm soft zone the elbow moves at most 3 mm per mm of the control"
                             << " (10 without)";
    }
}

TEST(LimbRig, StretchReachesAGoalBeyondReachAndVolumeScalesAcrossByOneOverRootStretch)
{
    PosedRig r(test::sampleWith("biped", {"arm"}, "volume", true));
    for (const std::string limb : {"arm.L", "arm.R"}) {
        const std::string ik = limb + "::ctrls.ik";
        EXPECT_EQ(r.defaults()[r.channel(ik, "volume")], 1.0) << "the option sets the attribute's default";
        const Vec3 root = r.restPosition(limb + "::ik.0"), end = r.restPosition(limb + "::ik.2");
        const double upper = glm::length(r.restPosition(limb + "::ik.1") - root);
        for (const double soft : {0.0, 0.05}) {
            Pose pose = r.defaults();
            pose[r.channel(limb + "::ctrls.switch", "ik_blend")] = 1.0;
            pose[r.channel(ik, "soft_ik")] = soft;
            const Vec3 goal = root + (end - root) * 1.3; // 30% past the rest reach (nearly straight)
            pose = r.moveTo(pose, ik, goal, limb + "::ik.2");
            r.evaluate(pose);
            EXPECT_LT(glm::length(r.position(limb + "::ik.2") - goal), 1e-9) << limb << ": stretch reaches the goal";
            const double s = glm::length(r.position(limb + "::ik.1") - root) / upper;
            EXPECT_GT(s, 1.2);
            const Vec3 scale = r.state().world[r.index(limb + "::skin.limb.0")].scale();
            EXPECT_NEAR(scale.x, 1.0, 1e-9) << "along the bone";
            EXPECT_NEAR(scale.y, 1.0 / std::sqrt(s), 1e-9) << limb;
            EXPECT_NEAR(scale.z, 1.0 / std::sqrt(s), 1e-9) << limb;
            pose[r.channel(ik, "volume")] = 0.0;
            r.evaluate(pose);
            EXPECT_NEAR(r.state().world[r.index(limb + "::skin.limb.0")].scale().y, 1.0, 1e-9) << "volume off keeps the thickness";
            pose[r.channel(ik, "stretch")] = 0.0;
            r.evaluate(pose);
            EXPECT_GT(glm::length(r.position(limb + "::ik.2") - goal), 0.05) << "without stretch the arm stops short";
        }
    }
}

// A point carried rigidly by `joint` from its rest place: where the foot's
// own point (heel, ball, toe tip, edge) is now.
Vec3 carried(const PosedRig& r, const std::string& joint, const Vec3& restPoint)
{
    const model::RigNodeIndex n = r.index(joint);
    return (r.state().world[n] * eval::Affine::fromMatrix(r.rig.nodes[n].worldMatrix).inverse()).apply(restPoint);
}

TEST(LimbRig, FootRollAndBankKeepThePlantedPivotFixedInWorldSpace)
{
    const std::pair<const char*, std::vector<std::string>> samples[] = {
        {"biped", {"leg.L", "leg.R"}}, {"quadruped", {"front_leg.L", "hind_leg.R"}}};
    for (const auto& [sample, legs] : samples) {
        PosedRig r(sample);
        for (const std::string& leg : legs) {
            const bool quad = r.rig.findPath(leg + "::ik.3").has_value();
            const std::string ankle = leg + (quad ? "::blend.3" : "::blend.2"), ball = leg + "::blend.ball";
            Pose pose = r.defaults();
            pose[r.channel(leg + "::ctrls.switch", "ik_blend")] = 1.0;
            const std::string ik = leg + "::ctrls.ik";
            pose[r.channel(ik, "tz")] = 0.1; // a foot stepped forward and turned in
            pose[r.channel(ik, "ry")] = 25.0;
            r.evaluate(pose);
            auto pivot = [&](const char* name) { return r.position(leg + "::rfoot." + std::string(name)); };
            const Vec3 heel = pivot("heel"), toe = pivot("toe"), ballPivot = pivot("ball"), in = pivot("bank_int"),
                       out = pivot("bank_ext");
            // The foot's own points at the pivots, carried by the ankle and the ball joints.
            const Vec3 heelRest = r.restPosition(leg + "::rfoot.heel"), toeRest = r.restPosition(leg + "::rfoot.toe"),
                       inRest = r.restPosition(leg + "::rfoot.bank_int"), outRest = r.restPosition(leg + "::rfoot.bank_ext");
            const int roll = r.channel(ik, "roll"), bank = r.channel(ik, "bank");
            pose[roll] = -30.0; // back on the heel
            r.evaluate(pose);
            EXPECT_LT(glm::length(carried(r, ankle, heelRest) - heel), 1e-6) << leg << " heel";
            EXPECT_GT(carried(r, ball, toeRest).y, toe.y + 0.02) << leg << " the toes lift";
            pose[roll] = 20.0; // on the ball: the heel lifts
            r.evaluate(pose);
            EXPECT_LT(glm::length(r.position(ball) - ballPivot), 1e-6) << leg << " ball";
            EXPECT_GT(carried(r, ankle, heelRest).y, heel.y + 0.02) << leg << " the heel lifts";
            pose[roll] = 70.0; // past the break: on the toe tip
            r.evaluate(pose);
            EXPECT_LT(glm::length(carried(r, ball, toeRest) - toe), 1e-6) << leg << " toe";
            EXPECT_GT(r.position(ball).y, ballPivot.y + 0.01) << leg << " the ball lifts";
            pose[roll] = 0.0;
            for (const double b : {25.0, -25.0}) { // onto one edge, then the other: one edge stays planted
                pose[bank] = b;
                r.evaluate(pose);
                const double inside = glm::length(carried(r, ankle, inRest) - in), outside = glm::length(carried(r, ankle, outRest) - out);
                EXPECT_LT(std::min(inside, outside), 1e-6) << leg << " bank " << b;
                EXPECT_GT(std::max(inside, outside), 0.01) << leg << " bank " << b << " lifts the other edge";
            }
            pose[bank] = 0.0;
            pose[r.channel(ik, "toe_tap")] = 30.0; // toe IK: the toes lift about the ball, the ball stays
            r.evaluate(pose);
            EXPECT_LT(glm::length(r.position(ball) - ballPivot), 1e-6) << leg;
            EXPECT_GT(carried(r, ball, toeRest).y, toe.y + 0.02) << leg << " toe tap";
        }
    }
}

TEST(LimbRig, AutoClavicleFollowsTheIkArmsRaiseByItsShareOnlyInIk)
{
    PosedRig r(test::sampleWith("biped", {"arm"}, "auto_clavicle", 0.5));
    for (const std::string arm : {"arm.L", "arm.R"}) {
        const std::string clavicle = arm + "::ctrls.clavicle", ik = arm + "::ctrls.ik";
        EXPECT_EQ(r.defaults()[r.channel(clavicle, "auto_clavicle")], 0.5) << "the option sets the default";
        Pose pose = r.defaults();
        pose[r.channel(arm + "::ctrls.switch", "ik_blend")] = 1.0;
        pose[r.channel(ik, "ty")] = 0.4; // the hand raised 40 cm
        r.evaluate(pose);
        const Vec3 origin = r.restPosition(clavicle), handRest = r.restPosition(ik);
        const Vec3 restDir = glm::normalize(handRest - origin), nowDir = glm::normalize(r.position(ik) - origin);
        const Mat3 turn = r.state().world[r.index(clavicle)].rotation() *
                          glm::transpose(eval::Affine::fromMatrix(r.rig.nodes[r.index(clavicle)].worldMatrix).rotation());
        const double full = std::acos(std::clamp(glm::dot(restDir, nowDir), -1.0, 1.0));
        const double taken = std::acos(std::clamp(glm::dot(restDir, glm::normalize(turn * restDir)), -1.0, 1.0));
        EXPECT_GT(full, 0.3);
        EXPECT_NEAR(taken, 0.5 * full, 1e-6) << arm << ": half the turn towards the hand";
        EXPECT_GT(r.position(arm + "::blend.0").y, r.restPosition(arm + "::blend.0").y + 0.01) << arm << ": the shoulder lifts";
        EXPECT_LT(glm::length(r.position(arm + "::ik.2") - r.position(ik)), 1e-9) << "the hand still reaches the control";
        pose[r.channel(clavicle, "auto_clavicle")] = 0.0;
        r.evaluate(pose);
        EXPECT_LT(glm::length(r.position(arm + "::blend.0") - r.restPosition(arm + "::blend.0")), 1e-9) << "0: the clavicle stays";
        pose[r.channel(clavicle, "auto_clavicle")] = 1.0;
        pose[r.channel(arm + "::ctrls.switch", "ik_blend")] = 0.0;
        r.evaluate(pose);
        EXPECT_LT(glm::length(r.position(arm + "::blend.0") - r.restPosition(arm + "::blend.0")), 1e-9) << "FK: the IK arm moves nothing";
    }
    // Mirrored: raising both hands lifts both shoulders alike.
    Pose pose = r.defaults();
    for (const std::string arm : {"arm.L", "arm.R"}) {
        pose[r.channel(arm + "::ctrls.switch", "ik_blend")] = 1.0;
        pose[r.channel(arm + "::ctrls.ik", "ty")] = 0.3;
    }
    r.evaluate(pose);
    const Vec3 left = r.position("arm.L::blend.0"), right = r.position("arm.R::blend.0");
    EXPECT_NEAR(left.x, -right.x, 1e-9);
    EXPECT_NEAR(left.y, right.y, 1e-9);
    EXPECT_NEAR(left.z, right.z, 1e-9);
}

TEST(LimbRig, ThePinLocksTheElbowAndKneeOnThePinControl)
{
    PosedRig r("biped");
    for (const std::string limb : {"arm.L", "arm.R", "leg.L", "leg.R"}) {
        const std::string ik = limb + "::ctrls.ik", pin = limb + "::ctrls.pin";
        Pose pose = r.defaults();
        pose[r.channel(limb + "::ctrls.switch", "ik_blend")] = 1.0;
        pose = r.moveTo(pose, ik, r.restPosition(limb + "::ik.2") + Vec3(0.0, 0.15, 0.05), limb + "::ik.2");
        pose = r.moveTo(pose, pin, r.restPosition(limb + "::ik.1") + Vec3(0.05, 0.04, 0.03), pin);
        r.evaluate(pose);
        const Vec3 free = r.position(limb + "::blend.1"), pinAt = r.position(pin);
        EXPECT_GT(glm::length(free - pinAt), 0.01) << limb << ": pin 0 leaves the elbow free";
        pose[r.channel(ik, "pin")] = 1.0;
        r.evaluate(pose);
        EXPECT_LT(glm::length(r.position(limb + "::blend.1") - pinAt), 1e-9) << limb << ": pinned";
        EXPECT_LT(glm::length(r.position(limb + "::blend.2") - r.position(ik)), 1e-9) << limb << ": the end still on the control";
        pose[r.channel(ik, "pin")] = 0.5;
        r.evaluate(pose);
        EXPECT_LT(glm::length(r.position(limb + "::blend.1") - (free + pinAt) * 0.5), 1e-9) << limb << ": half way";
        // The pin is an IK control: hidden at full FK.
        pose[r.channel(limb + "::ctrls.switch", "ik_blend")] = 0.0;
        r.evaluate(pose);
        EXPECT_FALSE(r.state().isVisible(r.index(pin))) << limb;
    }
}

TEST(LimbRig, TheQuadrupedFrontLegHangsFromTheChestAndItsIkCanFollowIt)
{
    PosedRig r("quadruped");
    const std::string leg = "front_leg.L", ik = leg + "::ctrls.ik";
    const auto space = r.program->channels().find(r.index(ik), "space");
    ASSERT_TRUE(space);
    ASSERT_TRUE(r.program->channels()[*space].isEnum());
    const auto& labels = *r.program->channels()[*space].labels;
    const auto chest = std::find(labels.begin(), labels.end(), "chest");
    ASSERT_NE(chest, labels.end()) << "the front leg's IK space offers the chest";
    Pose pose = r.defaults();
    pose[r.channel(leg + "::ctrls.switch", "ik_blend")] = 1.0;
    pose[r.channel("spine::ctrls.ik_chest", "ty")] = 0.1; // the chest lifts
    r.evaluate(pose);
    const Vec3 shoulder = r.position(leg + "::blend.0");
    EXPECT_GT(shoulder.y, r.restPosition(leg + "::blend.0").y + 0.05) << "the leg hangs from the chest";
    EXPECT_LT(glm::length(r.position(ik) - r.restPosition(ik)), 1e-9) << "in world space the foot stays planted";
    pose[*space] = double(chest - labels.begin());
    r.evaluate(pose);
    EXPECT_GT(r.position(ik).y, r.restPosition(ik).y + 0.05) << "in chest space the foot goes with the chest";
}

} // namespace
} // namespace rs
