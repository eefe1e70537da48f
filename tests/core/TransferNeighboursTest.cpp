// Closest neighbours (skin/Transfer.h, issue 20), as the Skinner seed defines
// it: the nearest source vertex at distance d; up to `neighbourCount` source
// vertices within d * `neighbourDistanceMultiplier`; their weights blended,
// closer ones counting more (by inverse distance). A target vertex at the
// origin and four source vertices at 1, 1.5, 2.5 and 4 cm, each all on its own
// joint, so the blended weights say exactly which were taken and how much.
#include "TestSupport.h"

#include "skin/Refit.h"
#include "skin/Transfer.h"

#include <gtest/gtest.h>

#include <map>

using namespace rs;

namespace {

constexpr float kDistances[] = {0.01f, 0.015f, 0.025f, 0.04f};

// Four vertices around the origin (no triangles: a point cloud), vertex i all on joint i.
skin::SkinChunk cloud()
{
    model::Mesh mesh;
    mesh.name = "probe";
    mesh.positions = {{kDistances[0], 0, 0}, {-kDistances[1], 0, 0}, {0, kDistances[2], 0}, {0, -kDistances[3], 0}};
    model::MeshWeights w;
    w.joints = {{1, "", "skin.a"}, {1, "", "skin.b"}, {1, "", "skin.c"}, {1, "", "skin.d"}};
    w.parents = {-1, 0, 1, 2};
    for (std::uint32_t v = 0; v <= 4; ++v)
        w.offsets.push_back(v);
    for (std::uint32_t v = 0; v < 4; ++v)
        w.influences.push_back({v, 1.0f});
    return skin::bindingChunk({"", mesh.name, mesh.vertexCount(), model::topologyFingerprint(mesh), w}, mesh, nullptr);
}

// The weights the origin gets, per joint.
std::map<std::uint32_t, float> blend(double multiplier, int count)
{
    model::Mesh target;
    target.name = "probe";
    target.positions = {{0, 0, 0}};
    skin::TransferOptions o;
    o.method = skin::TransferMethod::ClosestNeighbours;
    o.neighbourDistanceMultiplier = multiplier;
    o.neighbourCount = count;
    o.maxInfluences = 4; // the default keeps as many as a source vertex has: one
    std::vector<skin::MeshImportReport> reports;
    auto weights = skin::importChunks({cloud()}, {&target}, o, &reports);
    EXPECT_TRUE(weights.ok()) << formatAll(weights.diagnostics());
    std::map<std::uint32_t, float> out;
    if (!weights.ok())
        return out;
    EXPECT_EQ(reports.at(0).closestNeighbours, 1u);
    for (const model::Influence* i = weights->front().begin(0); i != weights->front().end(0); ++i)
        if (i->weight > 0.0f)
            out[i->joint] = i->weight;
    return out;
}

// Inverse-distance weights of the first n source vertices, normalised.
std::map<std::uint32_t, float> expected(int n)
{
    float sum = 0.0f;
    for (int i = 0; i < n; ++i)
        sum += 1.0f / kDistances[i];
    std::map<std::uint32_t, float> out;
    for (int i = 0; i < n; ++i)
        out[std::uint32_t(i)] = (1.0f / kDistances[i]) / sum;
    return out;
}

void expectNear(const std::map<std::uint32_t, float>& got, const std::map<std::uint32_t, float>& want)
{
    ASSERT_EQ(got.size(), want.size());
    for (const auto& [joint, weight] : want) {
        ASSERT_TRUE(got.count(joint)) << "joint " << joint;
        EXPECT_NEAR(got.at(joint), weight, 1e-5) << "joint " << joint;
    }
}

} // namespace

TEST(Transfer, TheDistanceMultiplierWidensTheSphereTheNeighboursAreTakenFrom)
{
    // The defaults: a 2 cm sphere (1 cm * 2) holds the 1 and 1.5 cm vertices: 0.6 / 0.4.
    expectNear(blend(2.0, 3), expected(2));
    EXPECT_NEAR(blend(2.0, 3).at(0), 0.6f, 1e-5);
    // 1: only the nearest (its sphere holds nothing else).
    expectNear(blend(1.0, 3), expected(1));
    // 3: a 3 cm sphere takes the 2.5 cm vertex too, and it weighs least.
    const auto wide = blend(3.0, 3);
    expectNear(wide, expected(3));
    EXPECT_GT(wide.at(0), wide.at(1));
    EXPECT_GT(wide.at(1), wide.at(2));
    // 5: the 4 cm vertex is inside, but three neighbours are asked for.
    expectNear(blend(5.0, 3), expected(3));
}

TEST(Transfer, TheNeighbourCountCapsHowManyVerticesInTheSphereBlend)
{
    expectNear(blend(5.0, 1), expected(1));
    expectNear(blend(5.0, 2), expected(2));
    expectNear(blend(5.0, 4), expected(4));
    expectNear(blend(5.0, 32), expected(4)); // no more than the cloud has
}
