// rig.slide on a curve (issue 22 item 7), as a rigger checks it on the built
// and evaluated rig: at slide 0 the skin joints sit on their guides; slid,
// every joint lies on the curve and keeps its spacing along the arc; the slide
// stops at its limits; moving a spline controller or a tweaker bends the path;
// stretch keeps each joint's share of the curve; the right branch mirrors the
// left; isolate_skin changes nothing of the skin's motion; an incremental rebuild after each edit is the full build. The curve is the one model::SplineConstraint documents (a cubic
// Hermite through its targets, tangents along their rest chain direction
// turned with them, scaled by the chord), evaluated here on its own and
// sampled finely. The rail case (two guide joints) is the vehicle's door
// (VehicleTest).
#include "core/IncrementalCheck.h"
#include "EvalTestSupport.h"
#include "io/RigDump.h"
#include "rigging/BuildCache.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rs {
namespace {

using eval::Pose;
using test::PosedRig;

constexpr int kSliders = 4; // the test guide's option
constexpr int kGuides = 8;

model::GuideDocument curveGuide(bool tweakers = false)
{
    model::GuideDocument guide = test::loadGuide("Slide/curve/guide.yml");
    if (tweakers)
        guide.instance(guide.instanceNamed("track")->id)->options["tweakers"] = true;
    return guide;
}

std::string skin(const std::string& side, int i) { return "track." + side + "::skin." + std::to_string(i); }

// The curve of a spline constraint, evaluated from its targets' world
// transforms (and their rest ones, for the tangents), sampled densely.
class Curve {
public:
    Curve(const PosedRig& r, const std::vector<eval::Affine>& rest, const std::string& constraint)
    {
        const model::RigConstraint* c = nullptr;
        for (const auto& k : r.rig.constraints)
            if (k.path == constraint)
                c = &k;
        if (!c) {
            ADD_FAILURE() << "no constraint " << constraint;
            return;
        }
        const std::vector<eval::Affine>& world = r.state().world;
        const std::size_t n = c->targets.size();
        std::vector<Vec3> p(n), m(n);
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3 before = rest[c->targets[i > 0 ? i - 1 : i]].translation;
            const Vec3 after = rest[c->targets[i + 1 < n ? i + 1 : i]].translation;
            const Vec3 local = glm::transpose(rest[c->targets[i]].rotation()) * glm::normalize(after - before);
            p[i] = world[c->targets[i]].translation;
            m[i] = world[c->targets[i]].rotation() * local;
        }
        constexpr int kPerSegment = 4000;
        for (std::size_t i = 0; i + 1 < n; ++i) {
            const double chord = glm::length(p[i + 1] - p[i]);
            for (int k = (i == 0 ? 0 : 1); k <= kPerSegment; ++k) {
                const double s = double(k) / kPerSegment, s2 = s * s, s3 = s2 * s;
                m_points.push_back((2 * s3 - 3 * s2 + 1) * p[i] + (s3 - 2 * s2 + s) * chord * m[i] + (-2 * s3 + 3 * s2) * p[i + 1] +
                                   (s3 - s2) * chord * m[i + 1]);
                m_arc.push_back(m_points.size() == 1 ? 0.0 : m_arc.back() + glm::length(m_points.back() - m_points[m_points.size() - 2]));
            }
        }
    }

    struct Closest {
        double distance = std::numeric_limits<double>::infinity();
        double arc = 0.0; // length along the curve from its start
    };
    Closest closest(const Vec3& q) const
    {
        Closest best;
        for (std::size_t i = 0; i + 1 < m_points.size(); ++i) {
            const Vec3 d = m_points[i + 1] - m_points[i];
            const double t = std::clamp(glm::dot(q - m_points[i], d) / glm::dot(d, d), 0.0, 1.0);
            const double distance = glm::length(m_points[i] + t * d - q);
            if (distance < best.distance)
                best = {distance, m_arc[i] + t * glm::length(d)};
        }
        return best;
    }
    double length() const { return m_arc.back(); }

private:
    std::vector<Vec3> m_points;
    std::vector<double> m_arc;
};

