#include "Picking.h"

#include "rigging/RigBuilder.h"
#include "core/TestSupport.h"

#include <gtest/gtest.h>

using namespace rs;
using namespace rs::viewport;

namespace {

struct Fixture {
    model::GuideDocument guide = test::loadSample("biped");
    model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    Scene scene = makeScene(guide, &rig, {});
    Camera camera;
    Fixture()
    {
        glm::dvec3 lo, hi;
        scene.bounds(lo, hi);
        camera.frame(lo, hi);
    }
    glm::dvec2 pixelOf(const glm::dvec3& world) const
    {
        glm::dvec2 p;
        projectToPixels(camera.projectionMatrix(800.0 / 600.0) * camera.viewMatrix(), world, 800, 600, p);
        return p;
    }
};

} // namespace

TEST(Picking, PicksTheGuideJointUnderTheCursor)
{
    Fixture f;
    const auto* arm = f.guide.instanceNamed("arm");
    const model::JointId elbow = arm->joints[2].id;
    const glm::dvec2 at = f.pixelOf(translationOf(f.guide.jointWorldMatrix(elbow))) + glm::dvec2(3, -2);
    const PickResult hit = pick(f.scene, f.camera, 800, 600, at);
    ASSERT_EQ(hit.kind, PickResult::Kind::GuideJoint);
    EXPECT_EQ(hit.joint, elbow);
    EXPECT_EQ(hit.owner, arm->id);
}

TEST(Picking, PicksAControllerCurveAwayFromJoints)
{
    Fixture f;
    f.scene.showGuides = false;
    const auto node = *f.rig.findPath("world::ctrls.world");
    const auto& curve = f.rig.nodes[node].curves[0];
    const glm::dvec3 onCurve = glm::dvec3(f.rig.nodes[node].worldMatrix * glm::dvec4(curve.points[5], 1.0));
    const PickResult hit = pick(f.scene, f.camera, 800, 600, f.pixelOf(onCurve));
    ASSERT_EQ(hit.kind, PickResult::Kind::Controller);
    EXPECT_EQ(f.rig.nodes[hit.node].path, "world::ctrls.world");
}

TEST(Picking, MissesEmptySpace)
{
    Fixture f;
    EXPECT_EQ(pick(f.scene, f.camera, 800, 600, {5, 5}).kind, PickResult::Kind::Nothing);
}

TEST(Picking, CvModeShowsTheSelectedControllersCvsAndPicksThemFirst)
{
    Fixture f;
    const auto node = *f.rig.findPath("arm.L::ctrls.ik");
    SceneSelection selection;
    selection.node = node;
    selection.nodes = {node};
    selection.cvs = {{node, 0, 0}};
    EXPECT_TRUE(makeScene(f.guide, &f.rig, selection).cvs.empty()) << "CVs only in CV mode";
    selection.cvMode = true;
    f.scene = makeScene(f.guide, &f.rig, selection);
    const auto& curves = f.rig.nodes[node].curves;
    std::size_t count = 0;
    for (const auto& c : curves) count += c.cvs.size();
    ASSERT_EQ(f.scene.cvs.size(), count) << "every CV of the selected controller, no other";
    EXPECT_EQ(f.scene.hulls.size(), curves.size());
    EXPECT_TRUE(f.scene.cvs[0].selected);
    EXPECT_FALSE(f.scene.cvs[1].selected);

    // A click near a CV picks it; the CVs sharing its place come with it.
    const SceneCv& third = f.scene.cvs[2];
    const PickResult hit = pick(f.scene, f.camera, 800, 600, f.pixelOf(third.position) + glm::dvec2(2, 1));
    ASSERT_EQ(hit.kind, PickResult::Kind::Cv);
    EXPECT_LT(glm::length(f.scene.cvs[hit.cv.cv].position - third.position), 1e-9);
    const auto together = coincidentCvs(f.scene, hit.cv);
    for (const auto& cv : f.scene.cvs) {
        const bool samePlace = glm::length(cv.position - third.position) < 1e-6;
        EXPECT_EQ(std::find(together.begin(), together.end(), cv.cv) != together.end(), samePlace) << cv.cv.cv;
    }
    // A box around the whole control holds every CV; a box elsewhere none.
    glm::dvec2 lo(1e300), hi(-1e300);
    for (const auto& cv : f.scene.cvs) { lo = glm::min(lo, f.pixelOf(cv.position)); hi = glm::max(hi, f.pixelOf(cv.position)); }
    EXPECT_EQ(boxPickCvs(f.scene, f.camera, 800, 600, lo - 2.0, hi + 2.0).size(), count);
    EXPECT_TRUE(boxPickCvs(f.scene, f.camera, 800, 600, {0, 0}, {4, 4}).empty());
}

TEST(Scene, DrawsTheMirroredGuidesItIsGivenWithTheGuidesOnly)
{
    Fixture f;
    EXPECT_TRUE(f.scene.mirrorJoints.empty()) << "none given, none drawn";
    const std::vector<session::MirroredGuideJoint> mirrored =
        session::mirroredGuideJoints(f.guide, test::builtinTemplates());
    ASSERT_FALSE(mirrored.empty());
    const Scene guides = makeScene(f.guide, &f.rig, {}, nullptr, mirrored);
    ASSERT_EQ(guides.mirrorJoints.size(), mirrored.size());
    EXPECT_EQ(guides.mirrorJoints[0].position, mirrored[0].position);
    EXPECT_EQ(guides.mirrorJoints[0].owner, mirrored[0].owner);
    const eval::EvalState pose; // Rig mode hides the guides, mirrored ones too
    EXPECT_TRUE(makeScene(f.guide, &f.rig, {}, &pose, mirrored).mirrorJoints.empty());
}
