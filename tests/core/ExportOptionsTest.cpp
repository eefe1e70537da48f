// Issue 6's export options, presets and mesh validation.
#include "rigging/RigBuilder.h"
#include "core/TestSupport.h"
#include "io/FbxExport.h"
#include "io/RigExport.h"
#include "model/Skeleton.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <glm/gtc/type_ptr.hpp>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <filesystem>
#include <set>

using namespace rs;

namespace {

const model::Rig& biped()
{
    static const model::Rig rig = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    return rig;
}

tinygltf::Model readGlb(const std::string& path)
{
    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&m, &error, &warning, path)) << error;
    return m;
}

template <typename T>
const T* accessorData(const tinygltf::Model& m, int accessor)
{
    const auto& a = m.accessors[std::size_t(accessor)];
    const auto& v = m.bufferViews[std::size_t(a.bufferView)];
    return reinterpret_cast<const T*>(m.buffers[std::size_t(v.buffer)].data.data() + v.byteOffset + a.byteOffset);
}

const tinygltf::Node* nodeNamed(const tinygltf::Model& m, const std::string& name)
{
    for (const auto& n : m.nodes)
        if (n.name == name)
            return &n;
    return nullptr;
}

} // namespace

TEST(SkinnedMesh, ProxyMeshFollowsTheBonesWithNormalisedWeights)
{
    const auto skeleton = model::extractSkeleton(biped());
    const io::SkinnedMesh mesh = io::proxyMesh(*skeleton, 20000);
    EXPECT_NEAR(double(mesh.vertexCount()), 20000.0, 2000.0);
    EXPECT_TRUE(io::checkInfluences(mesh, *skeleton).empty());
    std::set<int> bound;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        EXPECT_LE(mesh.influenceCount(v), 2u);
        for (std::size_t k = 0; k < mesh.influenceCount(v); ++k)
            bound.insert(mesh.influencesOf(v)[k].joint);
    }
    EXPECT_GT(bound.size(), skeleton->joints.size() * 3 / 4) << "most joints deform the proxy";
}

TEST(SkinnedMesh, InfluenceProblemsAreReportedAndLimitingFixesThem)
{
    const auto skeleton = model::extractSkeleton(biped());
    io::SkinnedMesh mesh;
    mesh.name = "body";
    mesh.positions = {{0, 1, 0}, {0, 1.1f, 0}, {0, 1.2f, 0}};
    mesh.indices = {0, 1, 2};
    mesh.influenceStart = {0, 5, 7, 8};
    mesh.influences = {{1, 0.3f}, {2, 0.25f}, {3, 0.2f}, {4, 0.15f}, {5, 0.1f}, // five, sum 1
                       {1, 0.5f}, {2, 0.3f},                                     // sum 0.8
                       {999, 1.f}};                                              // not a joint
    const Diagnostics problems = io::checkInfluences(mesh, *skeleton);
    ASSERT_EQ(problems.size(), 3u) << formatAll(problems);
    EXPECT_EQ(problems[0].message, "mesh body: 1 vertex bound to joints that are not in the export skeleton (first: vertex 2)");
    EXPECT_EQ(problems[1].message, "mesh body: 1 vertex with more than 4 influences (fix: keep the largest and renormalise) (first: vertex 0)");
    EXPECT_EQ(problems[2].message, "mesh body: 1 vertex whose weights do not sum to 1 (fix: normalise) (first: vertex 1)");
    EXPECT_EQ(problems[0].subject, Subject::ofMesh("body"));

    mesh.influences.back().joint = 6;
    const io::SkinnedMesh fixed = io::limitInfluences(mesh);
    EXPECT_TRUE(io::checkInfluences(fixed, *skeleton).empty());
    ASSERT_EQ(fixed.influenceCount(0), 4u);
    EXPECT_NEAR(fixed.influencesOf(0)[0].weight, 0.3 / 0.9, 1e-6);
    EXPECT_NEAR(fixed.influencesOf(1)[0].weight, 0.5 / 0.8, 1e-6);
}

TEST(RigExport, RefusesUnnormalisedWeightsUnlessFixedAndWritesNormalisedOnes)
{
    const auto skeleton = model::extractSkeleton(biped());
    std::vector<io::SkinnedMesh> meshes{io::proxyMesh(*skeleton, 2000)};
    for (auto& in : meshes[0].influences)
        in.weight *= 0.9f;
    io::ExportOptions options;
    options.meshes = &meshes;
    const std::string path = test::temporaryPath("unnormalised.glb");
    std::filesystem::remove(path);
    Diagnostics d = io::exportRig(biped(), path, options);
    ASSERT_TRUE(hasErrors(d));
    EXPECT_NE(d[0].format().find(path + ": error: mesh proxy: "), std::string::npos) << d[0].format();
    EXPECT_FALSE(std::filesystem::exists(path));

    options.fixWeights = true;
    d = io::exportRig(biped(), path, options);
    ASSERT_FALSE(hasErrors(d)) << formatAll(d);
    const auto m = readGlb(path);
    const auto& primitive = m.meshes.at(0).primitives.at(0);
    const int accessor = primitive.attributes.at("WEIGHTS_0");
    const float* weights = accessorData<float>(m, accessor);
    for (std::size_t v = 0; v < m.accessors[std::size_t(accessor)].count; ++v)
        ASSERT_NEAR(weights[4 * v] + weights[4 * v + 1] + weights[4 * v + 2] + weights[4 * v + 3], 1.f, 1e-6f) << v;
}

