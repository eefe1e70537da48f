// A skinned model file's per-vertex weights (io/ModelImport.h,
// model::FileWeights): the skinned character of assimp-testmodels, and our
// own skinned exports read back (glTF as written, FBX in centimetres Z-up).
#include "TestSupport.h"

#include "io/ModelImport.h"
#include "io/RigExport.h"
#include "model/Skeleton.h"
#include "rigging/RigBuilder.h"
#include "skin/ModelChunks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>

using namespace rs;

namespace {

const std::string kModels = "/usr/share/assimp/models";

// Every vertex's shares sum to 1 and name a bone of the mesh; returns the
// number of vertices with no share.
std::size_t expectNormalised(const model::Model& model, const model::Mesh& mesh)
{
    const model::FileWeights& w = *mesh.fileWeights;
    EXPECT_EQ(w.vertexCount(), mesh.vertexCount()) << mesh.name;
    std::size_t unweighted = 0;
    for (std::size_t v = 0; v < w.vertexCount(); ++v) {
        double sum = 0.0;
        for (const model::Influence* i = w.begin(v); i != w.end(v); ++i) {
            EXPECT_LT(i->joint, model.joints.size());
            sum += i->weight;
        }
        if (w.begin(v) == w.end(v))
            ++unweighted;
        else
            EXPECT_NEAR(sum, 1.0, 1e-5) << mesh.name << " vertex " << v;
    }
    return unweighted;
}

const model::Rig& biped()
{
    static const model::Rig rig = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    return rig;
}

// The proxy mesh of the biped exported to `path`, read back: positions and
// weights (by joint name) match what was written, to float precision.
void expectRoundTrip(const std::string& path, io::ExportPreset preset)
{
    const auto skeleton = model::extractSkeleton(biped());
    const std::vector<io::SkinnedMesh> meshes{io::proxyMesh(*skeleton, 2000)};
    io::ExportOptions options;
    options.preset = preset;
    options.meshes = &meshes;
    ASSERT_TRUE(io::exportRig(biped(), path, options).empty());
    // What was written, joints named as the preset names them (Unreal: the root is `root`).
    const io::PreparedExport prepared = io::prepareExport(biped(), options);
    ASSERT_TRUE(prepared.scene);
    const io::ExportScene& scene = *prepared.scene;
    auto read = io::importModel(path);
    ASSERT_TRUE(read.ok()) << formatAll(read.diagnostics());
    ASSERT_EQ(read->meshes.size(), 1u);
    const model::Mesh& mesh = read->meshes[0];
    const io::SkinnedMesh& written = scene.meshes.at(0);
    ASSERT_TRUE(mesh.fileWeights);
    // Assimp's glTF reader gives each triangle corner its own vertex: pair them by corner.
    ASSERT_EQ(mesh.triangleCount(), written.indices.size() / 3);
    EXPECT_EQ(expectNormalised(*read, mesh), 0u);
    for (std::size_t corner = 0; corner < mesh.indices.size(); ++corner) {
        const std::size_t v = mesh.indices[corner], w = written.indices[corner];
        ASSERT_LT(glm::distance(mesh.positions[v], written.positions[w]), 1e-4f) << path << " corner " << corner;
        std::map<std::string, float> expected, got;
        for (std::size_t k = 0; k < written.influenceCount(w); ++k)
            expected[scene.joints[std::size_t(written.influencesOf(w)[k].joint)].name] += written.influencesOf(w)[k].weight;
        for (const model::Influence* i = mesh.fileWeights->begin(v); i != mesh.fileWeights->end(v); ++i)
            got[read->joints[i->joint].name] += i->weight;
        ASSERT_EQ(got.size(), expected.size()) << path << " corner " << corner;
        for (const auto& [name, weight] : expected)
            ASSERT_NEAR(got[name], weight, 1e-5f) << path << " corner " << corner << " joint " << name;
    }
    // Bind matrices from the offsets, in metres Y-up like the positions.
    std::size_t compared = 0;
    for (const model::FileWeights::Bone& bone : mesh.fileWeights->bones) {
        const auto& joint = read->joints[bone.joint];
        for (const io::ExportJoint& s : scene.joints) {
            if (s.name == joint.name) {
                ++compared;
                EXPECT_LT(glm::distance(Vec3(bone.bindWorld[3]), Vec3(s.bindWorld[3])), 1e-4) << path << " " << s.name;
            }
        }
    }
    EXPECT_GE(compared, 10u) << path;
}

} // namespace

