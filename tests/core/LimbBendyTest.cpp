// Bendy limbs as an animator checks them (issue 22, item 2; option `bendy` of
// arm.limb, leg.limb and quad.leg): nothing moves at rest, a bend control
// bows its segment's twist joints along a smooth curve with the ends fixed,
// the elbow/knee tweak moves the middle of both segments and keeps the
// tangent at the elbow continuous, the twist is still shared linearly, the
// right side is the exact mirror of the left, IK/FK snapping still holds,
// and the volume compensation's power (`stomp_power`).
#include "EvalTestSupport.h"
#include "IncrementalCheck.h"
#include "io/RigDump.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

const char* const kLimbs[] = {"arm.L", "arm.R", "leg.L", "leg.R"};

// The biped with `option` set on its arm and leg instances.
model::GuideDocument bipedWith(std::map<std::string, Value> options)
{
    model::GuideDocument guide = test::loadSample("biped");
    for (const auto& i : guide.instances())
        if (i.name == "arm" || i.name == "leg")
            for (const auto& [name, value] : options)
                guide.instance(i.id)->options[name] = value;
    return guide;
}

model::GuideDocument bendyBiped(std::map<std::string, Value> more = {})
{
    more["bendy"] = Value(true);
    return bipedWith(std::move(more));
}

Vec3 axisAt(const PosedRig& r, const std::string& id, int column) { return r.state().world[r.index(id)].rotation()[column]; }

// The bend-plane normal of a limb (Z of its joint frames): across both bones.
Vec3 bendNormal(const PosedRig& r, const std::string& limb)
{
    return glm::normalize(Vec3(r.rig.nodes[r.index(limb + "::blend.0")].worldMatrix[2]));
}

