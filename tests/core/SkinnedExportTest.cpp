// Skinned export of a character (issue 19 item 6): the human of Debian's
// assimp-testmodels bound by heat to the guide fitted to it, exported through
// io::runExport in every format and preset, read back with Assimp: both meshes
// with normals, UVs and their materials (the eyes' embedded texture), and
// every vertex's weights within 1e-4 of what was exported. A mesh without
// weights or changed since binding is an error naming it, unless forced.
// Skipped when assimp-testmodels is not installed.
#include "TestSupport.h"

#include "io/CharacterExport.h"
#include "io/ExportRequest.h"
#include "io/ModelImport.h"
#include "rigging/RigBuilder.h"
#include "skin/BindModels.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <tuple>

using namespace rs;

namespace rs::io {
void PrintTo(ExportPreset preset, std::ostream* out); // ExportRoundTripTest.cpp: by name
} // namespace rs::io

namespace {

const std::string kHuman = "/usr/share/assimp/models/Collada/human.zae";

struct BoundHuman {
    model::GuideDocument guide;
    model::Rig rig;
    std::shared_ptr<const model::Model> model;
    io::ExportCharacter character;
};

const BoundHuman& boundHuman()
{
    static const BoundHuman human = [] {
        BoundHuman h;
        h.guide = test::loadGuide("Skin/human/guide.yml");
        h.rig = rigging::buildRig(h.guide, test::builtinTemplates());
        h.model = std::make_shared<const model::Model>(io::importModel(kHuman).take());
        auto bindings = skin::bindModels({{kHuman, h.model}}, skin::skinBones(h.rig).take(), {});
        h.character.bindings = bindings.take();
        h.character.models = {{kHuman, h.model.get()}};
        return h;
    }();
    return human;
}

#define SKIP_WITHOUT_HUMAN()                                                                                           \
    if (!std::filesystem::exists(kHuman))                                                                              \
    GTEST_SKIP() << kHuman << " is not installed (assimp-testmodels)"

TEST(SkinnedExport, EveryMeshOfTheBoundHumanCarriesItsWeightsNormalsUvsAndMaterial)
{
    SKIP_WITHOUT_HUMAN();
    const BoundHuman& h = boundHuman();
    const io::CharacterExport bound = io::characterExport(h.rig, h.character.bindings, h.character.models);
    EXPECT_FALSE(hasErrors(bound.problems)) << formatAll(bound.problems);
    ASSERT_EQ(bound.meshes.size(), 2u);
    ASSERT_EQ(bound.materials.size(), 2u);
    for (const io::SkinnedMesh& mesh : bound.meshes) {
        EXPECT_EQ(mesh.normals.size(), mesh.vertexCount());
        EXPECT_EQ(mesh.uvs.size(), mesh.vertexCount());
        ASSERT_GE(mesh.material, 0);
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
            ASSERT_GE(mesh.influenceCount(v), 1u) << mesh.name << " vertex " << v;
            ASSERT_LE(mesh.influenceCount(v), std::size_t(io::kMaxInfluences));
        }
    }
    const io::ExportMaterial& eye = bound.materials[std::size_t(bound.meshes[1].material)];
    EXPECT_EQ(eye.name, "Eye_brown");
    EXPECT_EQ(eye.imageName, "brown_eye.png");
    EXPECT_EQ(eye.mimeType, "image/png");
    EXPECT_TRUE(eye.imagePath.empty()) << "the image is inside the .zae";
    EXPECT_EQ(eye.image.size(), 610817u);
}

TEST(SkinnedExport, AMeshWithoutWeightsIsAnErrorNamingItUnlessForced)
{
    SKIP_WITHOUT_HUMAN();
    const BoundHuman& h = boundHuman();
    io::ExportCharacter character = h.character;
    character.bindings.pop_back(); // the eyes' weights
    io::ExportRequest request;
    request.path = test::temporaryPath("unbound-eyes.glb");
    std::filesystem::remove(request.path);
    const Diagnostics refused = io::runExport(h.guide, h.rig, {}, request, {}, &character);
    ASSERT_TRUE(hasErrors(refused));
    EXPECT_NE(formatAll(refused).find("mesh 'human-highpolyeyesMesh' of human.zae: it has no skin weights"), std::string::npos)
        << formatAll(refused);
    EXPECT_FALSE(std::filesystem::exists(request.path));

    request.force = true;
    const Diagnostics forced = io::runExport(h.guide, h.rig, {}, request, {}, &character);
    EXPECT_FALSE(hasErrors(forced)) << formatAll(forced);
    EXPECT_NE(formatAll(forced).find("exported anyway (forced)"), std::string::npos);
    EXPECT_TRUE(std::filesystem::exists(request.path));
    const io::CharacterExport bound = io::characterExport(h.rig, character.bindings, character.models);
    const io::SkinnedMesh& eyes = bound.meshes[1];
    for (std::size_t v = 0; v < eyes.vertexCount(); ++v) {
        ASSERT_EQ(eyes.influenceCount(v), 1u);
        ASSERT_EQ(eyes.influencesOf(v)[0].joint, 0) << "rigid on the root joint";
    }
}

