// Our binary FBX writer (issue 21): the container read back by a test-side
// parser (7.4 and 7.5), the skeleton as LimbNodes with or without a mesh, the
// bind pose, byte-identical output, write errors. Curves: FbxAnimationTest.cpp.
#include "core/FbxReader.h"
#include "core/TestSupport.h"
#include "io/FbxBinary.h"
#include "io/FbxExport.h"
#include "io/RigExport.h"
#include "model/Skeleton.h"
#include "rigging/RigBuilder.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

using namespace rs;

namespace {

const model::Rig& biped()
{
    static const model::Rig rig = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    return rig;
}

} // namespace

TEST(FbxBinary, RecordsOfEveryPropertyTypeParseBackIn74And75)
{
    for (std::uint32_t version : {io::fbx::kVersion74, io::fbx::kVersion75}) {
        std::deque<io::fbx::Node> top;
        io::fbx::Node& a = top.emplace_back("Scalars");
        a.addInt16(-7).addBool(true).addInt32(-123456).addFloat(1.5f).addDouble(-2.25).addInt64(46186158000LL)
            .addString(std::string("name\0\x01" "Class", 11)).addRaw(std::string("\0\xff\x01", 3));
        io::fbx::Node& b = top.emplace_back("Arrays");
        const std::vector<double> d{1.0, -2.0, 3.5};
        const std::vector<float> f{0.5f};
        const std::vector<std::int64_t> l{-1, 1LL << 40};
        const std::vector<std::int32_t> i{-3, 0, 7};
        const std::vector<std::uint8_t> bo{1, 0};
        b.addDoubles(d).addFloats(f).addInt64s(l).addInt32s(i).addBools(bo);
        b.child("Empty");            // no properties: ends with a null record
        b.child("Leaf").addInt32(1); // properties, no children: no null record
        b.child("Nested").child("Deeper").addString("x");
        auto serialised = io::fbx::serialise(top, version);
        ASSERT_TRUE(serialised.ok()) << formatAll(serialised.diagnostics());
        const std::string bytes = serialised.take();
        const test::FbxFile file = test::readFbx(bytes);
        ASSERT_TRUE(file.error.empty()) << version << ": " << file.error;
        EXPECT_EQ(file.version, version);
        ASSERT_EQ(file.records.size(), 2u);
        const auto& s = file.records[0].properties;
        ASSERT_EQ(s.size(), 8u);
        EXPECT_EQ(std::string({s[0].type, s[1].type, s[2].type, s[3].type, s[4].type, s[5].type, s[6].type, s[7].type}), "YCIFDLSR");
        EXPECT_EQ(s[0].integer, -7);
        EXPECT_EQ(s[1].integer, 1);
        EXPECT_EQ(s[2].integer, -123456);
        EXPECT_EQ(s[3].number, 1.5);
        EXPECT_EQ(s[4].number, -2.25);
        EXPECT_EQ(s[5].integer, 46186158000LL);
        EXPECT_EQ(s[6].text, std::string("name\0\x01" "Class", 11));
        EXPECT_EQ(s[7].text, std::string("\0\xff\x01", 3));
        const auto& arrays = file.records[1];
        ASSERT_EQ(arrays.properties.size(), 5u);
        EXPECT_EQ(arrays.properties[0].array, d);
        EXPECT_EQ(arrays.properties[1].array, std::vector<double>{0.5});
        EXPECT_EQ(arrays.properties[2].array, (std::vector<double>{-1.0, double(1LL << 40)}));
        EXPECT_EQ(arrays.properties[3].array, (std::vector<double>{-3.0, 0.0, 7.0}));
        EXPECT_EQ(arrays.properties[4].array, (std::vector<double>{1.0, 0.0}));
        ASSERT_EQ(arrays.children.size(), 3u);
        EXPECT_EQ(arrays.children[2].children.at(0).properties.at(0).text, "x");
        EXPECT_EQ((bytes.size() - 140) % 16, 0u) << "the footer's version is 16-byte aligned";
    }
}