// +1 when a joint's X axis points down its bone at rest, -1 on a mirrored branch.
double aimSign(const PosedRig& r, const std::string& id, const Vec3& bone)
{
    return glm::dot(Vec3(r.rig.nodes[r.index(id)].worldMatrix[0]), bone) >= 0.0 ? 1.0 : -1.0;
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// Cubic Hermite basis on one curve piece (s in [0, 1]): position weights of
// the start and end points; the curve of model::TwistConstraint's bendy mode.
double startWeight(double s) { return 2 * s * s * s - 3 * s * s + 1; }
double endWeight(double s) { return -2 * s * s * s + 3 * s * s; }

TEST(LimbBendy, AtRestEveryJointStaysWhereItIsWithoutBendy)
{
    for (const char* sample : {"biped", "quadruped"}) {
        model::GuideDocument plainGuide = test::loadSample(sample), bendyGuide = plainGuide;
        int limbs = 0;
        for (const auto& i : bendyGuide.instances())
            if (i.templateId == "arm.limb" || i.templateId == "leg.limb" || i.templateId == "quad.leg") {
                bendyGuide.instance(i.id)->options["bendy"] = Value(true);
                plainGuide.instance(i.id)->options["bendy"] = Value(false);
                ++limbs;
            }
        ASSERT_GT(limbs, 1) << sample;
        PosedRig plain(plainGuide), bendy(bendyGuide);
        ASSERT_TRUE(plain.ok() && bendy.ok());
        EXPECT_GT(bendy.rig.nodes.size(), plain.rig.nodes.size()) << sample << ": bendy adds its controls";
        int compared = 0;
        for (model::RigNodeIndex i = 0; i < plain.rig.nodes.size(); ++i) {
            const std::string& path = plain.rig.nodes[i].path;
            const auto twin = bendy.rig.findPath(path);
            ASSERT_TRUE(twin.has_value()) << path;
            EXPECT_LT(maxAbsDifference(bendy.state().worldMatrix(*twin), plain.state().worldMatrix(i)), 1e-6) << path;
            ++compared;
        }
        EXPECT_GT(compared, 100) << sample;
    }
}

TEST(LimbBendy, MovingAMidBendControlBowsItsSegmentAlongASmoothCurveWithTheEndsFixed)
{
    PosedRig r(bendyBiped({{"smooth_type", Value(std::string("parametric"))}}));
    ASSERT_TRUE(r.ok());
    const double bow = 0.05;
    for (const std::string limb : kLimbs) {
        const char* segments[] = {"up", "dn"};
        for (int s = 0; s < 2; ++s) {
            const std::string control = limb + "::ctrls.bend." + segments[s];
            const Vec3 start = r.restPosition(limb + "::blend." + std::to_string(s));
            const Vec3 end = r.restPosition(limb + "::blend." + std::to_string(s + 1));
            const Vec3 normal = bendNormal(r, limb);
            ASSERT_NEAR(glm::length(r.restPosition(control) - glm::mix(start, end, 0.5)), 0.0, 1e-9) << control;
            r.evaluate(r.moveTo(r.defaults(), control, r.restPosition(control) + normal * bow, control));
            for (const std::string fixed : {"skin.limb.0", "skin.limb.1", "skin.limb.2", "blend.1"})
                EXPECT_LT(glm::length(r.position(limb + "::" + fixed) - r.restPosition(limb + "::" + fixed)), 1e-9)
                    << control << " leaves " << fixed;
            // Twist joints at 1/3 and 2/3: parameter 2/3 of the first piece
            // and 1/3 of the second, each bowed by 20/27 of the control's move.
            const double L = glm::length(end - start), half = L / 2.0, chord = std::sqrt(half * half + bow * bow);
            const Vec3 dir = glm::normalize(end - start);
            for (int t = 0; t < 2; ++t) {
                const std::string joint = limb + "::skin." + segments[s] + "." + std::to_string(t);
                const Vec3 moved = r.position(joint) - r.restPosition(joint);
                EXPECT_NEAR(glm::dot(moved, normal), bow * 20.0 / 27.0, 1e-9) << joint;
                EXPECT_NEAR(glm::length(moved - normal * glm::dot(moved, normal) - dir * glm::dot(moved, dir)), 0.0, 1e-9) << joint;
                // It aims along the curve: the Hermite derivative there (per
                // unit of the piece's parameter), up the bow before the
                // control and down it after.
                const double along = (4.0 / 3.0) * half - chord / 3.0;
                const Vec3 tangent = glm::normalize(dir * along + normal * (t == 0 ? 1.0 : -1.0) * (4.0 / 3.0) * bow);
                EXPECT_GT(glm::dot(axisAt(r, joint, 0) * aimSign(r, joint, dir), tangent), 1.0 - 1e-9) << joint;
            }
            EXPECT_NEAR(startWeight(2.0 / 3.0), 7.0 / 27.0, 1e-12);
            EXPECT_NEAR(endWeight(2.0 / 3.0), 20.0 / 27.0, 1e-12);
        }
    }
}

TEST(LimbBendy, SmoothTypeLengthSpacesTheJointsEvenlyAlongTheBentCurve)
{
    for (const char* smooth : {"length", "parametric"}) {
        PosedRig r(bendyBiped({{"smooth_type", Value(std::string(smooth))}, {"twist_upper", Value(5LL)}}));
        ASSERT_TRUE(r.ok());
        const std::string control = "arm.L::ctrls.bend.up";
        const Vec3 along = glm::normalize(r.restPosition("arm.L::blend.1") - r.restPosition("arm.L::blend.0"));
        r.evaluate(r.moveTo(r.defaults(), control, r.restPosition(control) + along * 0.03 + bendNormal(r, "arm.L") * 0.03, control));
        std::vector<Vec3> points = {r.position("arm.L::skin.limb.0")};
        for (int t = 0; t < 5; ++t) points.push_back(r.position("arm.L::skin.up." + std::to_string(t)));
        points.push_back(r.position("arm.L::blend.1"));
        double shortest = 1e9, longest = 0.0;
        for (std::size_t i = 1; i < points.size(); ++i) {
            shortest = std::min(shortest, glm::length(points[i] - points[i - 1]));
            longest = std::max(longest, glm::length(points[i] - points[i - 1]));
        }
        std::printf("%s: chords between twist joints from %.5f to %.5f m\n", smooth, shortest, longest);
        if (std::string(smooth) == "length")
            EXPECT_LT(longest / shortest, 1.01) << "evenly spread by arc length (chords: a little shorter where it bends)";
        else
            EXPECT_GT(longest / shortest, 1.3) << "parametric spacing bunches up where the control pulls the curve";
    }
}

TEST(LimbBendy, TheTweakMovesBothSegmentsMiddlesAndKeepsTheTangentContinuousAtTheElbow)
{
    PosedRig r(bendyBiped({{"smooth_type", Value(std::string("parametric"))}, {"twist_upper", Value(8LL)},
                           {"twist_lower", Value(8LL)}}));
    ASSERT_TRUE(r.ok());
    const double move = 0.05;
    for (const std::string limb : kLimbs) {
        const std::string tweak = limb + "::ctrls.tweak";
        const Vec3 normal = bendNormal(r, limb);
        ASSERT_LT(glm::length(r.restPosition(tweak) - r.restPosition(limb + "::blend.1")), 1e-9);
        r.evaluate(r.moveTo(r.defaults(), tweak, r.restPosition(tweak) + normal * move, tweak));
        for (const char* segment : {"up", "dn"}) {
            const std::string mid = limb + "::ctrls.bend." + segment;
            EXPECT_LT(glm::length(r.position(mid) - r.restPosition(mid) - normal * (move / 2.0)), 1e-9) << mid;
        }
        EXPECT_LT(glm::length(r.position(limb + "::skin.limb.0") - r.restPosition(limb + "::skin.limb.0")), 1e-9) << limb;
        EXPECT_LT(glm::length(r.position(limb + "::skin.limb.2") - r.restPosition(limb + "::skin.limb.2")), 1e-9) << limb;
        // The joints at 4/9 along each segment: the upper's at parameter 8/9
        // of its first piece (control halfway, 8/9 of it), the lower's at 8/9
        // of the first piece too (the tweak, then the control halfway).
        const double s = 8.0 / 9.0;
        const Vec3 upper = r.position(limb + "::skin.up.3") - r.restPosition(limb + "::skin.up.3");
        const Vec3 lower = r.position(limb + "::skin.dn.3") - r.restPosition(limb + "::skin.dn.3");
        EXPECT_NEAR(glm::dot(upper, normal), endWeight(s) * move / 2.0, 1e-9) << limb;
        EXPECT_NEAR(glm::dot(lower, normal), startWeight(s) * move + endWeight(s) * move / 2.0, 1e-9) << limb;
    }
    // Continuity: with the elbow bent 70 degrees further in FK, both tangents
    // at the elbow turn with the tweak (halfway between the bones), so the
    // curve passes it with the rest angle between them (the rest pose's small
    // kink), while the bones turn 70 degrees apart. The tangents at the elbow
    // are measured on the joints (parametric spacing) nearest to it.
    for (const std::string limb : kLimbs) {
        const Vec3 restUpper = glm::normalize(r.restPosition(limb + "::blend.1") - r.restPosition(limb + "::blend.0"));
        const Vec3 restLower = glm::normalize(r.restPosition(limb + "::blend.2") - r.restPosition(limb + "::blend.1"));
        const double restKink = glm::degrees(std::acos(std::clamp(glm::dot(restUpper, restLower), -1.0, 1.0)));
        Pose fk = r.defaults();
        fk[r.channel(limb + "::ctrls.switch", "ik_blend")] = 0.0;
        const std::string elbow = limb + "::ctrls.fk.1";
        double boneAngle = 0.0;
        Pose bent;
        for (const double sign : {1.0, -1.0}) { // the way the elbow bends further on this side
            Mat4 world = r.evaluate(fk).worldMatrix(r.index(elbow));
            const Vec3 at(world[3]);
            world = Mat4(glm::mat3_cast(glm::angleAxis(glm::radians(70.0 * sign), bendNormal(r, limb))) * Mat3(world));
            world[3] = Vec4(at, 1.0);
            const Pose pose = r.posing->placeAt(fk, r.index(elbow), world);
            r.evaluate(pose);
            const Vec3 upperBone = glm::normalize(r.position(limb + "::blend.1") - r.position(limb + "::blend.0"));
            const Vec3 lowerBone = glm::normalize(r.position(limb + "::blend.2") - r.position(limb + "::blend.1"));
            const double angle = glm::degrees(std::acos(std::clamp(glm::dot(upperBone, lowerBone), -1.0, 1.0)));
            if (angle > boneAngle) {
                boneAngle = angle;
                bent = pose;
            }
        }
        ASSERT_NEAR(boneAngle, restKink + 70.0, 1e-6) << limb;
        r.evaluate(bent);
        // Four twist joints on a cubic piece at equal parameter steps give the
        // cubic itself: its derivative at the elbow from Lagrange's basis.
        auto derivativeAt = [&](const char* segment, int first, std::array<double, 4> params, double at) {
            Vec3 d(0.0);
            for (int j = 0; j < 4; ++j) {
                double basis = 0.0;
                for (int k = 0; k < 4; ++k) {
                    if (k == j) continue;
                    double term = 1.0 / (params[j] - params[k]);
                    for (int m = 0; m < 4; ++m)
                        if (m != j && m != k) term *= (at - params[m]) / (params[j] - params[m]);
                    basis += term;
                }
                d += basis * r.position(limb + "::skin." + segment + "." + std::to_string(first + j));
            }
            return glm::normalize(d);
        };
        // up.4..up.7 sit at 5/9..8/9 of the upper curve: its second piece's
        // parameters 1/9..7/9, the elbow at 1; dn.0..dn.3 at 1/9..4/9 of the
        // lower: its first piece's 2/9..8/9, the elbow at 0.
        const Vec3 in = derivativeAt("up", 4, {1.0 / 9, 3.0 / 9, 5.0 / 9, 7.0 / 9}, 1.0);
        const Vec3 out = derivativeAt("dn", 0, {2.0 / 9, 4.0 / 9, 6.0 / 9, 8.0 / 9}, 0.0);
        const double kink = glm::degrees(std::acos(std::clamp(glm::dot(in, out), -1.0, 1.0)));
        EXPECT_NEAR(kink, restKink, 1e-4) << limb << ": the bones are " << boneAngle << " degrees apart";
    }
}

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
