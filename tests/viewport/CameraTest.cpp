#include "Camera.h"

#include <gtest/gtest.h>

using namespace rs::viewport;

TEST(Camera, ProjectsTheTargetToTheViewCentre)
{
    Camera camera;
    camera.target = {0.3, 1.2, -0.5};
    const glm::dmat4 vp = camera.projectionMatrix(1.5) * camera.viewMatrix();
    glm::dvec2 pixel;
    ASSERT_TRUE(projectToPixels(vp, camera.target, 900, 600, pixel));
    EXPECT_NEAR(pixel.x, 450.0, 1e-9);
    EXPECT_NEAR(pixel.y, 300.0, 1e-9);
}

TEST(Camera, OrbitKeepsTheDistanceToTheTarget)
{
    Camera camera;
    camera.orbit(120, -40);
    EXPECT_NEAR(glm::length(camera.position() - camera.target), camera.distance, 1e-9);
}

TEST(Camera, PanMovesThePointUnderTheCursorWithIt)
{
    Camera camera;
    const glm::dvec3 point = camera.target;
    camera.pan(50, 0, 600);
    glm::dvec2 pixel;
    ASSERT_TRUE(projectToPixels(camera.projectionMatrix(1.0) * camera.viewMatrix(), point, 600, 600, pixel));
    EXPECT_NEAR(pixel.x, 300.0 + 50.0, 1e-6);
}

TEST(Camera, FramesABoxInsideTheView)
{
    Camera camera;
    camera.frame({-0.5, 0.0, -0.2}, {0.5, 1.8, 0.2});
    const glm::dmat4 vp = camera.projectionMatrix(1.0) * camera.viewMatrix();
    for (double x : {-0.5, 0.5})
        for (double y : {0.0, 1.8}) {
            glm::dvec2 pixel;
            ASSERT_TRUE(projectToPixels(vp, {x, y, 0.2}, 500, 500, pixel));
            EXPECT_GT(pixel.x, 0);
            EXPECT_LT(pixel.x, 500);
            EXPECT_GT(pixel.y, 0);
            EXPECT_LT(pixel.y, 500);
        }
}
