// The fallback methods of a skin chunk import (skin/Transfer.h, issue 20):
// closest point blends a triangle's vertices and closest neighbours blend by
// distance, the normal filter keeps an overlapping surface's weights off,
// inpainting fills what the closest point would take from the wrong surface
// (and can be cancelled), smoothing steps soften only where weights jump, and
// the nearest points are exact near and far from the cloud.
#include "TestSupport.h"
#include "TransferFixtures.h"

#include "skin/NearestPoints.h"
#include "skin/Surface.h"
#include "skin/Transfer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

using namespace rs;
using namespace rs::test::transfer;

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
