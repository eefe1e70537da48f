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

// Frame All on a standing figure (a column, outstretched arms, a ground ring
// reaching towards the camera) fills 90% of the view, not the smaller share
// its bounding box's corners would leave.
TEST(Camera, FramesPointsToFillNinetyPercentOfTheView)
{
    std::vector<glm::dvec3> points;
    for (int i = 0; i <= 18; ++i)
        points.emplace_back(0.0, 0.1 * i, 0.0);
    for (int i = -8; i <= 8; ++i)
        points.emplace_back(0.1 * i, 1.4, 0.0);
    for (int i = 0; i < 32; ++i)
        points.emplace_back(0.5 * std::cos(i * 0.19635), 0.0, 0.5 * std::sin(i * 0.19635));
    const int width = 798, height = 694;
    for (const bool ortho : {false, true}) {
        Camera camera;
        camera.orthographic = ortho;
        camera.frame(points, double(width) / height);
        const glm::dmat4 vp = camera.projectionMatrix(double(width) / height) * camera.viewMatrix();
        glm::dvec2 lo(1e9), hi(-1e9);
        for (const glm::dvec3& p : points) {
            glm::dvec2 pixel;
            ASSERT_TRUE(projectToPixels(vp, p, width, height, pixel));
            lo = glm::min(lo, pixel);
            hi = glm::max(hi, pixel);
        }
        EXPECT_GE(lo.x, 0.0);
        EXPECT_GE(lo.y, 0.0);
        EXPECT_LE(hi.x, width);
        EXPECT_LE(hi.y, height);
        const double fill = std::max((hi.x - lo.x) / width, (hi.y - lo.y) / height);
        EXPECT_GT(fill, 0.85) << (ortho ? "orthographic" : "perspective");
        EXPECT_LT(fill, 0.92) << (ortho ? "orthographic" : "perspective");
    }
}
