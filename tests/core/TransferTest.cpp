// Importing skin chunks (skin/Transfer.h, issue 20): the decision tree picks
// 1:1 only when the mesh's count and order match (a subset chunk's vertices
// 1:1, the rest transferred), else the chunk of the same count and order
// unless told not to; a merge keeps the newest chunk of a name; bad options
// are refused by name. The fallback methods: TransferMethodsTest.cpp; on
// garments and a character: TransferCharacterTest.cpp.
#include "TestSupport.h"
#include "TransferFixtures.h"

#include "skin/Transfer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

using namespace rs;
using namespace rs::test::transfer;

TEST(Transfer, AOneToOneRoundTripIsExact)
{
    const model::Mesh mesh = grid("sheet", 30, 20, 0.0f);
    const model::MeshWeights weights = rampWeights(mesh, 0.29f);
    std::vector<skin::MeshImportReport> reports;
    auto imported = skin::importChunks({chunkOf(mesh, weights)}, {&mesh}, {}, &reports);
    ASSERT_TRUE(imported.ok()) << formatAll(imported.diagnostics());
    EXPECT_EQ(imported->front(), weights);
    ASSERT_EQ(reports.size(), 1u);
    EXPECT_EQ(reports[0].route, skin::ImportRoute::OneToOne);
    EXPECT_EQ(reports[0].oneToOne, mesh.vertexCount());
    EXPECT_EQ(reports[0].closestPoint, 0u);
}

TEST(Transfer, ASubsetChunkLoadsItsVerticesOneToOneAndTransfersTheRest)
{
    const model::Mesh mesh = grid("sheet", 20, 20, 0.0f);
    const model::MeshWeights weights = rampWeights(mesh, 0.19f);
    // Export the left half only (x < 10 cm): ids, points, weights and the triangles among them.
    const skin::SkinChunk whole = chunkOf(mesh, weights);
    skin::SkinChunk half = whole;
    half.vertexIds.clear();
    half.positions.clear();
    half.normals.clear();
    half.weights.offsets = {0};
    half.weights.influences.clear();
    std::vector<std::uint32_t> at(mesh.vertexCount(), ~0u);
    for (std::uint32_t v = 0; v < mesh.vertexCount(); ++v)
        if (mesh.positions[v].x < 0.1f) {
            at[v] = std::uint32_t(half.vertexIds.size());
            half.vertexIds.push_back(v);
            half.positions.push_back(whole.positions[v]);
            half.normals.push_back(whole.normals[v]);
            half.weights.influences.insert(half.weights.influences.end(), weights.begin(v), weights.end(v));
            half.weights.offsets.push_back(std::uint32_t(half.weights.influences.size()));
        }
    half.triangles.clear();
    for (std::size_t k = 0; k + 2 < mesh.indices.size(); k += 3)
        if (at[mesh.indices[k]] != ~0u && at[mesh.indices[k + 1]] != ~0u && at[mesh.indices[k + 2]] != ~0u)
            half.triangles.insert(half.triangles.end(), {at[mesh.indices[k]], at[mesh.indices[k + 1]], at[mesh.indices[k + 2]]});
    std::vector<skin::MeshImportReport> reports;
    auto imported = skin::importChunks({half}, {&mesh}, {}, &reports);
    ASSERT_TRUE(imported.ok()) << formatAll(imported.diagnostics());
    EXPECT_EQ(reports[0].route, skin::ImportRoute::OneToOne);
    EXPECT_EQ(reports[0].oneToOne, half.vertexCount());
    EXPECT_EQ(reports[0].closestPoint, mesh.vertexCount() - half.vertexCount());
    const model::MeshWeights& w = imported->front();
    for (std::uint32_t v = 0; v < mesh.vertexCount(); ++v) {
        ASSERT_GE(w.end(v) - w.begin(v), 1) << "vertex " << v << " is unweighted";
        if (at[v] != ~0u) {
            ASSERT_TRUE(std::equal(w.begin(v), w.end(v), weights.begin(v), weights.end(v))) << "vertex " << v << " is not 1:1";
        }
    }
}

