// The W/E/R gizmo's maths without a GL context: handle picking and exact drags.
#include "Manipulator.h"
#include "Picking.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace rs::viewport;

namespace {

constexpr double kWidth = 800.0, kHeight = 600.0;

struct GizmoFixture {
    Camera camera;
    Gizmo gizmo;
    GizmoFixture(GizmoMode mode, const glm::dmat4& target = glm::translate(glm::dmat4(1.0), glm::dvec3(0.2, 1.0, 0.0)))
    {
        camera.target = glm::dvec3(target[3]);
        camera.distance = 3.0;
        gizmo.mode = mode;
        gizmo.target = target;
        gizmo.size = Gizmo::sizeFor(camera, gizmo.origin(), kHeight);
    }
    glm::dvec2 pixelOf(const glm::dvec3& world) const
    {
        glm::dvec2 p;
        projectToPixels(camera.projectionMatrix(kWidth / kHeight) * camera.viewMatrix(), world, kWidth, kHeight, p);
        return p;
    }
    Ray rayAt(const glm::dvec3& world) const { return rayThroughPixel(camera, kWidth, kHeight, pixelOf(world)); }
};

} // namespace

TEST(Manipulator, PicksTheHandleUnderTheCursorAndNothingElsewhere)
{
    GizmoFixture f(GizmoMode::Translate);
    for (int k = 0; k < 3; ++k)
        EXPECT_EQ(pickGizmoHandle(f.gizmo, f.camera, kWidth, kHeight, f.pixelOf(f.gizmo.origin() + f.gizmo.axis(k) * f.gizmo.size * 0.7)), k);
    EXPECT_EQ(pickGizmoHandle(f.gizmo, f.camera, kWidth, kHeight, glm::dvec2(5.0, 5.0)), -1);
    EXPECT_NEAR(glm::length(f.pixelOf(f.gizmo.origin() + glm::dvec3(0, f.gizmo.size, 0)) - f.pixelOf(f.gizmo.origin())), 90.0, 5.0);
}

TEST(Manipulator, TranslateDragMovesAlongTheHandleAxisOnly)
{
    const glm::dmat4 turned = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0.2, 1.0, 0.0)), 0.6, glm::dvec3(0, 1, 0));
    for (bool world : {false, true}) {
        GizmoFixture f(GizmoMode::Translate, turned);
        f.gizmo.worldSpace = world;
        const glm::dvec3 axis = f.gizmo.axis(0);
        GizmoDrag drag(f.gizmo, 0, f.rayAt(f.gizmo.origin() + axis * 0.1));
        const glm::dmat4 moved = drag.worldFor(f.rayAt(f.gizmo.origin() + axis * 0.35));
        const glm::dvec3 delta = glm::dvec3(moved[3]) - f.gizmo.origin();
        EXPECT_NEAR(glm::dot(delta, axis), 0.25, 1e-6) << world;
        EXPECT_LT(glm::length(delta - axis * glm::dot(delta, axis)), 1e-9) << world;
        EXPECT_LT(glm::length(glm::dvec3(moved[0]) - glm::dvec3(turned[0])), 1e-12); // orientation untouched
    }
    GizmoFixture f(GizmoMode::Translate, turned);
    EXPECT_GT(glm::length(f.gizmo.axis(0) - glm::dvec3(1, 0, 0)), 0.1); // local: the control's turned X
}

TEST(Manipulator, RotateDragTurnsAboutTheHandleAxisThroughTheOrigin)
{
    GizmoFixture f(GizmoMode::Rotate);
    f.camera.yaw = 0.0;
    f.camera.pitch = 0.0; // looking down -Z: the Z ring faces the camera
    const glm::dvec3 o = f.gizmo.origin();
    GizmoDrag drag(f.gizmo, 2, f.rayAt(o + glm::dvec3(f.gizmo.size, 0, 0)));
    const glm::dmat4 turned = drag.worldFor(f.rayAt(o + glm::dvec3(0, f.gizmo.size, 0)));
    EXPECT_LT(glm::length(glm::dvec3(turned[0]) - glm::dvec3(0, 1, 0)), 1e-6); // X turned onto Y: +90 degrees about Z
    EXPECT_LT(glm::length(glm::dvec3(turned[3]) - o), 1e-9);
}

TEST(Manipulator, ScaleDragScalesAlongTheControlsOwnAxis)
{
    GizmoFixture f(GizmoMode::Scale);
    f.gizmo.worldSpace = true; // scaling always follows the control's axes
    const glm::dvec3 o = f.gizmo.origin();
    GizmoDrag drag(f.gizmo, 1, f.rayAt(o + glm::dvec3(0, 0.1, 0)));
    const glm::dmat4 scaled = drag.worldFor(f.rayAt(o + glm::dvec3(0, 0.2, 0)));
    EXPECT_NEAR(glm::length(glm::dvec3(scaled[1])), 2.0, 1e-3);
    EXPECT_NEAR(glm::length(glm::dvec3(scaled[0])), 1.0, 1e-12);
}
