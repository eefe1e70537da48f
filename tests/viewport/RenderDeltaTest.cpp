// The renderer's scene layers are persistent: a change that names its
// instances (Scene::delta) sends only their vertices, and the picture is the
// one a full upload of the same scene draws.
#include "GlfwHost.h"
#include "render/Renderer.h"

#include "rigging/RigBuilder.h"
#include "core/TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

using namespace rs;
using namespace rs::viewport;

namespace {

std::unique_ptr<GlfwHost> host()
{
    std::string error;
    auto h = GlfwHost::create(640, 480, "render delta test", false, error);
    EXPECT_TRUE(h) << error << " (GL tests need a display: run them under xvfb-run)";
    return h;
}

std::size_t differingPixels(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b)
{
    std::size_t n = 0;
    for (std::size_t i = 0; i + 2 < a.size() && i + 2 < b.size(); i += 3)
        n += a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2];
    return n;
}

} // namespace

TEST(RenderDelta, AOneInstanceGuideEditSendsThatInstancesVerticesAndDrawsWhatAFullUploadDraws)
{
    auto drawn = host(), fresh = host();
    ASSERT_TRUE(drawn && fresh);
    model::GuideDocument guide = test::loadSample("biped");
    const SceneSelection selection{guide.instanceNamed("index")->id, model::kNoId, {}, model::kNoNode, {}, false, {}};
    const auto rig0 = rigging::buildRig(guide, test::builtinTemplates());
    Scene before = makeScene(guide, &rig0, selection);
    before.revision = 1;
    Camera camera;
    glm::dvec3 lo, hi;
    ASSERT_TRUE(before.bounds(lo, hi));
    camera.frame(lo, hi);
    drawn->render(before, camera);
    const std::uint64_t full = drawn->renderer().sceneVerticesUploaded();
    const auto imageBefore = drawn->readPixels();

    // A guide drag's step: the index finger's root joint moves.
    model::TemplateInstance* index = guide.instance(guide.instanceNamed("index")->id);
    index->joints.front().local.translate += Vec3(0.0, 0.04, 0.05);
    const auto rig1 = rigging::buildRig(guide, test::builtinTemplates());
    Scene after = makeScene(guide, &rig1, selection);
    after.revision = 2;
    // The editor names the instance and its ancestors (a builder may read its
    // children); theirs draw the same and are not sent.
    std::vector<model::InstanceId> named{index->id};
    for (const auto* i = index; i->parent != model::kNoId; i = guide.instance(i->parent))
        named.push_back(i->parent);
    std::sort(named.begin(), named.end());
    after.delta = {false, 1, named};
    drawn->render(after, camera);
    const std::uint64_t sent = drawn->renderer().sceneVerticesUploaded() - full;
    std::printf("scene vertices: full upload %llu (%llu bytes), one-instance edit %llu (%llu bytes)\n",
                (unsigned long long)full, (unsigned long long)(full * Renderer::vertexSize()), (unsigned long long)sent,
                (unsigned long long)(sent * Renderer::vertexSize()));
    EXPECT_GT(sent, 0u);
    EXPECT_LT(sent * 8, full) << "the finger's vertices, not the biped's";

    after.delta = {}; // the same scene, all of it, through a renderer that holds nothing yet
    fresh->render(after, camera);
    const auto image = drawn->readPixels();
    EXPECT_EQ(differingPixels(image, fresh->readPixels()), 0u) << "the incremental picture is the full upload's";
    EXPECT_GT(differingPixels(image, imageBefore), 20u) << "and the moved finger shows";
}

TEST(RenderDelta, AChangeThatEmptiesAnInstancesBlockSendsItsLayerAgainAndStillDrawsRight)
{
    auto drawn = host(), fresh = host();
    ASSERT_TRUE(drawn && fresh);
    model::GuideDocument guide = test::loadSample("biped");
    const auto rig0 = rigging::buildRig(guide, test::builtinTemplates());
    Scene before = makeScene(guide, &rig0, {});
    before.revision = 1;
    Camera camera;
    glm::dvec3 lo, hi;
    ASSERT_TRUE(before.bounds(lo, hi));
    camera.frame(lo, hi);
    drawn->render(before, camera);
    // The neck's shapes are hidden (as a shape override does): its
    // curve block empties while its joints stay.
    const model::InstanceId middle = guide.instanceNamed("neck")->id;
    Scene after = makeScene(guide, &rig0, {});
    const std::size_t curves = after.curves.size();
    std::erase_if(after.curves, [&](const SceneCurve& c) { return c.owner == middle; });
    ASSERT_LT(after.curves.size(), curves);
    after.revision = 2;
    after.delta = {false, 1, {middle}};
    drawn->render(after, camera);
    after.delta = {};
    fresh->render(after, camera);
    EXPECT_EQ(differingPixels(drawn->readPixels(), fresh->readPixels()), 0u);
    const auto image = drawn->readPixels();
    after.revision = 3; // and back: the block comes back at the end of the layer
    after.delta = {false, 2, {middle}};
    Scene again = makeScene(guide, &rig0, {});
    again.revision = 3;
    again.delta = {false, 2, {middle}};
    drawn->render(again, camera);
    again.delta = {};
    fresh->render(again, camera);
    EXPECT_EQ(differingPixels(drawn->readPixels(), fresh->readPixels()), 0u);
    EXPECT_GT(differingPixels(drawn->readPixels(), image), 10u) << "the shapes show again";
}
