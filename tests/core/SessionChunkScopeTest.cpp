// Skin chunk scopes in the core session (issue 20 items 1 and 4): an export
// of the vertices some skin joints weight (Skinner's joint selection), and an
// import that appends (keeps the weights a subset chunk does not cover)
// rather than replacing the mesh's weights.
#include "SessionSkinFixture.h"
#include "TestSupport.h"

#include "session/Session.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

using namespace rs;
using namespace rs::test::sessionskin;

namespace {

std::vector<model::Influence> influencesOf(const model::MeshWeights& w, std::uint32_t v)
{
    return {w.begin(v), w.end(v)};
}

} // namespace

TEST(SessionSkin, AJointScopeExportsOnlyTheVerticesThoseJointsWeightWithAllTheirWeights)
{
    Fixture f;
    ASSERT_TRUE(test::succeeded(f.s.addModel(kArm)));
    f.bind();
    const model::Rig& rig = *f.s.rig();
    const NodeKey elbow = rig.nodes[*rig.findPath("arm.L::skin.limb.1")].key;
    auto chunks = f.s.exportSkinChunks(session::SkinScope::ofJoints({elbow}));
    ASSERT_TRUE(chunks.ok()) << formatAll(chunks.diagnostics());
    ASSERT_EQ(chunks->size(), 1u);
    const skin::SkinChunk& c = (*chunks)[0];
    EXPECT_GT(c.vertexCount(), 0u);
    EXPECT_LT(c.vertexCount(), c.totalVertexCount) << "the elbow does not weight the whole sleeve";
    const auto joint = std::find_if(c.joints.begin(), c.joints.end(), [&](const skin::ChunkJoint& j) { return j.key == elbow; });
    ASSERT_NE(joint, c.joints.end());
    const std::uint32_t elbowIndex = std::uint32_t(joint - c.joints.begin());
    bool otherJoints = false;
    for (std::size_t i = 0; i < c.vertexCount(); ++i) {
        bool weighted = false;
        for (const model::Influence* w = c.weights.begin(i); w != c.weights.end(i); ++w) {
            weighted = weighted || (w->joint == elbowIndex && w->weight > 0.0f);
            otherJoints = otherJoints || w->joint != elbowIndex;
        }
        ASSERT_TRUE(weighted) << "exported vertex " << c.vertexIds[i] << " has no elbow weight";
    }
    EXPECT_TRUE(otherJoints) << "the vertices keep all their weights, not only the elbow's";
    // Every vertex the elbow weights is in the chunk.
    const model::MeshWeights& bound = f.s.document().bindings[0].weights;
    const auto boundElbow = std::find(bound.joints.begin(), bound.joints.end(), elbow) - bound.joints.begin();
    std::size_t weightedByElbow = 0;
    for (std::size_t v = 0; v < bound.vertexCount(); ++v)
        weightedByElbow += std::any_of(bound.begin(v), bound.end(v), [&](const model::Influence& i) {
            return i.joint == std::uint32_t(boundElbow) && i.weight > 0.0f;
        });
    EXPECT_EQ(c.vertexCount(), weightedByElbow);

    auto unknown = f.s.exportSkinChunks(session::SkinScope::ofJoints({{999, "", "skin.nose"}}));
    ASSERT_FALSE(unknown.ok());
    EXPECT_NE(formatAll(unknown.diagnostics()).find("'skin.nose' of instance 999 is not a skin joint of the rig"), std::string::npos)
        << formatAll(unknown.diagnostics());
    EXPECT_FALSE(f.s.exportSkinChunks(session::SkinScope::ofJoints({}))) << "no joint selected";
    EXPECT_FALSE(f.s.prepareSkinImport(*chunks, {}, session::SkinScope::ofJoints({elbow}))) << "an import writes vertices, not joints";
}

TEST(SessionSkin, AnAppendedImportOfASubsetChunkKeepsTheOtherVerticesWeights)
{
    Fixture f;
    ASSERT_TRUE(test::succeeded(f.s.addModel(kArm)));
    f.bind();
    const model::MeshWeights bound = f.s.document().bindings[0].weights;
    const std::uint32_t n = std::uint32_t(bound.vertexCount());
    f.s.selectVertices(0, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9}, false);
    auto subset = f.s.exportSkinChunks(session::SkinScope::selectedVertices());
    ASSERT_TRUE(subset.ok());
    ASSERT_EQ((*subset)[0].vertexCount(), 10u);
    std::vector<std::uint32_t> all(n);
    std::iota(all.begin(), all.end(), 0u);
    f.s.selectVertices(0, all, false);
    ASSERT_TRUE(test::succeeded(f.s.applyWeightOperation(session::Session::WeightOperation::Limit, 1)));
    f.s.clearVertexSelection();
    const model::MeshWeights spoiled = f.s.document().bindings[0].weights;

    auto job = f.s.prepareSkinImport(*subset, {}, session::SkinScope::all());
    ASSERT_TRUE(job.ok());
    job->append = true;
    ASSERT_TRUE(test::succeeded(job->run()));
    EXPECT_EQ(job->reports[0].route, skin::ImportRoute::OneToOne);
    auto appended = f.s.applySkinImport(job.take(), "Import skin weights");
    ASSERT_TRUE(appended.ok()) << formatAll(appended.diagnostics());
    EXPECT_NE(formatAll(appended.diagnostics()).find("appended: 10 vertices written, " + std::to_string(n - 10) + " kept their weights"),
              std::string::npos)
        << formatAll(appended.diagnostics());
    const model::MeshWeights& w = f.s.document().bindings[0].weights;
    for (std::uint32_t v = 0; v < n; ++v)
        ASSERT_EQ(influencesOf(w, v), influencesOf(v < 10 ? bound : spoiled, v)) << "vertex " << v;
    f.s.history().undo();
    ASSERT_TRUE(f.s.document().bindings[0].weights == spoiled);

    // Without append every vertex is written: those the chunk leaves out by transfer from it.
    auto replaced = f.s.importSkinChunks(*subset, {}, session::SkinScope::all());
    ASSERT_TRUE(replaced.ok());
    const model::MeshWeights& r = f.s.document().bindings[0].weights;
    std::size_t changed = 0;
    for (std::uint32_t v = 10; v < n; ++v)
        changed += influencesOf(r, v) != influencesOf(spoiled, v);
    EXPECT_GT(changed, 0u) << "the vertices outside the chunk were written too";
}
