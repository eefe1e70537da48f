// Skin chunk imports on garments and a character (skin/Transfer.h, issue
// 20): parachute pants over skinny jeans stretch less with the normal filter
// and least with inpainting; a denser remesh of the assimp human keeps its
// vertices' dominant joints with every method.
#include "JeansFixture.h"
#include "TestSupport.h"
#include "TransferFixtures.h"

#include "io/ModelImport.h"
#include "rigging/RigBuilder.h"
#include "skin/AutoWeights.h"
#include "skin/Surface.h"
#include "skin/Transfer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>

using namespace rs;
using test::transfer::dominant;

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
