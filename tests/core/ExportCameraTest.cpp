// util.camera in an export: the vehicle sample's chase camera becomes a real
// camera in every file (a glTF camera node, an FBX Camera model with its
// Camera attribute), at the rig camera's world transform in the file's rest
// pose and at every key of a clip, looking at the target, never a joint.
// Blender (tests/tools/blender-camera.py, ctest Export.vehicle.Camera.*)
// checks the same files' cameras from the other side.
#include "EvalTestSupport.h"
#include "FbxReader.h"
#include "TestSupport.h"
#include "io/ExportScene.h"
#include "io/FbxExport.h"
#include "io/RigExport.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>

#include <cmath>
#include <fstream>
#include <map>

namespace rs {
namespace {

const char* const kCamera = "camera::camera";
const char* const kCameraControl = "camera::ctrls.camera";
const char* const kTarget = "camera::ctrls.target";
// The template's defaults: 50 mm on a 1.28 x 0.72 inch film back.
const double kYfov = 2.0 * std::atan(0.5 * 0.72 * 25.4 / 50.0);

Vec3 lookOf(const Mat4& m) { return glm::normalize(-Vec3(m[2])); }
double angleBetween(const Vec3& a, const Vec3& b)
{
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// The camera dollies in, pans, rolls and zooms; the target rises.
std::vector<io::KeyedClip> cameraMove(const model::Rig& rig)
{
    const NodeKey camera = test::node(rig, kCameraControl).key, target = test::node(rig, kTarget).key;
    io::KeyedClip clip;
    clip.name = "camera_move";
    clip.times = {0.0, 1.0, 2.0};
    clip.poses.resize(3);
    clip.poses[1][camera] = {{"tx", 1.5}, {"ry", 20.0}, {"roll", 15.0}, {"focal_length", 85.0}};
    clip.poses[1][target] = {{"ty", 0.5}};
    clip.poses[2][camera] = {{"tz", -2.0}, {"rx", -10.0}, {"focal_length", 35.0}};
    return {clip};
}

io::ExportScene cameraScene(const model::Rig& rig, const std::vector<io::KeyedClip>& clips,
                            io::ExportPreset preset = io::ExportPreset::Gltf)
{
    io::ExportOptions options;
    options.keyedClips = &clips;
    options.preset = preset;
    options.force = true; // Unity: the vehicle has no humanoid bones
    auto prepared = io::prepareExport(rig, options);
    EXPECT_TRUE(prepared.scene) << formatAll(prepared.report);
    return prepared.scene ? *prepared.scene : io::ExportScene{};
}

const io::ExportTrack* cameraTrack(const io::ExportClip& clip)
{
    for (const auto& track : clip.tracks)
        if (track.camera)
            return &track;
    return nullptr;
}

} // namespace

TEST(ExportCamera, TheCameraNodeIsTheRigCamerasWorldTransformAimedAtTheTargetAtEveryKey)
{
    test::PosedRig r("vehicle");
    ASSERT_TRUE(r.ok());
    const auto clips = cameraMove(r.rig);
    const io::ExportScene scene = cameraScene(r.rig, clips);
    ASSERT_EQ(scene.cameras.size(), 1u);
    const io::ExportCamera& camera = scene.cameras.front();
    EXPECT_EQ(camera.id, kCamera);
    EXPECT_LT(maxAbsDifference(camera.poseWorld, r.rig.nodes[r.index(kCamera)].worldMatrix), 1e-9);
    EXPECT_LT(angleBetween(lookOf(camera.poseWorld),
                           glm::normalize(r.restPosition(kTarget) - translationOf(camera.poseWorld))), 1e-9);
    EXPECT_DOUBLE_EQ(camera.focalLength, 50.0);
    EXPECT_NEAR(io::verticalFieldOfView(camera, camera.focalLength), kYfov, 1e-12);

    ASSERT_EQ(scene.clips.size(), 1u);
    const io::ExportClip& clip = scene.clips.front();
    const io::ExportTrack* track = cameraTrack(clip);
    ASSERT_NE(track, nullptr);
    EXPECT_TRUE(track->animated & io::kTranslationChannel);
    EXPECT_TRUE(track->animated & io::kRotationChannel);
    EXPECT_TRUE(track->animated & io::kLensChannel);
    EXPECT_EQ(track->focalLengths, (std::vector<double>{50.0, 85.0, 35.0}));
    double travel = 0.0, turn = 0.0;
    for (std::size_t k = 0; k < clip.times.size(); ++k) {
        const auto& state = r.evaluate(eval::poseFromValues(r.rig, r.program->channels(), clips[0].poses[k]));
        const Mat4 rigCamera = state.worldMatrix(r.index(kCamera));
        Mat4 exported = glm::mat4_cast(track->rotations[k]);
        exported[3] = Vec4(track->translations[k], 1.0);
        EXPECT_LT(maxAbsDifference(exported, rigCamera), 1e-9) << "key " << k;
        const Vec3 eye = translationOf(exported), target = r.position(kTarget);
        EXPECT_LT(angleBetween(lookOf(exported), glm::normalize(target - eye)), 1e-9) << "key " << k;
        travel = std::max(travel, glm::length(eye - translationOf(camera.poseWorld)));
        turn = std::max(turn, angleBetween(Vec3(exported[1]), Vec3(camera.poseWorld[1])));
    }
    EXPECT_GT(travel, 1.0) << "the clip moves the camera";
    EXPECT_GT(turn, glm::radians(10.0)) << "the clip rolls the camera";
}

TEST(ExportCamera, TheCameraIsNoJointAndEveryPresetKeepsAOneRootSkeleton)
{
    const model::Rig rig = rigging::buildRig(test::loadSample("vehicle"), test::builtinTemplates());
    ASSERT_TRUE(rig.sets.count("cameras"));
    for (io::ExportPreset preset : {io::ExportPreset::Gltf, io::ExportPreset::Unreal, io::ExportPreset::Unity}) {
        const io::ExportScene scene = cameraScene(rig, {}, preset);
        EXPECT_EQ(scene.cameras.size(), 1u) << io::presetName(preset);
        int roots = 0;
        for (const auto& joint : scene.joints) {
            roots += joint.parent < 0;
            EXPECT_NE(joint.id.rfind("camera::", 0), 0u) << joint.id << " (" << io::presetName(preset) << ")";
        }
        EXPECT_EQ(roots, 1) << io::presetName(preset);
    }
}

TEST(ExportCamera, AZUpCentimetreFileTurnsTheCameraWithoutChangingWhereItLooks)
{
    const model::Rig rig = rigging::buildRig(test::loadSample("vehicle"), test::builtinTemplates());
    const auto clips = cameraMove(rig);
    const io::ExportScene scene = cameraScene(rig, clips, io::ExportPreset::Unreal);
    const io::ExportScene file = io::converted(scene, io::conventionFor(io::ExportPreset::Unreal, true));
    const Mat3 toZUp(rotationMatrix(Vec3(1, 0, 0), glm::radians(90.0))); // Y-up -> Z-up
    const Mat4 before = scene.cameras[0].poseWorld, after = file.cameras[0].poseWorld;
    EXPECT_LT(glm::length(translationOf(after) - toZUp * translationOf(before) * 100.0), 1e-9);
    EXPECT_LT(angleBetween(lookOf(after), toZUp * lookOf(before)), 1e-9);
    EXPECT_LT(angleBetween(Vec3(after[1]), toZUp * Vec3(before[1])), 1e-9);
    EXPECT_NEAR(file.cameras[0].farClip, 100.0 * scene.cameras[0].farClip, 1e-9);
    const io::ExportTrack *a = cameraTrack(scene.clips[0]), *b = cameraTrack(file.clips[0]);
    ASSERT_TRUE(a && b);
    for (std::size_t k = 0; k < a->rotations.size(); ++k)
        EXPECT_LT(angleBetween(Mat3(glm::mat3_cast(b->rotations[k])) * Vec3(0, 0, -1),
                               toZUp * (Mat3(glm::mat3_cast(a->rotations[k])) * Vec3(0, 0, -1))), 1e-9);
}

TEST(ExportCamera, TheGltfCameraHasTheLensYfovAndItsNodeFollowsTheClip)
{
    const model::Rig rig = rigging::buildRig(test::loadSample("vehicle"), test::builtinTemplates());
    const auto clips = cameraMove(rig);
    io::ExportOptions options;
    options.keyedClips = &clips;
    const std::string path = test::temporaryPath("camera.gltf");
    ASSERT_FALSE(hasErrors(io::exportRig(rig, path, options)));
    const nlohmann::json gltf = nlohmann::json::parse(std::ifstream(path));
    ASSERT_EQ(gltf["cameras"].size(), 1u);
    const auto& perspective = gltf["cameras"][0]["perspective"];
    EXPECT_NEAR(perspective["yfov"].get<double>(), kYfov, 1e-9);
    EXPECT_NEAR(perspective["aspectRatio"].get<double>(), 1.28 / 0.72, 1e-9);
    EXPECT_NEAR(perspective["znear"].get<double>(), 0.01, 1e-12);
    EXPECT_NEAR(perspective["zfar"].get<double>(), 1000.0, 1e-9);
    int node = -1;
    for (std::size_t n = 0; n < gltf["nodes"].size(); ++n)
        if (gltf["nodes"][n].contains("camera"))
            node = int(n);
    ASSERT_GE(node, 0);
    const auto& roots = gltf["scenes"][0]["nodes"];
    EXPECT_NE(std::find(roots.begin(), roots.end(), node), roots.end()) << "the camera sits at the scene root";
    EXPECT_FALSE(gltf["skins"][0]["joints"].dump().find("," + std::to_string(node) + ",") != std::string::npos);
    std::set<std::string> paths;
    for (const auto& channel : gltf["animations"][0]["channels"])
        if (channel["target"]["node"] == node)
            paths.insert(channel["target"]["path"].get<std::string>());
    EXPECT_EQ(paths, (std::set<std::string>{"translation", "rotation"}));
}

TEST(ExportCamera, TheFbxCameraLooksDownItsXWithAFocalLengthCurveByteIdentically)
{
    const model::Rig rig = rigging::buildRig(test::loadSample("vehicle"), test::builtinTemplates());
    const auto clips = cameraMove(rig);
    const io::ExportScene scene = cameraScene(rig, clips);
    const auto convention = io::conventionFor(io::ExportPreset::Gltf, true);
    const auto bytes = io::fbxBytes(io::converted(scene, convention), convention);
    ASSERT_TRUE(bytes);
    EXPECT_EQ(*bytes, *io::fbxBytes(io::converted(scene, convention), convention)) << "byte-identical";
    const test::FbxFile file = test::readFbx(*bytes);
    ASSERT_TRUE(file.error.empty()) << file.error;
    const test::FbxObjects objects(file);
    const auto models = objects.ofKind("Model", "Camera");
    const auto attributes = objects.ofKind("NodeAttribute", "Camera");
    ASSERT_EQ(models.size(), 1u);
    ASSERT_EQ(attributes.size(), 1u);
    auto property = [](const test::FbxRecord& object, const std::string& name) -> const test::FbxRecord* {
        for (const auto* p : object.find("Properties70")->all("P"))
            if (p->properties[0].text == name)
                return p;
        return nullptr;
    };
    ASSERT_NE(property(*attributes[0], "FocalLength"), nullptr);
    EXPECT_DOUBLE_EQ(property(*attributes[0], "FocalLength")->properties.back().number, 50.0);
    EXPECT_NEAR(property(*attributes[0], "FilmHeight")->properties.back().number, 0.72, 1e-12);
    // The model's +X is the rig camera's -Z (its Lcl Rotation, XYZ Euler degrees).
    const auto* rotation = property(*models[0], "Lcl Rotation");
    ASSERT_NE(rotation, nullptr);
    const std::size_t n = rotation->properties.size();
    const Vec3 euler(rotation->properties[n - 3].number, rotation->properties[n - 2].number, rotation->properties[n - 1].number);
    const Mat3 r = Mat3(rotationMatrix(Vec3(0, 0, 1), glm::radians(euler.z))) *
                   Mat3(rotationMatrix(Vec3(0, 1, 0), glm::radians(euler.y))) *
                   Mat3(rotationMatrix(Vec3(1, 0, 0), glm::radians(euler.x)));
    EXPECT_LT(angleBetween(r * Vec3(1, 0, 0), lookOf(scene.cameras[0].poseWorld)), 1e-9);
    EXPECT_LT(angleBetween(r * Vec3(0, 1, 0), Vec3(scene.cameras[0].poseWorld[1])), 1e-9);
    // A FocalLength curve node on the attribute, keyed 50, 85, 35 mm.
    const std::int64_t attributeId = attributes[0]->properties[0].integer;
    std::vector<double> keys;
    for (const auto* curveNode : objects.ofKind("AnimationCurveNode", "")) {
        const std::int64_t id = curveNode->properties[0].integer;
        bool onLens = false;
        for (auto [it, end] = objects.parents.equal_range(id); it != end; ++it)
            onLens = onLens || (it->second.first == attributeId && it->second.second == "FocalLength");
        if (!onLens)
            continue;
        for (const auto& [child, parent] : objects.parents)
            if (parent.first == id && parent.second == "d|FocalLength")
                keys = objects.byId.at(child)->find("KeyValueFloat")->properties[0].array;
    }
    EXPECT_EQ(keys, (std::vector<double>{50.0, 85.0, 35.0}));
}

TEST(ExportCamera, AssimpFindsTheCameraOfTheGlbAndTheFbxWhereTheRigPutsIt)
{
    const model::Rig rig = rigging::buildRig(test::loadSample("vehicle"), test::builtinTemplates());
    const io::ExportScene scene = cameraScene(rig, {});
    const Mat4 expected = scene.cameras.at(0).poseWorld;
    const double hfov = 2.0 * std::atan(0.5 * 1.28 * 25.4 / 50.0);
    for (const char* extension : {".glb", ".fbx"}) {
        const std::string path = test::temporaryPath(std::string("camera-assimp") + extension);
        ASSERT_FALSE(hasErrors(io::exportRig(rig, path, {})));
        Assimp::Importer importer;
        const aiScene* read = importer.ReadFile(path, 0);
        ASSERT_NE(read, nullptr) << importer.GetErrorString();
        ASSERT_EQ(read->mNumCameras, 1u) << extension;
        const aiCamera& camera = *read->mCameras[0];
        EXPECT_EQ(std::string(camera.mName.C_Str()), scene.cameras[0].name) << extension;
        const aiNode* node = read->mRootNode->FindNode(camera.mName);
        ASSERT_NE(node, nullptr) << extension;
        aiMatrix4x4 world = node->mTransformation;
        for (const aiNode* p = node->mParent; p; p = p->mParent)
            world = p->mTransformation * world;
        const aiVector3D look = aiMatrix3x3(world) * camera.mLookAt, up = aiMatrix3x3(world) * camera.mUp;
        EXPECT_LT(glm::length(Vec3(world.a4, world.b4, world.c4) - translationOf(expected)), 1e-5) << extension;
        EXPECT_LT(angleBetween(glm::normalize(Vec3(look.x, look.y, look.z)), lookOf(expected)), 1e-5) << extension;
        EXPECT_LT(angleBetween(glm::normalize(Vec3(up.x, up.y, up.z)), Vec3(expected[1])), 1e-5) << extension;
        EXPECT_NEAR(camera.mAspect, 1.28 / 0.72, 1e-5) << extension;
        // Assimp 5.2.5's glTF importer scales yfov by the aspect ratio (not
        // through the tangent); its FBX importer reads FieldOfView (degrees).
        EXPECT_NEAR(camera.mHorizontalFOV, std::string(extension) == ".fbx" ? hfov : kYfov * 1.28 / 0.72, 1e-5)
            << extension;
        EXPECT_NEAR(camera.mClipPlaneFar, 1000.0, 1e-3) << extension;
    }
}

// An orthographic camera (util.camera's `orthographic`, `ortho_width`) is one
// in every file: glTF's orthographic camera (half the width and height it
// sees), FBX's projection type 1 with the width as OrthoZoom (what Blender
// reads as its ortho_scale), and Assimp reads the glTF's width back.
TEST(ExportCamera, AnOrthographicCameraIsExportedOrthographicWithTheWidthItSees)
{
    model::GuideDocument guide = test::loadSample("vehicle");
    model::TemplateInstance& camera = *guide.instance(guide.instanceNamed("camera")->id);
    camera.options["orthographic"] = true;
    camera.options["ortho_width"] = 4.0;
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    const std::string path = test::temporaryPath("camera-ortho.gltf");
    ASSERT_FALSE(hasErrors(io::exportRig(rig, path, {})));
    const nlohmann::json gltf = nlohmann::json::parse(std::ifstream(path));
    ASSERT_EQ(gltf["cameras"].size(), 1u);
    EXPECT_EQ(gltf["cameras"][0]["type"], "orthographic");
    EXPECT_FALSE(gltf["cameras"][0].contains("perspective"));
    const auto& ortho = gltf["cameras"][0]["orthographic"];
    EXPECT_NEAR(ortho["xmag"].get<double>(), 2.0, 1e-12);
    EXPECT_NEAR(ortho["ymag"].get<double>(), 2.0 * 0.72 / 1.28, 1e-12);
    EXPECT_NEAR(ortho["znear"].get<double>(), 0.01, 1e-12);
    EXPECT_NEAR(ortho["zfar"].get<double>(), 1000.0, 1e-9);
    Assimp::Importer importer;
    const aiScene* read = importer.ReadFile(path, 0);
    ASSERT_NE(read, nullptr) << importer.GetErrorString();
    ASSERT_EQ(read->mNumCameras, 1u);
    EXPECT_NEAR(read->mCameras[0]->mOrthographicWidth, 2.0, 1e-6) << "Assimp keeps glTF's xmag as its width";

    const io::ExportScene scene = cameraScene(rig, {});
    ASSERT_EQ(scene.cameras.size(), 1u);
    EXPECT_TRUE(scene.cameras[0].orthographic);
    const auto convention = io::conventionFor(io::ExportPreset::Unreal, true); // centimetres: the width stays metres
    const auto bytes = io::fbxBytes(io::converted(scene, convention), convention);
    ASSERT_TRUE(bytes);
    const test::FbxFile file = test::readFbx(*bytes);
    ASSERT_TRUE(file.error.empty()) << file.error;
    const auto attributes = test::FbxObjects(file).ofKind("NodeAttribute", "Camera");
    ASSERT_EQ(attributes.size(), 1u);
    std::map<std::string, double> values;
    for (const auto* p : attributes[0]->find("Properties70")->all("P"))
        values[p->properties[0].text] = p->properties.back().type == 'D' ? p->properties.back().number
                                                                          : double(p->properties.back().integer);
    EXPECT_EQ(values["CameraProjectionType"], 1.0);
    EXPECT_NEAR(values["OrthoZoom"], 4.0, 1e-12);
}

} // namespace rs
