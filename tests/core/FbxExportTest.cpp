// Our binary FBX writer (issue 21): the container read back by a test-side
// parser, the skeleton as LimbNodes with or without a mesh, the animation
// curves (Lcl Scaling, continuous Euler, constant channels omitted, linear
// keys in FBX ticks), byte-identical output, write errors.
#include "core/FbxReader.h"
#include "core/TestSupport.h"
#include "io/FbxAnimation.h"
#include "io/FbxBinary.h"
#include "io/FbxExport.h"
#include "io/RigExport.h"
#include "model/Skeleton.h"
#include "rigging/RigBuilder.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>

using namespace rs;

namespace {

const model::Rig& biped()
{
    static const model::Rig rig = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    return rig;
}

std::string readBytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

// Objects by id, and the connections child -> (parent, property).
struct Objects {
    std::map<std::int64_t, const test::FbxRecord*> byId;
    std::multimap<std::int64_t, std::pair<std::int64_t, std::string>> parents;

    explicit Objects(const test::FbxFile& file)
    {
        for (const auto& o : file.find("Objects")->children)
            byId[o.properties.at(0).integer] = &o;
        for (const auto* c : file.find("Connections")->all("C"))
            parents.emplace(c->properties[1].integer,
                            std::pair{c->properties[2].integer, c->properties.size() > 3 ? c->properties[3].text : ""});
    }
    std::vector<const test::FbxRecord*> ofKind(const std::string& kind, const std::string& type) const
    {
        std::vector<const test::FbxRecord*> out;
        for (const auto& [id, o] : byId)
            if (o->name == kind && o->properties.at(2).text == type)
                out.push_back(o);
        return out;
    }
};

Quat fromEulerXyzDegrees(const Vec3& e)
{
    const Vec3 r = glm::radians(e);
    return glm::angleAxis(r.z, Vec3(0, 0, 1)) * glm::angleAxis(r.y, Vec3(0, 1, 0)) * glm::angleAxis(r.x, Vec3(1, 0, 0));
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
        std::string error;
        const std::string bytes = io::fbx::serialise(top, version, error);
        ASSERT_TRUE(error.empty()) << error;
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
    const test::FbxFile file = test::readFbx(readBytes(path));
    ASSERT_TRUE(file.error.empty()) << file.error;
    const Objects objects(file);
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

TEST(FbxAnimation, EulerCurvesStepAtMost180DegreesAndMatchTheQuaternions)
{
    std::vector<Quat> rotations;
    std::mt19937 random(21);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    const Vec3 axis = glm::normalize(Vec3(1.0, 2.0, -0.5));
    for (int k = 0; k <= 200; ++k) { // three turns about a slanted axis, with wobble through gimbal lock
        const double angle = glm::radians(5.4 * k);
        rotations.push_back(glm::angleAxis(angle, axis) * glm::angleAxis(jitter(random), Vec3(0, 1, 0)));
    }
    rotations.push_back(glm::angleAxis(glm::radians(90.0), Vec3(0, 1, 0))); // exactly at gimbal lock
    const std::vector<Vec3> euler = io::continuousEulerDegrees(rotations, Vec3(0.0));
    ASSERT_EQ(euler.size(), rotations.size());
    for (std::size_t k = 0; k < euler.size(); ++k) {
        const Quat back = fromEulerXyzDegrees(euler[k]);
        EXPECT_GT(std::abs(glm::dot(back, rotations[k])), 1.0 - 1e-9) << "key " << k;
        for (int c = 0; k > 0 && c < 3; ++c) {
            EXPECT_LE(std::abs(euler[k][c] - euler[k - 1][c]), 180.0) << "key " << k << " channel " << c;
        }
    }
    EXPECT_GT(std::abs(euler[200].x) + std::abs(euler[200].z), 360.0) << "whole turns are kept, not wrapped";
}

TEST(FbxExport, RangeOfMotionAnimatesLclScalingOnlyWhereScaleChanges)
{
    io::ExportOptions options;
    options.rangeOfMotion = true;
    options.controllers = true;
    const auto prepared = io::prepareExport(biped(), options);
    ASSERT_TRUE(prepared.scene);
    const io::ExportScene& scene = *prepared.scene;
    const auto bytes = io::fbxBytes(scene, io::conventionFor(io::ExportPreset::Gltf, true));
    ASSERT_TRUE(bytes);
    const test::FbxFile file = test::readFbx(*bytes);
    ASSERT_TRUE(file.error.empty()) << file.error;
    const Objects objects(file);

    // Which models each property animates, by joint name.
    std::map<std::string, std::set<std::string>> animated;
    std::size_t curves = 0;
    for (const auto& [child, link] : objects.parents) {
        const auto* object = objects.byId.at(child);
        if (object->name == "AnimationCurveNode" && !link.second.empty())
            animated[test::fbxObjectName(*objects.byId.at(link.first))].insert(link.second);
        if (object->name != "AnimationCurve")
            continue;
        ++curves;
        const auto& values = object->find("KeyValueFloat")->properties[0].array;
        const auto& times = object->find("KeyTime")->properties[0].array;
        EXPECT_EQ(object->find("KeyAttrFlags")->properties[0].array, std::vector<double>{4.0}) << "linear";
        EXPECT_EQ(object->find("KeyAttrRefCount")->properties[0].array, std::vector<double>{double(values.size())});
        ASSERT_EQ(values.size(), times.size());
        if (values.size() > 1) {
            EXPECT_EQ(values.size(), scene.clips[0].times.size());
            EXPECT_DOUBLE_EQ(times[1], std::round(scene.clips[0].times[1] * 46186158000.0)) << "FBX ticks";
            const bool moves = std::any_of(values.begin(), values.end(), [&](double v) { return std::abs(v - values[0]) > 1e-5; });
            EXPECT_TRUE(moves) << "a constant curve has one key";
        }
        if (link.second == "d|X" || link.second == "d|Y" || link.second == "d|Z") {
            const auto* node = objects.byId.at(link.first);
            for (std::size_t k = 1; test::fbxObjectName(*node) == "R" && k < values.size(); ++k) {
                EXPECT_LE(std::abs(values[k] - values[k - 1]), 180.0 + 1e-3);
            }
        }
    }
    EXPECT_GT(curves, 0u);
    const auto nulls = objects.ofKind("Model", "Null");
    ASSERT_EQ(nulls.size(), scene.controllers.size());
    for (const auto* model : nulls) {
        std::map<std::string, std::string> user;
        for (const auto& p : model->find("Properties70")->children)
            if (p.properties.at(3).text == "U")
                user[p.properties[0].text] = p.properties.at(4).text;
        EXPECT_EQ(user["rig_kind"], "controller") << test::fbxObjectName(*model);
        EXPECT_FALSE(user["rig_id"].empty()) << test::fbxObjectName(*model);
    }
    std::map<std::string, double> defined, counted;
    for (const auto* type : file.find("Definitions")->all("ObjectType"))
        defined[type->properties[0].text] = double(type->find("Count")->properties[0].integer);
    for (const auto& object : file.find("Objects")->children)
        ++counted[object.name];
    counted["GlobalSettings"] = 1;
    EXPECT_EQ(defined, counted) << "Definitions count every object kind";
    for (const auto& [model, properties] : animated)
        for (const auto& property : properties)
            EXPECT_TRUE(property == "Lcl Translation" || property == "Lcl Rotation" || property == "Lcl Scaling")
                << model << " " << property;
    // Scale is animated exactly on the nodes whose sampled scale changes.
    for (const auto& track : scene.clips[0].tracks) {
        const std::string& name = track.controller ? scene.controllers[std::size_t(track.node)].name
                                                   : scene.joints[std::size_t(track.node)].name;
        const Mat4& local = track.controller ? scene.controllers[std::size_t(track.node)].poseLocal
                                             : scene.joints[std::size_t(track.node)].poseLocal;
        Vec3 t, s;
        Quat r;
        decompose(local, t, r, s);
        bool scales = false;
        for (const Vec3& key : track.scales)
            scales = scales || glm::length(key - s) > 1e-5 * std::sqrt(3.0);
        EXPECT_EQ(animated[name].count("Lcl Scaling") > 0, scales) << name;
    }
    EXPECT_EQ(file.find("Takes")->all("Take").size(), scene.clips.size()) << "one take per clip";
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
    const std::string bytes = readBytes(a);
    EXPECT_GT(bytes.size(), 10000u);
    EXPECT_TRUE(bytes == readBytes(b)) << "no clock in the file";
    EXPECT_NE(bytes.find("1970-01-01 10:00:00:000"), std::string::npos);

    options.stampTime = true;
    ASSERT_TRUE(io::exportRig(biped(), b, options).empty());
    EXPECT_EQ(readBytes(b).find("1970-01-01 10:00:00:000"), std::string::npos) << "the real time when asked";
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
    const Objects objects(file);
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

// No sample's range of motion scales a joint, so a scale clip is made here:
// the biped's clip with its most turning joint also scaled up to 1.5 and back,
// and the nodes posed (a spine joint turned) away from the bind pose. Assimp
// must read scaling keys and the rotations; the files also go to
// $RIGSMITH_SCALE_CLIP_DIR when set, for the Blender check (ctest
// Export.ScaleClip.Blender: the rest pose is the BindPose's, not the posed
// nodes', since the file has no mesh and no clusters).
TEST(FbxExport, APosedScaleClipReachesAssimp)
{
    io::ExportOptions options;
    options.rangeOfMotion = true;
    auto prepared = io::prepareExport(biped(), options);
    ASSERT_TRUE(prepared.scene);
    io::ExportScene scene = std::move(*prepared.scene);
    // The joint that turns most during the clip.
    io::ExportTrack* turning = &scene.clips[0].tracks[0];
    double mostTurn = 0.0;
    for (auto& candidate : scene.clips[0].tracks)
        for (const Quat& r : candidate.rotations)
            if (const double turn = 1.0 - std::abs(glm::dot(r, candidate.rotations[0])); turn > mostTurn) {
                mostTurn = turn;
                turning = &candidate;
            }
    io::ExportTrack& track = *turning;
    ASSERT_GT(mostTurn, 0.01);
    const std::string name = scene.joints[std::size_t(track.node)].name;
    for (std::size_t k = 0; k < track.scales.size(); ++k)
        track.scales[k] = Vec3(1.0 + 0.5 * std::sin(3.14159265358979 * double(k) / double(track.scales.size() - 1)));
    scene.joints[2].poseLocal = scene.joints[2].bindLocal * rotationMatrix(Vec3(0, 0, 1), 0.5);
    const char* dir = std::getenv("RIGSMITH_SCALE_CLIP_DIR");
    if (dir)
        std::filesystem::create_directories(dir);
    const std::string path = dir ? std::string(dir) + "/scale-clip.fbx" : test::temporaryPath("scale-clip.fbx");
    ASSERT_TRUE(io::writeFbx(scene, path, {}).empty());
    std::ofstream(path.substr(0, path.size() - 4) + ".json") << io::exportReferenceJson(scene);

    const test::FbxFile file = test::readFbx(readBytes(path));
    ASSERT_TRUE(file.error.empty()) << file.error;
    const Objects objects(file);
    std::set<std::string> scaledModels;
    for (const auto& [child, link] : objects.parents)
        if (link.second == "Lcl Scaling")
            scaledModels.insert(test::fbxObjectName(*objects.byId.at(link.first)));
    EXPECT_EQ(scaledModels, std::set<std::string>{name});
    EXPECT_EQ(objects.ofKind("Deformer", "Cluster").size(), 0u);

    Assimp::Importer importer;
    const aiScene* ai = importer.ReadFile(path, 0);
    ASSERT_NE(ai, nullptr) << importer.GetErrorString();
    ASSERT_GE(ai->mNumAnimations, 1u);
    double largest = 0.0;
    for (unsigned c = 0; c < ai->mAnimations[0]->mNumChannels; ++c) {
        const aiNodeAnim& channel = *ai->mAnimations[0]->mChannels[c];
        if (std::string(channel.mNodeName.C_Str()) != name)
            continue;
        for (unsigned k = 0; k < channel.mNumScalingKeys; ++k)
            largest = std::max(largest, double(channel.mScalingKeys[k].mValue.x));
        // The Euler curves give back the sampled rotations at the keys.
        ASSERT_EQ(channel.mNumRotationKeys, track.rotations.size());
        for (unsigned k = 0; k < channel.mNumRotationKeys; ++k) {
            const aiQuaternion& q = channel.mRotationKeys[k].mValue;
            EXPECT_GT(std::abs(glm::dot(Quat(q.w, q.x, q.y, q.z), track.rotations[k])), 1.0 - 1e-6) << "key " << k;
        }
    }
    EXPECT_NEAR(largest, 1.5, 1e-3) << name << "'s scale keys";
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