TEST(Transfer, AReorderedMeshWithTheSameCountIsTransferredNotLoadedOneToOne)
{
    const model::Mesh mesh = grid("sheet", 30, 20, 0.0f);
    const model::MeshWeights weights = rampWeights(mesh, 0.29f);
    // The same surface with its vertices in reverse order.
    model::Mesh reordered = mesh;
    const std::uint32_t n = std::uint32_t(mesh.vertexCount());
    for (std::uint32_t v = 0; v < n; ++v)
        reordered.positions[v] = mesh.positions[n - 1 - v];
    for (std::uint32_t& i : reordered.indices)
        i = n - 1 - i;
    ASSERT_NE(model::topologyFingerprint(reordered), model::topologyFingerprint(mesh));
    for (const skin::TransferMethod method : {skin::TransferMethod::ClosestPoint, skin::TransferMethod::ClosestNeighbours}) {
        skin::TransferOptions options;
        options.method = method;
        std::vector<skin::MeshImportReport> reports;
        auto imported = skin::importChunks({chunkOf(mesh, weights)}, {&reordered}, options, &reports);
        ASSERT_TRUE(imported.ok()) << formatAll(imported.diagnostics());
        EXPECT_EQ(reports[0].route, skin::ImportRoute::Fallback);
        EXPECT_EQ(reports[0].oneToOne, 0u);
        EXPECT_EQ(reports[0].closestPoint + reports[0].closestNeighbours, mesh.vertexCount());
        const model::MeshWeights& w = imported->front();
        for (std::uint32_t v = 0; v < n; ++v) // each vertex is at a source vertex: its weights
            for (std::uint32_t j = 0; j < 3; ++j) {
                auto weightOf = [&](const model::MeshWeights& m, std::size_t at) {
                    float sum = 0.0f;
                    for (auto* i = m.begin(at); i != m.end(at); ++i)
                        sum += i->joint == j ? i->weight : 0.0f;
                    return sum;
                };
                ASSERT_NEAR(weightOf(w, v), weightOf(weights, n - 1 - v), 1e-5) << skin::transferMethodName(method) << " vertex " << v;
            }
    }
}

TEST(Transfer, TheDecisionTreeFindsTheChunkOfTheSameCountAndOrderUnlessToldNot)
{
    const model::Mesh mesh = grid("old_name", 12, 12, 0.0f);
    const model::MeshWeights weights = rampWeights(mesh, 0.11f);
    model::Mesh renamed = mesh;
    renamed.name = "new_name";
    const model::Mesh other = grid("hat", 5, 5, 0.5f);
    const std::vector<skin::SkinChunk> chunks = {chunkOf(mesh, weights), chunkOf(other, allOn(other, 2))};
    std::vector<skin::MeshImportReport> reports;
    auto found = skin::importChunks(chunks, {&renamed}, {}, &reports);
    ASSERT_TRUE(found.ok());
    EXPECT_EQ(reports[0].route, skin::ImportRoute::OneToOne);
    EXPECT_EQ(reports[0].source, "old_name");
    EXPECT_EQ(found->front(), weights);
    skin::TransferOptions noSearch;
    noSearch.searchByCountAndOrder = false;
    reports.clear();
    auto uber = skin::importChunks(chunks, {&renamed}, noSearch, &reports);
    ASSERT_TRUE(uber.ok());
    EXPECT_EQ(reports[0].route, skin::ImportRoute::Fallback);
    EXPECT_EQ(reports[0].source, "uber chunk");
    // The hat's chunk has one influence: its mesh goes 100% on it, whatever its topology.
    const model::Mesh hat = grid("hat", 9, 9, 0.5f);
    reports.clear();
    auto single = skin::importChunks(chunks, {&hat}, {}, &reports);
    ASSERT_TRUE(single.ok());
    EXPECT_EQ(reports[0].route, skin::ImportRoute::SingleInfluence);
    EXPECT_EQ(single->front().influences.size(), hat.vertexCount());
    EXPECT_EQ(dominant(single->front(), 40), 2u);
}

TEST(Transfer, AMergeKeepsTheNewestChunkOfAName)
{
    const model::Mesh mesh = grid("body", 4, 4, 0.0f);
    const skin::SkinChunk older = chunkOf(mesh, allOn(mesh, 0), 1000), newer = chunkOf(mesh, allOn(mesh, 1), 2000);
    for (const auto& order : {std::vector<skin::SkinChunk>{older, newer}, std::vector<skin::SkinChunk>{newer, older}}) {
        auto merged = skin::mergeChunks(order);
        ASSERT_TRUE(merged.ok());
        ASSERT_EQ(merged->size(), 1u);
        EXPECT_EQ(merged->front().exportedAtMicroseconds, 2000);
        EXPECT_EQ(merged->front().weights.influences[0].joint, 1u);
        ASSERT_EQ(merged.diagnostics().size(), 1u);
        EXPECT_NE(merged.diagnostics()[0].message.find("replaces the one exported"), std::string::npos);
    }
}

TEST(Transfer, BadOptionsAreRefusedByName)
{
    skin::TransferOptions options;
    options.neighbourCount = 0;
    options.normalTolerance = 2.0;
    const Status status = skin::validateTransferOptions(options);
    ASSERT_TRUE(status.failed());
    EXPECT_EQ(status.diagnostics().size(), 2u);
    EXPECT_NE(formatAll(status.diagnostics()).find("number of neighbours"), std::string::npos);
    EXPECT_FALSE(skin::parseTransferMethod("nearest").has_value());
}
