// Where an import writes (skin/ImportScope.h) and which pose it reads
// (issue 20 item 4): a selection or --append keeps the other vertices'
// weights; a chunk exported posed, imported with its pre-deformed points onto
// the same mesh, gives the weights a bind-pose export gives.
#include "TestSupport.h"

#include "skin/ImportScope.h"
#include "skin/Refit.h"
#include "skin/Transfer.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

// A wavy sheet of n by n vertices, 2 cm apart.
model::Mesh sheet(const std::string& name, int n)
{
    model::Mesh mesh;
    mesh.name = name;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            mesh.positions.push_back({x * 0.02f, y * 0.02f, 0.01f * std::sin(float(x + 2 * y))});
    for (int y = 0; y + 1 < n; ++y)
        for (int x = 0; x + 1 < n; ++x) {
            const std::uint32_t a = std::uint32_t(y * n + x), b = a + 1, c = a + std::uint32_t(n), d = c + 1;
            mesh.indices.insert(mesh.indices.end(), {a, b, c, b, d, c});
        }
    return mesh;
}

// Two joints, the first fading into the second along x.
model::MeshWeights ramp(const model::Mesh& mesh)
{
    model::MeshWeights w;
    w.joints = {{1, "", "skin.a"}, {1, "", "skin.b"}};
    w.parents = {-1, 0};
    w.offsets.push_back(0);
    for (const glm::vec3& p : mesh.positions) {
        const float t = std::clamp(p.x / 0.3f, 0.0f, 1.0f);
        w.influences.insert(w.influences.end(), {{0, 1.0f - t}, {1, t}});
        w.offsets.push_back(std::uint32_t(w.influences.size()));
    }
    return w;
}

// The whole mesh's bind-pose chunk, its influences named by tag (no rig).
skin::SkinChunk bindChunk(const model::Mesh& mesh, const model::MeshWeights& weights)
{
    return skin::bindingChunk({"", mesh.name, mesh.vertexCount(), model::topologyFingerprint(mesh), weights}, mesh, nullptr);
}

} // namespace

TEST(ImportScope, APosedChunkImportedWithPreDeformedPointsGivesTheBindPoseResult)
{
    const model::Mesh mesh = sheet("sheet", 16);
    const skin::SkinChunk bind = bindChunk(mesh, ramp(mesh));
    // The same chunk exported posed: its points bent up and moved 10 cm; bind points kept.
    skin::SkinChunk posed = bind;
    posed.inBindPose = false;
    posed.bindPositions = bind.positions;
    posed.bindNormals = bind.normals;
    for (glm::vec3& p : posed.positions)
        p = glm::vec3(p.x, p.y + 0.1f, p.z + 0.5f * p.x * p.x);
    skin::TransferOptions options;
    options.forceUberChunk = true; // not 1:1: the points are read
    auto fromBind = skin::importChunks({bind}, {&mesh}, options);
    auto fromPosed = skin::importChunks({posed}, {&mesh}, options);
    ASSERT_TRUE(fromBind.ok() && fromPosed.ok()) << formatAll(fromPosed.diagnostics());
    EXPECT_EQ(fromPosed->front(), fromBind->front());
    options.usePreDeformed = false; // the pose at export does not fit the bind-pose mesh
    auto fromExportPose = skin::importChunks({posed}, {&mesh}, options);
    ASSERT_TRUE(fromExportPose.ok());
    EXPECT_NE(fromExportPose->front(), fromBind->front());
}

TEST(ImportScope, ASelectionOrAppendWritesOnlyTheVerticesItCovers)
{
    const model::Mesh mesh = sheet("sheet", 10);
    skin::SkinChunk subset = bindChunk(mesh, ramp(mesh));
    subset.vertexIds = {0, 1, 2, 3};
    skin::MeshImportReport oneToOne;
    oneToOne.route = skin::ImportRoute::OneToOne;
    oneToOne.source = "sheet";
    const std::vector<std::uint32_t> selection = {2, 3, 50};
    auto count = [](const std::vector<bool>& w) { return std::count(w.begin(), w.end(), true); };
    EXPECT_EQ(count(skin::writtenVertices({subset}, oneToOne, 100, {})), 100) << "unbind first: every vertex";
    EXPECT_EQ(count(skin::writtenVertices({subset}, oneToOne, 100, {nullptr, true})), 4) << "append: the chunk's vertices";
    EXPECT_EQ(count(skin::writtenVertices({subset}, oneToOne, 100, {&selection, false})), 3) << "a selection";
    EXPECT_EQ(count(skin::writtenVertices({subset}, oneToOne, 100, {&selection, true})), 2) << "both";
    skin::MeshImportReport transferred;
    EXPECT_EQ(count(skin::writtenVertices({subset}, transferred, 100, {nullptr, true})), 100) << "a transfer covers every vertex";
}

TEST(ImportScope, UnwrittenVerticesKeepTheirWeights)
{
    const model::Mesh mesh = sheet("sheet", 4);
    const model::MeshWeights imported = ramp(mesh);
    model::MeshWeights existing = imported;
    for (model::Influence& i : existing.influences)
        i.weight = i.joint == 0 ? 1.0f : 0.0f;
    std::vector<bool> write(mesh.vertexCount(), false);
    write[5] = true;
    const auto merged = skin::keepUnwritten(existing, imported, write);
    ASSERT_TRUE(merged.has_value());
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const model::MeshWeights& expected = v == 5 ? imported : existing;
        EXPECT_EQ(std::vector<model::Influence>(merged->begin(v), merged->end(v)),
                  std::vector<model::Influence>(expected.begin(v), expected.end(v)));
    }
    model::MeshWeights otherJoints = existing;
    otherJoints.joints[1].tag = "skin.c";
    EXPECT_FALSE(skin::keepUnwritten(otherJoints, imported, write).has_value());
}
