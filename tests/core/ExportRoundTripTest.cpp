// Every sample in every format and preset, re-imported with Assimp (the third
// consumer of issue 6, next to the Khronos validator and Blender in
// tests/tools/check-export.sh): joint names, parents and bind positions, the
// bind matrices against the node tree, and every vertex's weights.
#include "rigging/RigBuilder.h"
#include "core/TestSupport.h"
#include "io/RigExport.h"
#include "model/Skeleton.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>

using namespace rs;

namespace rs::io {
// Test names and failure messages show the preset by name.
void PrintTo(ExportPreset preset, std::ostream* out) { *out << presetName(preset); }
} // namespace rs::io

namespace {

Mat4 toGlm(const aiMatrix4x4& m)
{
    Mat4 out;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            out[c][r] = m[r][c];
    return out;
}

Mat4 worldOf(const aiNode* node)
{
    Mat4 world(1.0);
    for (; node; node = node->mParent)
        world = toGlm(node->mTransformation) * world;
    return world;
}

// Reference vertices by position (grid cells of `cell`), to find a vertex whatever order the importer keeps.
class VertexIndex {
public:
    VertexIndex(const io::SkinnedMesh& mesh, double cell) : m_mesh(mesh), m_cell(cell)
    {
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
            m_cells[key(mesh.positions[v])].push_back(v);
    }
    std::vector<std::size_t> near(const glm::vec3& p, double tolerance) const
    {
        std::vector<std::size_t> out;
        const auto [x, y, z] = key(p);
        for (long dx = -1; dx <= 1; ++dx)
            for (long dy = -1; dy <= 1; ++dy)
                for (long dz = -1; dz <= 1; ++dz)
                    if (auto it = m_cells.find({x + dx, y + dy, z + dz}); it != m_cells.end())
                        for (std::size_t v : it->second)
                            if (glm::length(m_mesh.positions[v] - p) <= tolerance)
                                out.push_back(v);
        return out;
    }

private:
    using Key = std::tuple<long, long, long>;
    Key key(const glm::vec3& p) const
    {
        return {std::lround(p.x / m_cell), std::lround(p.y / m_cell), std::lround(p.z / m_cell)};
    }
    const io::SkinnedMesh& m_mesh;
    double m_cell;
    std::map<Key, std::vector<std::size_t>> m_cells;
};

using Case = std::tuple<std::string, std::string, io::ExportPreset>; // sample, extension, preset

class ExportRoundTrip : public testing::TestWithParam<Case> {};

void expectWeightsMatch(const aiScene& scene, const io::ExportScene& expected, double tolerance)
{
    ASSERT_EQ(scene.mNumMeshes, 1u);
    const aiMesh& mesh = *scene.mMeshes[0];
    const io::SkinnedMesh& reference = expected.meshes[0];
    std::vector<std::map<std::string, float>> weights(mesh.mNumVertices);
    for (unsigned b = 0; b < mesh.mNumBones; ++b)
        for (unsigned w = 0; w < mesh.mBones[b]->mNumWeights; ++w)
            weights[mesh.mBones[b]->mWeights[w].mVertexId][mesh.mBones[b]->mName.C_Str()] += mesh.mBones[b]->mWeights[w].mWeight;
    const VertexIndex index(reference, 100 * tolerance);
    double worst = 0.0;
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        const glm::vec3 p(mesh.mVertices[v].x, mesh.mVertices[v].y, mesh.mVertices[v].z);
        const auto candidates = index.near(p, tolerance);
        ASSERT_FALSE(candidates.empty()) << "vertex " << v << " is not where any exported vertex is";
        double best = 1.0;
        for (std::size_t c : candidates) {
            std::map<std::string, float> want;
            for (std::size_t k = 0; k < reference.influenceCount(c); ++k)
                want[expected.joints[std::size_t(reference.influencesOf(c)[k].joint)].name] += reference.influencesOf(c)[k].weight;
            double error = 0.0;
            for (const auto& [name, w] : want)
                error = std::max(error, std::abs(double(w) - double(weights[v].count(name) ? weights[v].at(name) : 0.f)));
            for (const auto& [name, w] : weights[v])
                error = std::max(error, want.count(name) ? 0.0 : double(w));
            best = std::min(best, error);
        }
        worst = std::max(worst, best);
    }
    EXPECT_LT(worst, 1e-4);
}