// Each sliding joint's arc position on the left curve, every one checked to lie on it.
std::vector<double> arcsOnCurve(const PosedRig& r, const std::vector<eval::Affine>& rest, const std::string& what)
{
    const Curve curve(r, rest, "track.L::cns.spline");
    std::vector<double> arcs;
    for (int i = 0; i < kSliders; ++i) {
        const Curve::Closest c = curve.closest(r.position(skin("L", i)));
        EXPECT_LT(c.distance, 1e-6) << what << ": joint " << i << " off the curve";
        arcs.push_back(c.arc);
    }
    return arcs;
}

double guideLengthAhead(const model::GuideDocument& guide)
{
    const auto& joints = guide.instanceNamed("track")->joints;
    double length = 0.0;
    for (int i = kSliders; i < kGuides; ++i)
        length += glm::length(translationOf(guide.jointWorldMatrix(joints[i].id)) -
                              translationOf(guide.jointWorldMatrix(joints[i - 1].id)));
    return length;
}

TEST(SlideRig, AtSlideZeroTheJointsSitOnTheirGuidesOnBothSides)
{
    const model::GuideDocument guide = curveGuide();
    PosedRig r(guide);
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.rig.diagnostics.empty()) << formatAll(r.rig.diagnostics);
    EXPECT_FALSE(r.rig.findPath(skin("L", kSliders))) << "the guides past the sliders only lay the path";
    r.evaluate(r.defaults());
    const auto& joints = guide.instanceNamed("track")->joints;
    for (int i = 0; i < kSliders; ++i) {
        const Vec3 at = translationOf(guide.jointWorldMatrix(joints[std::size_t(i)].id));
        EXPECT_LT(glm::length(r.position(skin("L", i)) - at), 1e-6) << i;
        EXPECT_LT(glm::length(r.position(skin("R", i)) - Vec3(-at.x, at.y, at.z)), 1e-6) << i;
    }
}

TEST(SlideRig, SlidJointsLieOnTheCurveAndKeepTheirSpacingAlongTheArc)
{
    PosedRig r(curveGuide());
    ASSERT_TRUE(r.ok());
    const int slide = r.channel("track.L::ctrls.spline.0", "slide");
    const auto rest = r.evaluate(r.defaults()).world;
    const std::vector<double> before = arcsOnCurve(r, rest, "at rest");
    EXPECT_NEAR(before.front(), 0.0, 1e-6);
    for (double s : {0.1, 0.37, r.program->channels().clamp(slide, 100.0)}) {
        Pose pose = r.defaults();
        pose[slide] = s;
        r.evaluate(pose);
        const std::vector<double> after = arcsOnCurve(r, rest, "slide " + std::to_string(s));
        for (int i = 0; i < kSliders; ++i)
            EXPECT_NEAR(after[std::size_t(i)] - before[std::size_t(i)], s, 1e-4) << "slide " << s << ": joint " << i;
        for (int i = 1; i < kSliders; ++i)
            EXPECT_NEAR(after[std::size_t(i)] - after[std::size_t(i) - 1], before[std::size_t(i)] - before[std::size_t(i) - 1], 1e-4)
                << "slide " << s << ": spacing " << i;
    }
}

TEST(SlideRig, TheSlideStopsAtItsLimits)
{
    const model::GuideDocument guide = curveGuide();
    PosedRig r(guide);
    ASSERT_TRUE(r.ok());
    const int slide = r.channel("track.L::ctrls.spline.0", "slide");
    const auto& layout = r.program->channels();
    EXPECT_TRUE(layout[std::size_t(slide)].limited);
    EXPECT_NEAR(layout.clamp(slide, 100.0), guideLengthAhead(guide), 1e-9) << "as far as the guides go past the last slider";
    EXPECT_DOUBLE_EQ(layout.clamp(slide, -1.0), 0.0) << "no further back than its rest";
    // At the forward limit the last slider is still on the curve, short of its end.
    const auto rest = r.evaluate(r.defaults()).world;
    Pose pose = r.defaults();
    pose[slide] = layout.clamp(slide, 100.0);
    r.evaluate(pose);
    const Curve curve(r, rest, "track.L::cns.spline");
    const Curve::Closest last = curve.closest(r.position(skin("L", kSliders - 1)));
    EXPECT_LT(last.distance, 1e-6);
    EXPECT_LE(last.arc, curve.length() + 1e-9);
    EXPECT_GT(last.arc, curve.length() - 0.01) << "a chord shorter than its arc by a few millimetres at most";
}

