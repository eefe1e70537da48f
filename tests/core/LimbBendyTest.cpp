// Bendy limbs as an animator checks them (issue 22, item 2; option `bendy` of
// arm.limb, leg.limb and quad.leg): nothing moves at rest, a bend control
// bows its segment's twist joints along a smooth curve with the ends fixed,
// the elbow/knee tweak moves the middle of both segments and keeps the
// tangent at the elbow continuous, and smooth type `length` spaces the
// joints evenly. With the rest of the rig (twist, mirroring, IK/FK snap,
// pickwalk, stomp power, warnings, incremental builds): LimbBendyRigTest.cpp.
#include "EvalTestSupport.h"
#include "LimbBendySupport.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;
using namespace test::bendy;

Vec3 axisAt(const PosedRig& r, const std::string& id, int column) { return r.state().world[r.index(id)].rotation()[column]; }

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

} // namespace
} // namespace rs