TEST_P(ExportRoundTrip, AssimpReadsTheSameSkeletonAndWeights)
{
    const auto& [sample, extension, preset] = GetParam();
    const model::GuideDocument guide = test::loadSample(sample);
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    const std::vector<io::SkinnedMesh> meshes{io::proxyMesh(*model::extractSkeleton(rig), 3000)};
    io::ExportOptions options;
    options.preset = preset;
    options.guide = &guide;
    options.meshes = &meshes;
    // The humanoid map finds no arms on the quadruped and the prop: refused unless forced (RangeOfMotionTest).
    options.force = preset == io::ExportPreset::Unity && sample != "biped";
    const std::string path = test::temporaryPath(sample + "-" + io::presetName(preset) + extension);
    const Diagnostics report = io::exportRig(rig, path, options);
    ASSERT_FALSE(hasErrors(report)) << formatAll(report);
    EXPECT_EQ(formatAll(report).find("forced") != std::string::npos, options.force) << formatAll(report);

    const bool fbx = extension == ".fbx";
    const io::Convention convention = io::conventionFor(preset, fbx);
    auto prepared = io::prepareExport(rig, options);
    ASSERT_TRUE(prepared.scene);
    const io::ExportScene expected = io::converted(std::move(*prepared.scene), convention);

    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    const double tolerance = 1e-4 * convention.unitsPerMetre;
    for (const auto& joint : expected.joints) {
        const aiNode* node = scene->mRootNode->FindNode(joint.name.c_str());
        ASSERT_NE(node, nullptr) << joint.name;
        if (joint.parent >= 0) {
            EXPECT_EQ(node->mParent->mName.C_Str(), expected.joints[std::size_t(joint.parent)].name);
        }
        EXPECT_LT(glm::length(translationOf(worldOf(node)) - translationOf(joint.bindWorld)), tolerance) << joint.name;
    }
    // Bind matrices: world(bone node) * offset = world(mesh node) for every bone.
    const aiMesh& mesh = *scene->mMeshes[0];
    const aiNode* meshNode = scene->mRootNode->FindNode(meshes[0].name.c_str());
    ASSERT_NE(meshNode, nullptr);
    for (unsigned b = 0; b < mesh.mNumBones; ++b) {
        const aiNode* bone = scene->mRootNode->FindNode(mesh.mBones[b]->mName);
        ASSERT_NE(bone, nullptr);
        const Mat4 product = worldOf(bone) * toGlm(mesh.mBones[b]->mOffsetMatrix);
        EXPECT_LT(maxAbsDifference(product, worldOf(meshNode)), 1e-4) << mesh.mBones[b]->mName.C_Str();
    }
    expectWeightsMatch(*scene, expected, tolerance);
}

std::vector<Case> allCases()
{
    std::vector<Case> out;
    for (const char* sample : {"biped", "quadruped", "prop", "vehicle", "robot", "claw", "cart", "strider"})
        for (const char* extension : {".glb", ".gltf", ".fbx"})
            for (auto preset : {io::ExportPreset::Gltf, io::ExportPreset::Unreal, io::ExportPreset::Unity})
                out.emplace_back(sample, extension, preset);
    return out;
}

std::string caseName(const testing::TestParamInfo<Case>& info)
{
    const auto& [sample, extension, preset] = info.param;
    return sample + "_" + extension.substr(1) + "_" + io::presetName(preset);
}

INSTANTIATE_TEST_SUITE_P(Samples, ExportRoundTrip, testing::ValuesIn(allCases()), caseName);

} // namespace
