// Importing skin chunks (skin/Transfer.h, issue 20): the decision tree picks
// 1:1 only when the mesh's count and order match, the fallbacks carry weights
// onto a changed mesh, the normal filter keeps an overlapping surface's
// weights off, and a merge keeps the newest chunk of a name.
#include "JeansFixture.h"
#include "TestSupport.h"

#include "io/ModelImport.h"
#include "rigging/RigBuilder.h"
#include "skin/AutoWeights.h"
#include "skin/NearestPoints.h"
#include "skin/Refit.h"
#include "skin/Surface.h"
#include "skin/Transfer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numeric>

using namespace rs;

namespace {

// A grid of nx by ny vertices, 1 cm apart, at height z, facing +z (or -z).
model::Mesh grid(const std::string& name, int nx, int ny, float z, bool up = true, float spacing = 0.01f)
{
    model::Mesh mesh;
    mesh.name = name;
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x)
            mesh.positions.push_back({x * spacing, y * spacing, z});
    for (int y = 0; y + 1 < ny; ++y)
        for (int x = 0; x + 1 < nx; ++x) {
            const std::uint32_t a = std::uint32_t(y * nx + x), b = a + 1, c = a + std::uint32_t(nx), d = c + 1;
            if (up)
                mesh.indices.insert(mesh.indices.end(), {a, b, c, b, d, c});
            else
                mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
        }
    return mesh;
}

// Three joints along x: the first fades into the second, the second into the third.
model::MeshWeights rampWeights(const model::Mesh& mesh, float width)
{
    model::MeshWeights w;
    w.joints = {{1, "", "skin.a"}, {1, "", "skin.b"}, {1, "", "skin.c"}};
    w.parents = {-1, 0, 1};
    w.offsets.push_back(0);
    for (const glm::vec3& p : mesh.positions) {
        const float t = std::clamp(p.x / width, 0.0f, 1.0f) * 2.0f;
        if (t < 1.0f)
            w.influences.insert(w.influences.end(), {{0, 1.0f - t}, {1, t}});
        else
            w.influences.insert(w.influences.end(), {{1, 2.0f - t}, {2, t - 1.0f}});
        w.offsets.push_back(std::uint32_t(w.influences.size()));
    }
    return w;
}

model::MeshWeights allOn(const model::Mesh& mesh, std::uint32_t joint)
{
    model::MeshWeights w;
    w.joints = {{1, "", "skin.a"}, {1, "", "skin.b"}, {1, "", "skin.c"}};
    w.parents = {-1, 0, 1};
    for (std::uint32_t v = 0; v <= mesh.vertexCount(); ++v)
        w.offsets.push_back(v);
    w.influences.assign(mesh.vertexCount(), {joint, 1.0f});
    return w;
}

// The chunk of a whole mesh in bind pose.
skin::SkinChunk chunkOf(const model::Mesh& mesh, const model::MeshWeights& weights, std::int64_t time = 1)
{
    skin::SkinChunk c = skin::bindingChunk({"", mesh.name, mesh.vertexCount(), model::topologyFingerprint(mesh), weights}, mesh, nullptr);
    c.exportedAtMicroseconds = time; // the merge tests say which is newer
    return c;
}

std::uint32_t dominant(const model::MeshWeights& w, std::size_t v)
{
    return std::max_element(w.begin(v), w.end(v), [](const auto& a, const auto& b) { return a.weight < b.weight; })->joint;
}

} // namespace

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

