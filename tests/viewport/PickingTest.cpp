#include "Picking.h"

#include "build/RigBuilder.h"
#include "core/TestSupport.h"

#include <gtest/gtest.h>

using namespace rs;
using namespace rs::viewport;

namespace {

struct Fixture {
    model::GuideDocument guide = test::loadSample("biped");
    model::Rig rig = build::buildRig(guide, test::builtinTemplates());
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
    const auto node = *f.rig.find("world::ctrls.world");
    const auto& curve = f.rig.nodes[node].curves[0];
    const glm::dvec3 onCurve = glm::dvec3(f.rig.nodes[node].worldMatrix * glm::dvec4(curve.points[5], 1.0));
    const PickResult hit = pick(f.scene, f.camera, 800, 600, f.pixelOf(onCurve));
    ASSERT_EQ(hit.kind, PickResult::Kind::Controller);
    EXPECT_EQ(f.rig.nodes[hit.node].id, "world::ctrls.world");
}

TEST(Picking, MissesEmptySpace)
{
    Fixture f;
    EXPECT_EQ(pick(f.scene, f.camera, 800, 600, {5, 5}).kind, PickResult::Kind::Nothing);
}