TEST(SlideRig, MovingASplineControllerBendsThePathTheJointsSlideOn)
{
    PosedRig r(curveGuide());
    ASSERT_TRUE(r.ok());
    const int slide = r.channel("track.L::ctrls.spline.0", "slide");
    const auto rest = r.evaluate(r.defaults()).world;
    const std::vector<double> spacing = arcsOnCurve(r, rest, "at rest");
    Pose pose = r.defaults();
    pose[slide] = 0.3;
    r.evaluate(pose);
    std::vector<Vec3> straight;
    for (int i = 0; i < kSliders; ++i)
        straight.push_back(r.position(skin("L", i)));

    pose[r.channel("track.L::ctrls.spline.1", "tx")] = 0.2;
    pose[r.channel("track.L::ctrls.spline.1", "ty")] = 0.15;
    pose[r.channel("track.L::ctrls.spline.2", "rx")] = 25.0;
    r.evaluate(pose);
    EXPECT_GT(glm::length(r.position("track.L::mch.curve.4") - rest[r.index("track.L::mch.curve.4")].translation), 0.1)
        << "the path moved with its controller";
    const std::vector<double> bent = arcsOnCurve(r, rest, "bent");
    double moved = 0.0;
    for (int i = 0; i < kSliders; ++i) {
        moved = std::max(moved, glm::length(r.position(skin("L", i)) - straight[std::size_t(i)]));
        EXPECT_NEAR(bent[std::size_t(i)], spacing[std::size_t(i)] + 0.3, 1e-4) << "joint " << i << " slid 0.3 m along the bent path";
    }
    EXPECT_GT(moved, 0.05) << "the joints follow the bent path";
}

TEST(SlideRig, ATweakerShapesThePathAtItsGuide)
{
    PosedRig r(curveGuide(true));
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.rig.diagnostics.empty()) << formatAll(r.rig.diagnostics);
    const auto rest = r.evaluate(r.defaults()).world;
    Pose pose = r.defaults();
    pose[r.channel("track.L::ctrls.tweak.2", "ty")] = 0.1;
    r.evaluate(pose);
    const Curve curve(r, rest, "track.L::cns.spline");
    EXPECT_LT(curve.closest(r.position("track.L::ctrls.tweak.2")).distance, 1e-9) << "the curve passes through the tweaker";
    EXPECT_GT(glm::length(r.position(skin("L", 2)) - rest[r.index(skin("L", 2))].translation), 0.05) << "the joint there follows";
    arcsOnCurve(r, rest, "tweaked");
}

TEST(SlideRig, WithStretchEachJointKeepsItsShareOfTheCurve)
{
    PosedRig r(curveGuide());
    ASSERT_TRUE(r.ok());
    const auto rest = r.evaluate(r.defaults()).world;
    const Curve restCurve(r, rest, "track.L::cns.spline");
    const std::vector<double> before = arcsOnCurve(r, rest, "at rest");
    Pose pose = r.defaults();
    pose[r.channel("track.L::ctrls.spline.0", "stretch")] = 1.0;
    pose[r.channel("track.L::ctrls.spline.1", "tx")] = 0.3; // the path's middle control pulled on (X along the path)
    r.evaluate(pose);
    const Curve curve(r, rest, "track.L::cns.spline");
    const std::vector<double> after = arcsOnCurve(r, rest, "stretched");
    EXPECT_GT(curve.length(), restCurve.length() + 0.1);
    EXPECT_GT(after.back() - after.front(), before.back() - before.front() + 0.02) << "the chain stretches";
    // Each joint keeps its curve parameter: at its guide's point of the curve.
    for (int i = 0; i < kSliders; ++i)
        EXPECT_LT(glm::length(r.position(skin("L", i)) - r.position("track.L::mch.curve." + std::to_string(i))), 1e-6) << i;
}