TEST(Transfer, ClosestPointBlendsTheTrianglesVerticesAndNeighboursBlendByDistance)
{
    const model::Mesh coarse = grid("sheet", 11, 11, 0.0f, true, 0.02f);
    const model::MeshWeights weights = rampWeights(coarse, 0.2f);
    model::Mesh fine = grid("sheet", 41, 41, 0.002f, true, 0.005f); // 2 mm above, four times denser
    std::vector<skin::MeshImportReport> reports;
    auto closest = skin::importChunks({chunkOf(coarse, weights)}, {&fine}, {}, &reports);
    ASSERT_TRUE(closest.ok());
    EXPECT_EQ(reports[0].route, skin::ImportRoute::Fallback);
    EXPECT_NE(reports[0].why.find("121 -> 1681 vertices"), std::string::npos) << reports[0].why;
    // The ramp is linear on each triangle: closest point on triangles reproduces it.
    const model::MeshWeights exact = rampWeights(fine, 0.2f);
    for (std::size_t v = 0; v < fine.vertexCount(); ++v)
        for (auto* i = exact.begin(v); i != exact.end(v); ++i) {
            float got = 0.0f;
            for (auto* k = closest->front().begin(v); k != closest->front().end(v); ++k)
                got += k->joint == i->joint ? k->weight : 0.0f;
            ASSERT_NEAR(got, i->weight, 1e-4) << "vertex " << v;
        }
    skin::TransferOptions neighbours;
    neighbours.method = skin::TransferMethod::ClosestNeighbours;
    reports.clear();
    auto blended = skin::importChunks({chunkOf(coarse, weights)}, {&fine}, neighbours, &reports);
    ASSERT_TRUE(blended.ok());
    EXPECT_EQ(reports[0].closestNeighbours, fine.vertexCount());
    for (std::size_t v = 0; v < fine.vertexCount(); ++v)
        ASSERT_EQ(dominant(blended->front(), v), dominant(exact, v)) << "vertex " << v;
}

TEST(Transfer, TheNormalFilterKeepsAnOverlappingSurfacesWeightsOff)
{
    // Two sheets 1 cm apart facing away from each other (the inside of two
    // legs), the lower on joint a, the upper on joint c. The target faces up
    // from 6 mm: nearer the upper sheet, but facing as the lower one does.
    const model::Mesh lower = grid("lower", 10, 10, 0.0f, true), upper = grid("upper", 10, 10, 0.01f, false);
    const model::Mesh target = grid("pants", 12, 12, 0.006f, true, 0.0075f);
    const std::vector<skin::SkinChunk> chunks = {chunkOf(lower, allOn(lower, 0)), chunkOf(upper, allOn(upper, 2))};
    for (const skin::TransferMethod method : {skin::TransferMethod::ClosestPoint, skin::TransferMethod::ClosestNeighbours}) {
        skin::TransferOptions options;
        options.method = method;
        std::vector<skin::MeshImportReport> reports;
        auto plain = skin::importChunks(chunks, {&target}, options, &reports);
        ASSERT_TRUE(plain.ok());
        EXPECT_EQ(reports[0].source, "uber chunk");
        EXPECT_EQ(dominant(plain->front(), 66), 2u) << "without the filter the nearer, wrong surface wins";
        options.normalFilter = true;
        reports.clear();
        auto filtered = skin::importChunks(chunks, {&target}, options, &reports);
        ASSERT_TRUE(filtered.ok());
        for (std::size_t v = 0; v < target.vertexCount(); ++v)
            ASSERT_EQ(dominant(filtered->front(), v), 0u) << skin::transferMethodName(method) << " vertex " << v;
        EXPECT_EQ(reports[0].normalFilterFallbacks, 0u);
    }
    // Nothing faces the target's way: every vertex falls back to closest point, unfiltered.
    skin::TransferOptions options;
    options.normalFilter = true;
    std::vector<skin::MeshImportReport> reports;
    auto fallback = skin::importChunks({chunkOf(upper, allOn(upper, 2))}, {&target}, options, &reports);
    ASSERT_TRUE(fallback.ok());
    EXPECT_EQ(reports[0].normalFilterFallbacks, target.vertexCount());
    EXPECT_EQ(dominant(fallback->front(), 0), 2u);
}