TEST(FbxExport, JointsAreLimbNodeModelsWithAttributesWithoutAMesh)
{
    const std::string path = test::temporaryPath("bare.fbx");
    ASSERT_TRUE(io::exportRig(biped(), path).empty());
    const test::FbxFile file = test::readFbx(test::readFileBytes(path));
    ASSERT_TRUE(file.error.empty()) << file.error;
    const test::FbxObjects objects(file);
    const auto skeleton = model::extractSkeleton(biped());
    const auto limbs = objects.ofKind("Model", "LimbNode");
    ASSERT_EQ(limbs.size(), skeleton->joints.size());
    std::set<std::int64_t> limbIds;
    for (const auto* m : limbs)
        limbIds.insert(m->properties[0].integer);
    std::size_t attributes = 0;
    for (const auto* a : objects.ofKind("NodeAttribute", "LimbNode")) {
        const auto [first, last] = objects.parents.equal_range(a->properties[0].integer);
        ASSERT_NE(first, last);
        EXPECT_TRUE(limbIds.count(first->second.first)) << "a LimbNode attribute is connected to its joint's model";
        ++attributes;
    }
    EXPECT_EQ(attributes, limbs.size());
    EXPECT_EQ(objects.ofKind("Pose", "BindPose").size(), 1u);
    EXPECT_EQ(objects.ofKind("Model", "Null").size(), 0u) << "no controllers unless asked";

    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    for (const auto& joint : skeleton->joints) {
        const aiNode* node = scene->mRootNode->FindNode(joint.name.c_str());
        ASSERT_NE(node, nullptr) << joint.name;
        if (joint.parent >= 0) {
            EXPECT_EQ(std::string(node->mParent->mName.C_Str()), skeleton->joints[std::size_t(joint.parent)].name);
        }
    }
}

TEST(FbxExport, TheSameSceneGivesByteIdenticalFiles)
{
    const std::vector<io::SkinnedMesh> meshes{io::proxyMesh(*model::extractSkeleton(biped()), 2000)};
    io::ExportOptions options;
    options.meshes = &meshes;
    options.controllers = true;
    options.rangeOfMotion = true;
    const std::string a = test::temporaryPath("same-a.fbx"), b = test::temporaryPath("same-b.fbx");
    ASSERT_TRUE(io::exportRig(biped(), a, options).empty());
    ASSERT_TRUE(io::exportRig(biped(), b, options).empty());
    const std::string bytes = test::readFileBytes(a);
    EXPECT_GT(bytes.size(), 10000u);
    EXPECT_TRUE(bytes == test::readFileBytes(b)) << "no clock in the file";
    EXPECT_NE(bytes.find("1970-01-01 10:00:00:000"), std::string::npos);

    options.stampTime = true;
    ASSERT_TRUE(io::exportRig(biped(), b, options).empty());
    EXPECT_EQ(test::readFileBytes(b).find("1970-01-01 10:00:00:000"), std::string::npos) << "the real time when asked";
}

TEST(FbxExport, AWriteErrorIsADiagnosticAndWritesNothing)
{
    const std::string path = test::temporaryPath("no-such-folder") + "/rig.fbx";
    const Diagnostics report = io::exportRig(biped(), path);
    ASSERT_TRUE(hasErrors(report));
    EXPECT_NE(formatAll(report).find(path), std::string::npos) << formatAll(report);
}

TEST(FbxExport, APosedExportKeepsItsBindPoseInTheClustersAndThePose)
{
    const std::vector<io::SkinnedMesh> meshes{io::proxyMesh(*model::extractSkeleton(biped()), 2000)};
    io::ExportOptions options;
    options.meshes = &meshes;
    auto prepared = io::prepareExport(biped(), options);
    ASSERT_TRUE(prepared.scene);
    io::ExportScene scene = std::move(*prepared.scene);
    scene.joints[1].poseLocal = scene.joints[1].bindLocal * rotationMatrix(Vec3(0, 0, 1), 0.7); // posed node
    const auto bytes = io::fbxBytes(scene, {});
    ASSERT_TRUE(bytes);
    Assimp::Importer importer;
    const aiScene* ai = importer.ReadFileFromMemory(bytes->data(), bytes->size(), 0, "fbx");
    ASSERT_NE(ai, nullptr) << importer.GetErrorString();
    const test::FbxFile file = test::readFbx(*bytes);
    const test::FbxObjects objects(file);
    const auto poses = objects.ofKind("Pose", "BindPose");
    ASSERT_EQ(poses.size(), 1u);
    const auto nodes = poses[0]->all("PoseNode");
    EXPECT_EQ(nodes.size(), scene.joints.size() + scene.meshes.size());
    for (std::size_t j = 0; j < scene.joints.size(); ++j) {
        const auto& m = nodes[j]->find("Matrix")->properties[0].array;
        ASSERT_EQ(m.size(), 16u);
        EXPECT_NEAR(m[12], scene.joints[j].bindWorld[3][0], 1e-9) << scene.joints[j].name;
        EXPECT_NEAR(m[13], scene.joints[j].bindWorld[3][1], 1e-9) << scene.joints[j].name;
    }
    for (unsigned b = 0; b < ai->mMeshes[0]->mNumBones; ++b) { // bind from TransformLink, not the posed nodes
        const aiBone& bone = *ai->mMeshes[0]->mBones[b];
        for (const auto& joint : scene.joints) {
            if (joint.name == bone.mName.C_Str()) {
                EXPECT_NEAR(bone.mOffsetMatrix.a4, glm::inverse(joint.bindWorld)[3][0], 1e-4) << joint.name;
            }
        }
    }
}