TEST(SlideRig, AnFkControlTurnsItsJointWhereTheCurveCarriesIt)
{
    PosedRig r(curveGuide());
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    pose[r.channel("track.L::ctrls.spline.0", "slide")] = 0.2;
    r.evaluate(pose);
    const Vec3 at = r.position(skin("L", 1));
    const Mat3 turned = r.state().world[r.index(skin("L", 1))].rotation();
    pose[r.channel("track.L::ctrls.fk.1", "rz")] = 30.0;
    r.evaluate(pose);
    EXPECT_LT(glm::length(r.position(skin("L", 1)) - at), 1e-9) << "the FK control turns the joint in place";
    const Vec3 x = r.state().world[r.index(skin("L", 1))].rotation()[0];
    EXPECT_NEAR(glm::degrees(std::acos(std::clamp(glm::dot(x, turned[0]), -1.0, 1.0))), 30.0, 1e-6);
    EXPECT_LT(glm::length(r.position(skin("L", 2)) - r.position("track.L::drv.2")), 1e-9) << "the next joint stays on the curve";
}

TEST(SlideRig, AnIncrementalRebuildAfterEachEditIsTheFullBuild)
{
    model::GuideDocument guide = curveGuide();
    const model::InstanceId track = guide.instanceNamed("track")->id;
    rigging::BuildCache cache;
    auto compare = [&](const std::string& what) {
        test::buildAndCompare(guide, cache, what);
        const model::Rig full = rigging::buildRig(guide, test::builtinTemplates());
        EXPECT_TRUE(full.diagnostics.empty()) << what << ": " << formatAll(full.diagnostics);
    };
    compare("first build");
    guide.instance(track)->options["sliders"] = 2;
    compare("two sliders");
    guide.instance(track)->options["tweakers"] = true;
    compare("tweakers");
    guide.instance(track)->options["fk"] = false;
    compare("no fk");
    guide.instance(track)->joints[3].local.translate.y += 0.05;
    compare("a guide joint moved");
    guide.instance(track)->options["controls"] = 4;
    compare("four controllers");
}

TEST(SlideRig, WithIsolateSkinTheSkinJointsSlideAsWithout)
{
    model::GuideDocument isolated = curveGuide();
    isolated.instance(isolated.instanceNamed("track")->id)->options["isolate_skin"] = Value(true);
    PosedRig plain(curveGuide()), r(isolated);
    ASSERT_TRUE(plain.ok() && r.ok());
    EXPECT_TRUE(r.rig.diagnostics.empty()) << formatAll(r.rig.diagnostics);
    EXPECT_NE(r.rig.nodes[r.rig.nodes[r.index(skin("L", 1))].parent].path, "track.L::ctrls.fk.1") << "the skin hangs from skin";
    for (PosedRig* rig : {&plain, &r}) {
        Pose pose = rig->defaults();
        pose[rig->channel("track.L::ctrls.spline.0", "slide")] = 0.3;
        pose[rig->channel("track.L::ctrls.spline.1", "ty")] = 0.1;
        pose[rig->channel("track.L::ctrls.fk.2", "rz")] = 20.0;
        rig->evaluate(pose);
    }
    for (int i = 0; i < kSliders; ++i)
        EXPECT_LT(maxAbsDifference(r.state().world[r.index(skin("L", i))].matrix(), plain.state().world[plain.index(skin("L", i))].matrix()),
                  1e-9)
            << i;
}

TEST(SlideRig, TheRightBranchMirrorsTheLeft)
{
    PosedRig r(curveGuide());
    ASSERT_TRUE(r.ok());
    Pose pose = r.defaults();
    pose[r.channel("track.L::ctrls.spline.0", "slide")] = 0.45;
    pose[r.channel("track.R::ctrls.spline.0", "slide")] = 0.45;
    r.evaluate(pose);
    for (int i = 0; i < kSliders; ++i) {
        const Vec3 left = r.position(skin("L", i)), right = r.position(skin("R", i));
        EXPECT_LT(glm::length(right - Vec3(-left.x, left.y, left.z)), 1e-9) << i;
        EXPECT_GT(glm::length(left - r.restPosition(skin("L", i))), 0.3) << i;
    }
}

} // namespace
} // namespace rs