TEST(ModelImport, TheSkinnedCharacterBringsItsWeightsOnItsSkeleton)
{
    auto man = io::importModel(kModels + "/X/BCN_Epileptic.X");
    ASSERT_TRUE(man.ok()) << formatAll(man.diagnostics()) << " (run.sh installs assimp-testmodels)";
    ASSERT_EQ(man->meshes.size(), 3u);
    for (const model::Mesh& mesh : man->meshes) {
        ASSERT_TRUE(mesh.fileWeights) << mesh.name;
        EXPECT_EQ(expectNormalised(*man, mesh), 0u) << mesh.name;
        EXPECT_GE(mesh.fileWeights->bones.size(), 10u) << mesh.name;
    }
    EXPECT_GE(man->joints.size(), 24u);
    for (std::size_t j = 0; j < man->joints.size(); ++j)
        EXPECT_LT(man->joints[j].parent, int(j)) << "parents first";
    // A file whose shares do not sum to 1 (Blender's FBX: 0.97) arrives normalised.
    auto bones = io::importModel(kModels + "/FBX/huesitos.fbx");
    ASSERT_TRUE(bones.ok()) << formatAll(bones.diagnostics());
    ASSERT_TRUE(bones->meshes.at(0).fileWeights);
    EXPECT_EQ(expectNormalised(*bones, bones->meshes[0]), 0u);
    EXPECT_EQ(bones->meshes[0].fileWeights->bones.size(), 9u) << "a bone without weights is still one of the mesh's";
}

TEST(ModelImport, AMeshWithoutBonesHasNoFileWeights)
{
    auto box = io::importModel(kModels + "/OBJ/box.obj");
    ASSERT_TRUE(box.ok()) << formatAll(box.diagnostics());
    for (const model::Mesh& mesh : box->meshes)
        EXPECT_FALSE(mesh.fileWeights) << mesh.name;
    EXPECT_TRUE(box->joints.empty());
}

TEST(ModelImport, OurSkinnedExportsReadBackWithTheWeightsWritten)
{
    const std::string glb = test::temporaryPath("weights-roundtrip.glb");
    expectRoundTrip(glb, io::ExportPreset::Gltf);
    const std::string fbx = test::temporaryPath("weights-roundtrip.fbx");
    expectRoundTrip(fbx, io::ExportPreset::Unreal); // centimetres, Z-up: back in metres, Y-up
}

TEST(ModelChunks, EachSkinnedMeshBecomesAChunkOnTheFilesSkeletonByName)
{
    auto man = io::importModel(kModels + "/X/BCN_Epileptic.X");
    ASSERT_TRUE(man.ok()) << formatAll(man.diagnostics());
    auto chunks = skin::chunksFromModel(*man, {});
    ASSERT_TRUE(chunks.ok()) << formatAll(chunks.diagnostics());
    ASSERT_EQ(chunks->size(), 3u);
    for (std::size_t m = 0; m < chunks->size(); ++m) {
        const skin::SkinChunk& c = (*chunks)[m];
        const model::Mesh& mesh = man->meshes[m];
        EXPECT_EQ(c.mesh, mesh.name);
        ASSERT_EQ(c.weights.joints.size(), man->joints.size()) << "every joint of the file, for the hierarchy";
        for (std::size_t j = 0; j < man->joints.size(); ++j) {
            EXPECT_EQ(c.weights.joints[j], skin::fileJointKey(man->joints[j].name));
            EXPECT_EQ(c.joints[j].name, man->joints[j].name);
            EXPECT_EQ(c.weights.parents[j], man->joints[j].parent);
        }
        EXPECT_EQ(c.weights.offsets, mesh.fileWeights->offsets);
        EXPECT_EQ(c.weights.influences, mesh.fileWeights->influences);
        for (const model::FileWeights::Bone& bone : mesh.fileWeights->bones)
            EXPECT_EQ(c.joints[bone.joint].bind, bone.bindWorld) << "the mesh's own bind matrix";
    }
    auto box = io::importModel(kModels + "/OBJ/box.obj");
    ASSERT_TRUE(box.ok());
    auto none = skin::chunksFromModel(*box, {});
    ASSERT_FALSE(none.ok());
    EXPECT_NE(formatAll(none.diagnostics()).find("box.obj: error: no mesh in the file is skinned"), std::string::npos)
        << formatAll(none.diagnostics());
}