TEST(SkinnedExport, AMeshChangedSinceBindingIsAnErrorAndAnOrphanRecordAWarning)
{
    SKIP_WITHOUT_HUMAN();
    const BoundHuman& h = boundHuman();
    io::ExportCharacter character = h.character;
    character.bindings[0].fingerprint ^= 1; // other triangles
    model::MeshBinding orphan = character.bindings[1];
    orphan.mesh = "cape";
    character.bindings.push_back(orphan);
    const io::CharacterExport bound = io::characterExport(h.rig, character.bindings, character.models);
    const std::string text = formatAll(bound.problems);
    EXPECT_NE(text.find("error: mesh 'human-baseMesh' of human.zae: it changed since it was bound"), std::string::npos) << text;
    EXPECT_NE(text.find("warning: mesh 'cape' of human.zae: its weights match no mesh"), std::string::npos) << text;
}

// Every vertex read back has, at some exported vertex at its place, the same
// weights by joint name (within 1e-4).
double worstWeightError(const aiMesh& mesh, const io::SkinnedMesh& reference, const std::vector<io::ExportJoint>& joints,
                        double tolerance)
{
    std::map<std::tuple<long, long, long>, std::vector<std::size_t>> cells;
    auto key = [&](const glm::vec3& p) {
        return std::tuple<long, long, long>{std::lround(p.x / (100 * tolerance)), std::lround(p.y / (100 * tolerance)),
                                            std::lround(p.z / (100 * tolerance))};
    };
    for (std::size_t v = 0; v < reference.vertexCount(); ++v)
        cells[key(reference.positions[v])].push_back(v);
    std::vector<std::map<std::string, float>> weights(mesh.mNumVertices);
    for (unsigned b = 0; b < mesh.mNumBones; ++b)
        for (unsigned w = 0; w < mesh.mBones[b]->mNumWeights; ++w)
            weights[mesh.mBones[b]->mWeights[w].mVertexId][mesh.mBones[b]->mName.C_Str()] += mesh.mBones[b]->mWeights[w].mWeight;
    double worst = 0.0;
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        const glm::vec3 p(mesh.mVertices[v].x, mesh.mVertices[v].y, mesh.mVertices[v].z);
        double best = 1.0;
        const auto [x, y, z] = key(p);
        for (long dx = -1; dx <= 1; ++dx)
            for (long dy = -1; dy <= 1; ++dy)
                for (long dz = -1; dz <= 1; ++dz) {
                    auto it = cells.find({x + dx, y + dy, z + dz});
                    for (std::size_t c : it == cells.end() ? std::vector<std::size_t>{} : it->second) {
                        if (glm::length(reference.positions[c] - p) > tolerance)
                            continue;
                        std::map<std::string, float> want;
                        for (std::size_t k = 0; k < reference.influenceCount(c); ++k)
                            want[joints[std::size_t(reference.influencesOf(c)[k].joint)].name] += reference.influencesOf(c)[k].weight;
                        double error = 0.0;
                        for (const auto& [name, w] : want)
                            error = std::max(error, std::abs(double(w) - double(weights[v].count(name) ? weights[v].at(name) : 0.f)));
                        for (const auto& [name, w] : weights[v])
                            error = std::max(error, want.count(name) ? 0.0 : double(w));
                        best = std::min(best, error);
                    }
                }
        worst = std::max(worst, best);
    }
    return worst;
}

using Case = std::tuple<std::string, io::ExportPreset>; // extension, preset

class SkinnedExportRoundTrip : public testing::TestWithParam<Case> {};

