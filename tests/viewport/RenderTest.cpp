// Renders the built biped through the GLFW host (OpenGL 3.3 core, Mesa under
// Xvfb) and checks the image: background, guide joints, controller colours.
#include "GlfwHost.h"

#include "rigging/RigBuilder.h"
#include "core/TestSupport.h"

#include <gtest/gtest.h>

using namespace rs;
using namespace rs::viewport;

namespace {

struct Rgb { int r, g, b; };

Rgb at(const std::vector<std::uint8_t>& image, int width, glm::dvec2 p)
{
    const std::size_t i = (std::size_t(p.y) * std::size_t(width) + std::size_t(p.x)) * 3;
    return {image[i], image[i + 1], image[i + 2]};
}

bool near(Rgb a, Rgb b, int tolerance) { return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance && std::abs(a.b - b.b) <= tolerance; }

} // namespace

TEST(Render, DrawsTheBuiltBipedInAGlfwWindow)
{
    std::string error;
    auto host = GlfwHost::create(640, 480, "render test", false, error);
    ASSERT_TRUE(host) << error << " (GL tests need a display: run them under xvfb-run)";
    const auto guide = test::loadSample("biped");
    const auto rig = rigging::buildRig(guide, test::builtinTemplates());
    const Scene scene = makeScene(guide, &rig, {});
    Camera camera;
    glm::dvec3 lo, hi;
    ASSERT_TRUE(scene.bounds(lo, hi));
    camera.frame(lo, hi);
    host->render(scene, camera);
    const auto image = host->readPixels();
    ASSERT_EQ(image.size(), std::size_t(host->width() * host->height() * 3));

    const glm::dmat4 vp = camera.projectionMatrix(double(host->width()) / host->height()) * camera.viewMatrix();
    glm::dvec2 p;
    EXPECT_TRUE(near(at(image, host->width(), {2, 2}), {41, 43, 48}, 3)) << "background in the corner";
    // A guide joint is drawn as an orange dot (242, 140, 51).
    ASSERT_TRUE(projectToPixels(vp, translationOf(guide.jointWorldMatrix(guide.instanceNamed("neck")->joints[2].id)),
                                host->width(), host->height(), p));
    EXPECT_TRUE(near(at(image, host->width(), p), {242, 140, 51}, 12));
    // Somewhere the yellow world controller is visible.
    int yellow = 0;
    for (std::size_t i = 0; i < image.size(); i += 3)
        yellow += image[i] > 230 && image[i + 1] > 230 && image[i + 2] < 40;
    EXPECT_GT(yellow, 50);
}