TEST(RigExport, ControllersAreTaggedNodesOutsideTheSkin)
{
    io::ExportOptions options;
    options.controllers = true;
    const std::string path = test::temporaryPath("controllers.glb");
    ASSERT_TRUE(io::exportRig(biped(), path, options).empty());
    const auto m = readGlb(path);
    const std::set<int> joints(m.skins[0].joints.begin(), m.skins[0].joints.end());
    std::size_t controllers = 0;
    for (std::size_t i = 0; i < m.nodes.size(); ++i) {
        const auto& extras = m.nodes[i].extras;
        if (!extras.Has("rig"))
            continue;
        EXPECT_EQ(extras.Get("rig").Get("kind").Get<std::string>(), "controller");
        EXPECT_FALSE(extras.Get("rig").Get("id").Get<std::string>().empty());
        EXPECT_EQ(joints.count(int(i)), 0u);
        ++controllers;
    }
    EXPECT_EQ(controllers, biped().count(model::RigNodeKind::Controller));
    const auto* arm = nodeNamed(m, test::node(biped(), "arm.L::ctrls.clavicle").name);
    ASSERT_NE(arm, nullptr);
    EXPECT_EQ(arm->extras.Get("rig").Get("id").Get<std::string>(), "arm.L::ctrls.clavicle");
}

TEST(RigExport, CurrentPoseMovesTheNodesAndKeepsTheBindPose)
{
    const model::PoseValues pose{{test::node(biped(), "arm.L::ctrls.clavicle").key, {{"rz", 40.0}}}};
    io::ExportOptions options;
    options.pose = &pose;
    const std::string rest = test::temporaryPath("rest.glb"), posed = test::temporaryPath("posed.glb");
    ASSERT_TRUE(io::exportRig(biped(), rest).empty());
    ASSERT_TRUE(io::exportRig(biped(), posed, options).empty());
    const auto a = readGlb(rest), b = readGlb(posed);
    const std::string clavicle = test::node(biped(), "arm.L::skin.clavicle").name;
    EXPECT_NE(nodeNamed(a, clavicle)->rotation, nodeNamed(b, clavicle)->rotation);
    EXPECT_EQ(nodeNamed(a, "sk_spine_hips")->rotation, nodeNamed(b, "sk_spine_hips")->rotation);
    const auto& ibmA = a.accessors[std::size_t(a.skins[0].inverseBindMatrices)];
    const float* x = accessorData<float>(a, a.skins[0].inverseBindMatrices);
    const float* y = accessorData<float>(b, b.skins[0].inverseBindMatrices);
    EXPECT_TRUE(std::equal(x, x + 16 * ibmA.count, y)) << "the bind pose does not move";
}

// The range of motion is tested in RangeOfMotionTest.cpp.

TEST(RigExport, UnrealFbxIsZUpCentimetresWithARootJointAtTheOrigin)
{
    const std::vector<io::SkinnedMesh> meshes{io::proxyMesh(*model::extractSkeleton(biped()), 2000)};
    io::ExportOptions options;
    options.preset = io::ExportPreset::Unreal;
    options.meshes = &meshes;
    const std::string path = test::temporaryPath("unreal.fbx");
    ASSERT_TRUE(io::exportRig(biped(), path, options).empty());
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    float unit = 0.f; // Assimp's importer stores the FBX global settings as float and int32
    int32_t up = 0;
    ASSERT_TRUE(scene->mMetaData->Get("UnitScaleFactor", unit));
    ASSERT_TRUE(scene->mMetaData->Get("UpAxis", up));
    EXPECT_EQ(unit, 1.f) << "centimetres";
    EXPECT_EQ(up, 2) << "Z up";
    const aiNode* root = scene->mRootNode->FindNode("root");
    ASSERT_NE(root, nullptr);
    const aiMatrix4x4& t = root->mTransformation;
    EXPECT_TRUE(t.IsIdentity());
    const aiNode* hips = scene->mRootNode->FindNode("sk_spine_hips");
    ASSERT_NE(hips, nullptr);
    EXPECT_NEAR(hips->mTransformation.c4, 100.0, 1e-3) << "the hips 1 m up: Z, in centimetres";
}

TEST(RigExport, UnityPresetUsesHumanoidNames)
{
    io::ExportOptions options;
    options.preset = io::ExportPreset::Unity;
    const model::GuideDocument guide = test::loadSample("biped");
    options.guide = &guide;
    const std::string path = test::temporaryPath("unity.glb");
    ASSERT_TRUE(io::exportRig(biped(), path, options).empty());
    const auto m = readGlb(path);
    for (const char* name : {"Hips", "Spine", "Head", "LeftUpperArm", "RightLowerLeg", "LeftIndexProximal"})
        EXPECT_NE(nodeNamed(m, name), nullptr) << name;
}

TEST(RigExport, UnknownExtensionsAreRefused)
{
    const Diagnostics d = io::exportRig(biped(), "rig.obj");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].format(), "rig.obj: error: unknown export format: use .glb, .gltf or .fbx");
}