TEST(Transfer, InpaintingFillsWhatTheClosestPointWouldTakeFromTheWrongSurface)
{
    // The lower sheet (joint a) faces up under the whole target; the upper one
    // (joint c) faces down over its left half only, nearer than the lower.
    const model::Mesh lower = grid("lower", 10, 10, 0.0f, true), upper = grid("upper", 5, 10, 0.01f, false);
    const model::Mesh target = grid("pants", 12, 12, 0.006f, true, 0.0075f);
    const std::vector<skin::SkinChunk> chunks = {chunkOf(lower, allOn(lower, 0)), chunkOf(upper, allOn(upper, 2))};
    std::vector<skin::MeshImportReport> reports;
    auto closest = skin::importChunks(chunks, {&target}, {}, &reports);
    ASSERT_TRUE(closest.ok());
    std::size_t wrong = 0;
    for (std::size_t v = 0; v < target.vertexCount(); ++v)
        wrong += dominant(closest->front(), v) != 0;
    EXPECT_GT(wrong, target.vertexCount() / 4) << "closest point takes the upper sheet's joint on the left";
    skin::TransferOptions options;
    options.method = skin::TransferMethod::Inpainting;
    options.inpaintDistance = 0.02; // 5% of this small sheet's diagonal (the default) is under the 6 mm gap
    reports.clear();
    auto inpainted = skin::importChunks(chunks, {&target}, options, &reports);
    ASSERT_TRUE(inpainted.ok()) << formatAll(inpainted.diagnostics());
    EXPECT_EQ(reports[0].inpainted, wrong);
    EXPECT_EQ(reports[0].closestPoint + reports[0].inpainted, target.vertexCount());
    const auto& ids = reports[0].inpaintedVertices; // by vertex: the ones closest point got wrong
    ASSERT_EQ(ids.size(), wrong);
    for (std::size_t v = 0; v < target.vertexCount(); ++v)
        EXPECT_EQ(std::binary_search(ids.begin(), ids.end(), std::uint32_t(v)), dominant(closest->front(), v) != 0) << "vertex " << v;
    for (std::size_t v = 0; v < target.vertexCount(); ++v) {
        ASSERT_EQ(dominant(inpainted->front(), v), 0u) << "vertex " << v;
        float sum = 0.0f;
        for (auto* i = inpainted->front().begin(v); i != inpainted->front().end(v); ++i)
            sum += i->weight;
        ASSERT_NEAR(sum, 1.0f, 1e-5);
    }
    // Where every closest point is near and agrees, inpainting is closest point.
    const model::Mesh coarse = grid("sheet", 11, 11, 0.0f, true, 0.02f), fine = grid("sheet", 41, 41, 0.002f, true, 0.005f);
    const model::MeshWeights ramp = rampWeights(coarse, 0.2f);
    auto a = skin::importChunks({chunkOf(coarse, ramp)}, {&fine}, {}, nullptr);
    auto b = skin::importChunks({chunkOf(coarse, ramp)}, {&fine}, options, nullptr);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a->front(), b->front());
}

namespace {

// How far the posed pants land from where their own legs would take them.
struct Displacement {
    float worst = 0.0f, mean = 0.0f;
    std::size_t wrongLeg = 0; // vertices whose heaviest joint is not the ideal's
};

Displacement displacement(const test::JeansFixture& f, const model::MeshWeights& weights)
{
    const auto posed = test::skinWithLeftLegForward(f, f.pants, weights, 45.0f);
    const auto ideal = test::skinWithLeftLegForward(f, f.pants, f.idealPants, 45.0f);
    Displacement d;
    for (std::size_t v = 0; v < posed.size(); ++v) {
        const float error = glm::length(posed[v] - ideal[v]);
        d.worst = std::max(d.worst, error);
        d.mean += error / float(posed.size());
        d.wrongLeg += dominant(weights, v) != dominant(f.idealPants, v);
    }
    return d;
}

} // namespace

TEST(Transfer, ParachutePantsOverSkinnyJeansStretchLessWithTheNormalFilterAndLeastWithInpainting)
{
    // The metric: the left leg swings 45 degrees forward and each pants vertex
    // is compared with where the jeans' weights at its own leg's height take
    // it (JeansFixture::idealPants). A vertex weighted to the other leg stays
    // behind (or follows the wrong leg) by up to the leg's whole swing; the
    // worst such vertex is what a rigger sees as the garment tearing at the
    // crotch. Unlike the longest stretched edge it is zero for a right
    // transfer and does not depend on the tessellation.
    const test::JeansFixture f = test::makeJeansFixture();
    auto source = skin::TransferSource::fromChunk(f.jeansChunk, true);
    ASSERT_TRUE(source.ok()) << formatAll(source.diagnostics());
    skin::TransferOptions closest, filtered, inpainting;
    filtered.normalFilter = true;
    inpainting.method = skin::TransferMethod::Inpainting;
    std::vector<Displacement> results;
    for (const auto* options : {&closest, &filtered, &inpainting}) {
        skin::MeshImportReport report;
        auto weights = skin::transferWeights(*source, f.pants, *options, &report);
        ASSERT_TRUE(weights.ok()) << formatAll(weights.diagnostics());
        results.push_back(displacement(f, *weights));
        std::cout << "[ jeans ] " << (options == &closest ? "closest point" : options == &filtered ? "normal filter" : "inpainting")
                  << ": worst displacement " << results.back().worst * 100.0f << " cm, mean " << results.back().mean * 1000.0f << " mm, "
                  << results.back().wrongLeg << " of " << f.pants.vertexCount() << " vertices on the wrong leg"
                  << (options == &inpainting ? ", " + std::to_string(report.inpainted) + " inpainted" : std::string()) << "\n";
    }
    EXPECT_GT(results[0].wrongLeg, 0u) << "the fixture must fool closest point";
    EXPECT_LT(results[1].worst, results[0].worst) << "the normal filter";
    EXPECT_LT(results[2].worst, results[1].worst) << "inpainting";
    EXPECT_EQ(results[2].wrongLeg, 0u);
}