TEST(FbxExport, Version75FilesWithWideOffsetsReadBack)
{
    const std::vector<io::SkinnedMesh> meshes{io::proxyMesh(*model::extractSkeleton(biped()), 2000)};
    io::ExportOptions options;
    options.meshes = &meshes;
    auto prepared = io::prepareExport(biped(), options);
    ASSERT_TRUE(prepared.scene);
    io::FbxWriteOptions wide;
    wide.version = 7500;
    const auto bytes = io::fbxBytes(*prepared.scene, {}, wide);
    ASSERT_TRUE(bytes);
    const test::FbxFile file = test::readFbx(*bytes);
    ASSERT_TRUE(file.error.empty()) << file.error;
    EXPECT_EQ(file.version, 7500u);
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFileFromMemory(bytes->data(), bytes->size(), 0, "fbx");
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    EXPECT_EQ(scene->mNumMeshes, 1u);
    wide.version = 7300;
    EXPECT_FALSE(io::fbxBytes(*prepared.scene, {}, wide)) << "only 7400 and 7500 are written";
}

// Issue 21: a texture travels inside the FBX (the Video's Content) or, with
// embedTextures off, as a file written beside it that the FBX names relatively.
TEST(FbxExport, TexturesAreEmbeddedOrWrittenBesideTheFileAndNamedRelatively)
{
    std::vector<io::SkinnedMesh> meshes{io::proxyMesh(*model::extractSkeleton(biped()), 500)};
    meshes[0].material = 0;
    std::vector<io::ExportMaterial> materials(1);
    materials[0].name = "skin";
    materials[0].imageName = "skin.png";
    materials[0].image = std::string("\x89PNG not really an image\0with a zero", 36);
    materials[0].mimeType = "image/png";
    io::ExportOptions options;
    options.meshes = &meshes;
    options.materials = &materials;
    const std::filesystem::path folder = test::temporaryPath("fbx-textures");
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder / "relative");
    auto videoOf = [](const std::string& path) {
        static test::FbxFile file; // the records the returned pointer lives in
        file = test::readFbx(test::readFileBytes(path));
        EXPECT_TRUE(file.error.empty()) << file.error;
        const auto videos = file.find("Objects")->all("Video");
        EXPECT_EQ(videos.size(), 1u);
        return videos.empty() ? nullptr : videos[0];
    };

    ASSERT_FALSE(hasErrors(io::exportRig(biped(), (folder / "embedded.fbx").string(), options)));
    const test::FbxRecord* embedded = videoOf((folder / "embedded.fbx").string());
    ASSERT_TRUE(embedded && embedded->find("Content"));
    EXPECT_EQ(embedded->find("Content")->properties[0].text, materials[0].image);
    EXPECT_FALSE(std::filesystem::exists(folder / "skin.png")) << "embedded: nothing beside the file";

    options.embedTextures = false;
    const std::string relativePath = (folder / "relative" / "rig.fbx").string();
    ASSERT_FALSE(hasErrors(io::exportRig(biped(), relativePath, options)));
    const test::FbxRecord* relative = videoOf(relativePath);
    ASSERT_TRUE(relative);
    EXPECT_EQ(relative->find("Content"), nullptr) << "no image bytes inside the file";
    EXPECT_EQ(relative->find("RelativeFilename")->properties[0].text, "skin.png");
    EXPECT_EQ(test::readFileBytes((folder / "relative" / "skin.png").string()), materials[0].image);
    EXPECT_LT(std::filesystem::file_size(relativePath), std::filesystem::file_size(folder / "embedded.fbx"));

    // A name that would leave the folder is refused, and nothing is written.
    materials[0].imageName = "../escaped.png";
    const std::string refusedPath = (folder / "relative" / "refused.fbx").string();
    const Diagnostics refused = io::exportRig(biped(), refusedPath, options);
    ASSERT_TRUE(hasErrors(refused));
    EXPECT_NE(formatAll(refused).find("'../escaped.png' of material 'skin' is not a plain file name"), std::string::npos)
        << formatAll(refused);
    EXPECT_FALSE(std::filesystem::exists(folder / "escaped.png"));
    EXPECT_FALSE(std::filesystem::exists(refusedPath));
}