TEST_P(SkinnedExportRoundTrip, AssimpReadsBothMeshesWithTheirWeightsUvsAndMaterials)
{
    SKIP_WITHOUT_HUMAN();
    const auto& [extension, preset] = GetParam();
    const BoundHuman& h = boundHuman();
    io::ExportRequest request;
    request.path = test::temporaryPath(std::string("human-") + io::presetName(preset) + extension);
    request.preset = preset;
    const Diagnostics report = io::runExport(h.guide, h.rig, {}, request, {}, &h.character);
    ASSERT_FALSE(hasErrors(report)) << formatAll(report);

    // What was exported, in the file's convention.
    const io::CharacterExport bound = io::characterExport(h.rig, h.character.bindings, h.character.models);
    io::ExportOptions options;
    options.preset = preset;
    options.guide = &h.guide;
    options.meshes = &bound.meshes;
    options.materials = &bound.materials;
    auto prepared = io::prepareExport(h.rig, options);
    ASSERT_TRUE(prepared.scene);
    const bool fbx = extension == ".fbx";
    const io::Convention convention = io::conventionFor(preset, fbx);
    const io::ExportScene expected = io::converted(std::move(*prepared.scene), convention);

    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(request.path, 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    ASSERT_EQ(scene->mNumMeshes, 2u);
    for (unsigned m = 0; m < 2; ++m) {
        const aiMesh& mesh = *scene->mMeshes[m];
        const io::SkinnedMesh& reference = expected.meshes[m];
        EXPECT_EQ(std::string(mesh.mName.C_Str()), reference.name);
        ASSERT_TRUE(mesh.mNormals) << reference.name;
        ASSERT_TRUE(mesh.mTextureCoords[0]) << reference.name;
        // UVs come back in the imported (OpenGL) convention: glTF's flip undone by Assimp.
        std::multimap<std::tuple<float, float, float>, glm::vec2> uvsAt; // a seam has several at one place
        for (std::size_t v = 0; v < reference.vertexCount(); ++v)
            uvsAt.emplace(std::tuple{reference.positions[v].x, reference.positions[v].y, reference.positions[v].z}, reference.uvs[v]);
        for (unsigned v = 0; v < mesh.mNumVertices; v += 97) {
            const aiVector3D& p = mesh.mVertices[v];
            const glm::vec2 uv(mesh.mTextureCoords[0][v].x, mesh.mTextureCoords[0][v].y);
            const auto [first, last] = uvsAt.equal_range({p.x, p.y, p.z});
            ASSERT_NE(first, last) << reference.name << " vertex " << v << " is not where an exported vertex is";
            double nearest = 1.0;
            for (auto it = first; it != last; ++it)
                nearest = std::min(nearest, double(glm::length(it->second - uv)));
            ASSERT_LT(nearest, 1e-6) << reference.name << " vertex " << v << ": its UV";
        }
        EXPECT_LT(worstWeightError(mesh, reference, expected.joints, 1e-5 * convention.unitsPerMetre), 1e-4) << reference.name;
    }
    const aiMaterial& eye = *scene->mMaterials[scene->mMeshes[1]->mMaterialIndex];
    aiString name, texture;
    eye.Get(AI_MATKEY_NAME, name);
    EXPECT_EQ(std::string(name.C_Str()), "Eye_brown");
    ASSERT_EQ(eye.GetTexture(aiTextureType_DIFFUSE, 0, &texture), AI_SUCCESS);
    const aiTexture* image = scene->GetEmbeddedTexture(texture.C_Str());
    ASSERT_NE(image, nullptr) << "the eyes' texture is embedded: " << texture.C_Str();
    EXPECT_EQ(image->mWidth, 610817u);
}

std::vector<Case> allCases()
{
    std::vector<Case> out;
    for (const char* extension : {".glb", ".gltf", ".fbx"})
        for (auto preset : {io::ExportPreset::Gltf, io::ExportPreset::Unreal, io::ExportPreset::Unity})
            out.emplace_back(extension, preset);
    return out;
}

std::string caseName(const testing::TestParamInfo<Case>& info)
{
    const auto& [extension, preset] = info.param;
    return extension.substr(1) + "_" + io::presetName(preset);
}

INSTANTIATE_TEST_SUITE_P(BoundHuman, SkinnedExportRoundTrip, testing::ValuesIn(allCases()), caseName);

} // namespace