TEST(Transfer, CancellingDuringInpaintingGivesAnErrorAndNoResult)
{
    // The lower sheet (a ramp over three joints) faces up under the whole
    // target; the upper one faces down over its left three quarters: those
    // target vertices are inpainted, one region above kSmallRegion (4096).
    const model::Mesh lower = grid("lower", 70, 70, 0.0f, true), upper = grid("upper", 52, 70, 0.01f, false);
    const model::Mesh target = grid("pants", 80, 80, 0.006f, true, 0.0087f);
    const skin::SkinChunk chunk = chunkOf(lower, rampWeights(lower, 0.69f));
    const skin::SkinChunk top = chunkOf(upper, allOn(upper, 2));
    auto source = skin::TransferSource::uber({chunk, top}, true);
    ASSERT_TRUE(source.ok());
    skin::TransferOptions options;
    options.method = skin::TransferMethod::Inpainting;
    std::vector<double> heard;
    options.progress = [&](double f) {
        heard.push_back(f);
        return true;
    };
    skin::MeshImportReport report;
    auto whole = skin::transferWeights(*source, target, options, &report);
    ASSERT_TRUE(whole.ok()) << formatAll(whole.diagnostics());
    EXPECT_GT(report.inpainted, 4096u);
    ASSERT_FALSE(heard.empty());
    EXPECT_DOUBLE_EQ(heard.back(), 1.0);
    EXPECT_TRUE(std::is_sorted(heard.begin(), heard.end()));
    // The reports after the closest points (the first 20%) come from the solve:
    // cancel at each of them in turn.
    const auto inpaintingReports = std::count_if(heard.begin(), heard.end(), [](double f) { return f > 0.2; });
    EXPECT_GE(inpaintingReports, 3) << "assembly, factorisation and the joint solves";
    for (std::ptrdiff_t cancelAt = 0; cancelAt < inpaintingReports; ++cancelAt) {
        std::ptrdiff_t seen = 0;
        options.progress = [&](double f) { return f <= 0.2 || seen++ < cancelAt; };
        auto cancelled = skin::transferWeights(*source, target, options, nullptr);
        ASSERT_FALSE(cancelled.ok()) << "cancelled at inpainting report " << cancelAt;
        EXPECT_NE(formatAll(cancelled.diagnostics()).find("cancelled"), std::string::npos) << formatAll(cancelled.diagnostics());
    }
    // Nothing to inpaint (every closest point near and facing the same way): the progress still ends at 1.
    heard.clear();
    options.progress = [&](double f) {
        heard.push_back(f);
        return true;
    };
    report = {};
    ASSERT_TRUE(skin::transferWeights(*source, grid("below", 20, 20, -0.002f), options, &report).ok());
    EXPECT_EQ(report.inpainted, 0u);
    ASSERT_FALSE(heard.empty());
    EXPECT_DOUBLE_EQ(heard.back(), 1.0);
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

TEST(Transfer, SmoothingStepsSoftenOnlyWhereWeightsJumpAndNeverAtASourceVertex)
{
    // A hard edge: joint a left of x = 5.5 cm, joint c right of it.
    const model::Mesh coarse = grid("sheet", 12, 12, 0.0f, true, 0.01f);
    model::MeshWeights hard = allOn(coarse, 0);
    for (std::size_t v = 0; v < coarse.vertexCount(); ++v)
        if (coarse.positions[v].x > 0.055f)
            hard.influences[v].joint = 2;
    const model::Mesh fine = grid("sheet", 45, 45, 0.0f, true, 0.0025f);
    skin::TransferOptions options;
    options.smoothSteps = 3;
    std::vector<skin::MeshImportReport> reports;
    auto smoothed = skin::importChunks({chunkOf(coarse, hard)}, {&fine}, options, &reports);
    ASSERT_TRUE(smoothed.ok());
    EXPECT_GT(reports[0].smoothed, 0u);
    EXPECT_LT(reports[0].smoothed, fine.vertexCount() / 4) << "only around the edge";
    const model::MeshWeights& w = smoothed->front();
    for (std::size_t v = 0; v < fine.vertexCount(); ++v) {
        float sum = 0.0f;
        for (auto* i = w.begin(v); i != w.end(v); ++i)
            sum += i->weight;
        ASSERT_NEAR(sum, 1.0f, 1e-5);
        if (std::fmod(fine.positions[v].x + 1e-4f, 0.01f) < 2e-4f && std::fmod(fine.positions[v].y + 1e-4f, 0.01f) < 2e-4f) {
            ASSERT_EQ(w.end(v) - w.begin(v), 1) << "vertex " << v << " is at a source vertex: its weights stay as they are";
        }
    }
    reports.clear();
    options.weightDifferenceThreshold = 1.0; // no neighbour differs by more than everything
    ASSERT_TRUE(skin::importChunks({chunkOf(coarse, hard)}, {&fine}, options, &reports).ok());
    EXPECT_EQ(reports[0].smoothed, 0u);
}

TEST(Transfer, NearestPointsAreExactNearAndFarFromTheCloud)
{
    // Points on a wavy sheet (the grid's case) and two clumps; queries on it,
    // just off it and far away (the KD-tree's case), against brute force.
    std::vector<glm::vec3> points;
    std::uint32_t seed = 12345;
    auto random = [&] {
        seed = seed * 1664525u + 1013904223u;
        return float(seed >> 8) / float(1u << 24);
    };
    for (int i = 0; i < 4000; ++i) {
        const float u = random(), v = random();
        points.push_back({u, v, 0.05f * std::sin(7.0f * u)});
    }
    for (int i = 0; i < 50; ++i)
        points.push_back({2.0f + 0.001f * random(), 0.0f, 0.0f});
    points.push_back(points[17]); // a duplicate
    const skin::NearestPoints nearest(points);
    for (int q = 0; q < 1500; ++q) {
        const float spread = q < 500 ? 0.001f : q < 1000 ? 0.05f : 3.0f;
        const glm::vec3 p(random() * 1.2f - 0.1f, random() * 1.2f - 0.1f, (random() - 0.5f) * spread);
        std::vector<float> all;
        for (const glm::vec3& x : points)
            all.push_back(glm::dot(x - p, x - p));
        std::partial_sort(all.begin(), all.begin() + 16, all.end());
        for (const int k : {1, 3, 16}) {
            std::uint32_t index[32];
            float distance2[32];
            ASSERT_EQ(nearest.nearest(p, k, index, distance2), k);
            for (int i = 0; i < k; ++i) {
                ASSERT_EQ(distance2[i], all[std::size_t(i)]) << "query " << q << " k " << k << " rank " << i;
                ASSERT_EQ(glm::dot(points[index[i]] - p, points[index[i]] - p), distance2[i]);
            }
        }
    }
    std::uint32_t index[5];
    float distance2[5];
    EXPECT_EQ(skin::NearestPoints({{0, 0, 0}}).nearest({1, 1, 1}, 5, index, distance2), 1) << "one point: one found";
    EXPECT_EQ(skin::NearestPoints({}).nearest({1, 1, 1}, 5, index, distance2), 0);
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

namespace {

const std::string kHuman = "/usr/share/assimp/models/Collada/human.zae";

// The human's mesh welded across its seams (as tests/bench/SkinBench.cpp does).
model::Mesh welded(const model::Mesh& mesh)
{
    const skin::Surface surface = skin::makeSurface(mesh);
    model::Mesh out;
    out.name = mesh.name;
    for (const Vec3& p : surface.positions)
        out.positions.emplace_back(p);
    for (const auto& t : surface.triangles)
        out.indices.insert(out.indices.end(), t.begin(), t.end());
    return out;
}

// Each triangle split in four; `weights` (per vertex of `mesh`) carried the
// same way: an edge's midpoint gets the mean of its ends' weights.
model::Mesh subdivide(const model::Mesh& mesh, const model::MeshWeights& weights, model::MeshWeights& outWeights)
{
    model::Mesh out = mesh;
    out.indices.clear();
    std::vector<std::map<std::uint32_t, float>> mixed(mesh.vertexCount());
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
        for (auto* i = weights.begin(v); i != weights.end(v); ++i)
            mixed[v][i->joint] += i->weight;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
        const auto key = std::minmax(a, b);
        auto [it, added] = midpoints.try_emplace({key.first, key.second}, std::uint32_t(out.positions.size()));
        if (added) {
            out.positions.push_back(0.5f * (mesh.positions[a] + mesh.positions[b]));
            std::map<std::uint32_t, float> m;
            for (auto [j, w] : mixed[a])
                m[j] += 0.5f * w;
            for (auto [j, w] : mixed[b])
                m[j] += 0.5f * w;
            mixed.push_back(std::move(m));
        }
        return it->second;
    };
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
        out.indices.insert(out.indices.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    }
    outWeights = model::MeshWeights{weights.joints, weights.parents, {0}, {}};
    for (const auto& m : mixed) {
        for (auto [j, w] : m)
            outWeights.influences.push_back({j, w});
        outWeights.offsets.push_back(std::uint32_t(outWeights.influences.size()));
    }
    return out;
}

} // namespace

TEST(Transfer, ADenserRemeshOfTheHumanKeepsItsDominantJoints)
{
    if (!std::filesystem::exists(kHuman))
        GTEST_SKIP() << kHuman << " is missing (apt-get install assimp-testmodels)";
    const model::GuideDocument guide = test::loadGuide("Skin/human/guide.yml");
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    const auto bones = skin::skinBones(rig).take();
    const model::Model human = io::importModel(kHuman).take();
    std::vector<model::Mesh> source, dense;
    std::vector<model::MeshWeights> sourceWeights, reference;
    std::vector<skin::SkinChunk> chunks;
    for (const model::Mesh& mesh : human.meshes)
        source.push_back(welded(mesh));
    for (const model::Mesh& mesh : source) {
        skin::BindOptions options;
        for (const model::Mesh& other : source)
            if (&other != &mesh)
                options.occluders.push_back(&other);
        sourceWeights.push_back(skin::bindMesh(mesh, bones, options).take());
        skin::ChunkExportOptions exportOptions;
        exportOptions.rig = &rig;
        chunks.push_back(skin::makeSkinChunk({&mesh, &sourceWeights.back(), kHuman, {}}, bones, exportOptions).take());
    }
    for (std::size_t m = 0; m < source.size(); ++m) {
        reference.emplace_back();
        dense.push_back(subdivide(source[m], sourceWeights[m], reference.back()));
        // Off the source surface, as a remesh is: every vertex 2 mm out along its normal.
        const std::vector<glm::vec3> normals = skin::vertexNormals(dense.back());
        for (std::size_t v = 0; v < normals.size(); ++v)
            dense.back().positions[v] += 0.002f * normals[v];
    }
    std::vector<const model::Mesh*> targets;
    for (const model::Mesh& mesh : dense)
        targets.push_back(&mesh);
    for (const skin::TransferMethod method :
         {skin::TransferMethod::ClosestPoint, skin::TransferMethod::ClosestNeighbours, skin::TransferMethod::Inpainting}) {
        skin::TransferOptions options;
        options.method = method;
        std::vector<skin::MeshImportReport> reports;
        auto imported = skin::importChunks(chunks, targets, options, &reports);
        ASSERT_TRUE(imported.ok()) << formatAll(imported.diagnostics());
        std::size_t vertices = 0, same = 0;
        for (std::size_t m = 0; m < dense.size(); ++m) {
            // The eyes' chunk is all on the head: single influence; the body changed topology: fallback.
            EXPECT_EQ(reports[m].route, m == 0 ? skin::ImportRoute::Fallback : skin::ImportRoute::SingleInfluence) << dense[m].name;
            EXPECT_EQ(reports[m].source, dense[m].name);
            const model::MeshWeights& w = (*imported)[m];
            ASSERT_EQ(w.vertexCount(), dense[m].vertexCount());
            for (std::size_t v = 0; v < w.vertexCount(); ++v, ++vertices) {
                ASSERT_GE(w.end(v) - w.begin(v), 1) << "vertex " << v << " is unweighted";
                same += dominant(w, v) == dominant(reference[m], v);
            }
        }
        const double share = double(same) / double(vertices);
        EXPECT_GE(share, 0.98) << skin::transferMethodName(method) << ": " << same << " of " << vertices;
        std::cout << "[ transfer ] " << skin::transferMethodName(method) << ": dominant joint kept at " << same << " of " << vertices
                  << " vertices (" << share * 100.0 << "%)\n";
    }
}
