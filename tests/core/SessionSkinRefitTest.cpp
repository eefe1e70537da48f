// A bound mesh that changed since its bind, in the core session: re-fitted
// from the previous mesh's chunk when its model is reloaded and when a guide
// whose model was re-ordered or remeshed is opened (one undo step that brings
// the old record back), and kept but not applied, with a report, when there
// is no previous mesh or its model is gone.
#include "SessionSkinFixture.h"
#include "TestSupport.h"

#include "io/WeightsFile.h"
#include "session/Session.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

using namespace rs;

using namespace rs::test::sessionskin;

TEST(SessionSkin, AReloadedChangedMeshIsRefittedAndUndoKeepsTheOldRecordNotApplied)
{
    Fixture f;
    ASSERT_TRUE(test::succeeded(f.s.addModel(kArm)));
    f.bind();
    const model::MeshBinding bound = f.s.document().bindings[0];
    // The file changes on disk: two more rings.
    model::Model longer = f.files.files[kArm];
    const model::Mesh& old = longer.meshes[0];
    longer.meshes[0] = tube("sleeve", old.positions.front(), old.positions.back(), 18);
    f.files.files[kArm] = longer;
    f.reported.clear();
    ASSERT_TRUE(test::succeeded(f.s.reloadModel(kArm)));
    EXPECT_TRUE(f.saidSomething("mesh 'sleeve' changed since it was bound (192 vertices then, 216 now): its weights were re-fitted"));
    EXPECT_EQ(f.s.history().undoText(), "Re-fit weights of mesh 'sleeve'");
    EXPECT_FALSE(f.s.characterMeshes()[0].changed);
    EXPECT_TRUE(f.s.characterMeshes()[0].weights);
    EXPECT_EQ(f.s.document().bindings[0].vertexCount, 216u);

    f.s.history().undo();
    EXPECT_TRUE(f.s.characterMeshes()[0].changed);
    EXPECT_FALSE(f.s.characterMeshes()[0].weights) << "never applied to the wrong vertices";
    EXPECT_TRUE(f.s.document().bindings[0] == bound) << "the old record comes back";

    // Without the previous mesh (an older guide, no chunk file) it is kept and reported.
    f.s.setSavedChunks({});
    f.reported.clear();
    f.s.replaceDocument(f.s.document());
    EXPECT_TRUE(f.saidSomething("mesh 'sleeve' changed since it was bound (192 vertices then, 216 now): its weights are kept but not applied; bind it again"));
    EXPECT_TRUE(f.s.document().bindings[0] == bound) << "kept";
    EXPECT_FALSE(f.s.history().canUndo());

    // A record whose model is gone from the guide is kept and reported too.
    f.reported.clear();
    model::GuideDocument guide = f.s.document();
    guide.models.clear();
    f.s.replaceDocument(guide);
    EXPECT_TRUE(f.saidSomething("match no mesh"));
    EXPECT_EQ(f.s.document().bindings.size(), 1u);
}

namespace {

std::uint32_t dominantJoint(const model::MeshWeights& w, std::size_t v)
{
    const model::Influence* best = std::max_element(w.begin(v), w.end(v), [](auto& a, auto& b) { return a.weight < b.weight; });
    return best->joint;
}

} // namespace

TEST(SessionSkin, AGuideWhoseModelWasReorderedOrRemeshedIsRefittedOnOpenWithAReport)
{
    Fixture f;
    ASSERT_TRUE(test::succeeded(f.s.addModel(kArm)));
    f.bind();
    const model::GuideDocument saved = f.s.document();
    const std::string folder = test::temporaryPath("session-refit");
    std::filesystem::create_directories(folder);
    const std::string guide = folder + "/hero.yml";
    ASSERT_TRUE(test::succeeded(io::saveGuideChunks(f.s.bindingChunks(), guide)));
    EXPECT_EQ(io::chunksPathFor(guide), folder + "/hero.weights.rschunks");
    auto chunks = io::loadGuideChunks(guide);
    ASSERT_TRUE(chunks.ok());
    ASSERT_EQ(chunks->size(), 1u);

    // Re-ordered: the same vertices backwards (same count, other order).
    const model::Mesh before = f.files.files[kArm].meshes[0];
    const std::uint32_t n = std::uint32_t(before.vertexCount());
    model::Mesh reversed = before;
    std::reverse(reversed.positions.begin(), reversed.positions.end());
    for (std::uint32_t& i : reversed.indices)
        i = n - 1 - i;
    Fixture g;
    g.files.files[kArm].meshes[0] = reversed;
    g.s.setSavedChunks(*chunks);
    g.s.replaceDocument(saved); // as File > Open does
    EXPECT_TRUE(g.saidSomething("its weights were re-fitted from the previous mesh"));
    EXPECT_TRUE(g.saidSomething("0 vertices matched 1:1")) << "the order check fails: not loaded 1:1";
    EXPECT_EQ(g.s.history().undoText(), "Re-fit weights of mesh 'sleeve'");
    EXPECT_FALSE(g.s.characterMeshes()[0].changed) << "the re-fitted record fits the mesh (applied once the rig is built)";
    g.s.build();
    ASSERT_TRUE(g.s.characterMeshes()[0].weights);
    const model::MeshWeights& was = saved.bindings[0].weights;
    const model::MeshWeights& now = g.s.document().bindings[0].weights;
    std::size_t same = 0;
    for (std::uint32_t v = 0; v < n; ++v)
        same += now.joints[dominantJoint(now, v)] == was.joints[dominantJoint(was, n - 1 - v)];
    EXPECT_GE(same, n * 98 / 100) << "each vertex keeps its weights wherever it moved in the order";

    // Remeshed: two more rings.
    Fixture h;
    h.files.files[kArm].meshes[0] = tube("sleeve", before.positions.front(), before.positions.back(), 18);
    h.s.setSavedChunks(*chunks);
    h.s.replaceDocument(saved);
    EXPECT_TRUE(h.saidSomething("(192 vertices then, 216 now): its weights were re-fitted"));
    EXPECT_EQ(h.s.document().bindings[0].vertexCount, 216u);
    EXPECT_FALSE(h.s.characterMeshes()[0].changed);
    h.s.history().undo();
    EXPECT_TRUE(h.s.document().bindings[0] == saved.bindings[0]) << "undo brings the previous record back";
    std::filesystem::remove_all(folder);
}
