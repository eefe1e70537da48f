// The FBX writer's animation (issue 21): Euler curves continuous and exact,
// Lcl Scaling only where scale changes, constant channels omitted, linear keys
// in FBX ticks, one take per clip, controllers' user properties; a posed scale
// clip read back by Assimp (and by Blender: ctest Export.ScaleClip.Blender).
#include "core/FbxReader.h"
#include "core/TestSupport.h"
#include "io/FbxAnimation.h"
#include "io/FbxExport.h"
#include "io/RigExport.h"
#include "rigging/RigBuilder.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>

using namespace rs;

namespace {

const model::Rig& biped()
{
    static const model::Rig rig = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    return rig;
}

Quat fromEulerXyzDegrees(const Vec3& e)
{
    const Vec3 r = glm::radians(e);
    return glm::angleAxis(r.z, Vec3(0, 0, 1)) * glm::angleAxis(r.y, Vec3(0, 1, 0)) * glm::angleAxis(r.x, Vec3(1, 0, 0));
}

} // namespace

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
    const test::FbxObjects objects(file);

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
            // A curve has a key at every key time of its clip (the range of motion is in clips of a minute).
            const auto clip = std::find_if(scene.clips.begin(), scene.clips.end(), [&](const io::ExportClip& c) {
                return c.times.size() == values.size() && times[1] == std::round(c.times[1] * 46186158000.0); // FBX ticks
            });
            EXPECT_NE(clip, scene.clips.end()) << "a curve of " << values.size() << " keys, the second at " << times[1];
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
    track.animated |= io::kScaleChannel; // the writers write the channels the flags name
    scene.joints[2].poseLocal = scene.joints[2].bindLocal * rotationMatrix(Vec3(0, 0, 1), 0.5);
    const char* dir = std::getenv("RIGSMITH_SCALE_CLIP_DIR");
    if (dir)
        std::filesystem::create_directories(dir);
    const std::string path = dir ? std::string(dir) + "/scale-clip.fbx" : test::temporaryPath("scale-clip.fbx");
    ASSERT_TRUE(io::writeFbx(scene, path, {}).empty());
    std::ofstream(path.substr(0, path.size() - 4) + ".json") << io::exportReferenceJson(scene);

    const test::FbxFile file = test::readFbx(test::readFileBytes(path));
    ASSERT_TRUE(file.error.empty()) << file.error;
    const test::FbxObjects objects(file);
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
        // The Euler curves give back the sampled rotations at the keys (Assimp
        // may add keys of its own between them: each of ours is matched by time).
        ASSERT_GE(channel.mNumRotationKeys, track.rotations.size());
        const double ticksPerSecond = ai->mAnimations[0]->mTicksPerSecond > 0.0 ? ai->mAnimations[0]->mTicksPerSecond : 1.0;
        unsigned at = 0;
        for (std::size_t k = 0; k < track.rotations.size(); ++k) {
            const double time = scene.clips[0].times[k] - scene.clips[0].times[0];
            while (at + 1 < channel.mNumRotationKeys &&
                   std::abs(channel.mRotationKeys[at].mTime / ticksPerSecond - time) > 1e-4)
                ++at;
            ASSERT_NEAR(channel.mRotationKeys[at].mTime / ticksPerSecond, time, 1e-4) << "key " << k;
            const aiQuaternion& q = channel.mRotationKeys[at].mValue;
            EXPECT_GT(std::abs(glm::dot(Quat(q.w, q.x, q.y, q.z), track.rotations[k])), 1.0 - 1e-6) << "key " << k;
        }
    }
    EXPECT_NEAR(largest, 1.5, 1e-3) << name << "'s scale keys";
}

// The FBX carries the channels the clip's flags name, as glTF does
// (ExportTrack::animated / held): a channel whose samples move but whose flag
// is clear gets no curve node, a held channel one key, an animated one every key.
TEST(FbxExport, CurveNodesAreTheClipsAnimatedAndHeldChannels)
{
    io::ExportOptions options;
    options.rangeOfMotion = true;
    auto prepared = io::prepareExport(biped(), options);
    ASSERT_TRUE(prepared.scene);
    io::ExportScene scene = std::move(*prepared.scene);
    scene.clips.resize(1); // the first of the range's clips of a minute
    io::ExportClip& clip = scene.clips[0];
    // Every animated rotation but the first is cleared; the first track's
    // translation is held at an offset instead of whatever it did.
    io::ExportTrack* first = nullptr;
    std::set<std::string> expected;
    for (auto& track : clip.tracks) {
        if (!(track.animated & io::kRotationChannel))
            continue;
        if (!first) {
            first = &track;
            expected.insert(scene.joints[std::size_t(track.node)].name + " Lcl Rotation");
            continue;
        }
        track.animated &= ~unsigned(io::kRotationChannel);
    }
    ASSERT_NE(first, nullptr);
    const Vec3 offset = translationOf(scene.joints[std::size_t(first->node)].poseLocal) + Vec3(0.0, 0.1, 0.0);
    for (Vec3& t : first->translations)
        t = offset;
    first->animated &= ~unsigned(io::kTranslationChannel);
    first->held |= io::kTranslationChannel;
    expected.insert(scene.joints[std::size_t(first->node)].name + " Lcl Translation");
    // A channel whose every key stays within the writer's float resolution
    // (1e-5) of the node's own value is not written (a bendy limb's twist
    // joint moving a few micrometres as the IK arm bends a little).
    auto withinResolution = [&](const io::ExportTrack& track, unsigned bit) {
        const Mat4& local = track.controller ? scene.controllers[std::size_t(track.node)].poseLocal
                                             : scene.joints[std::size_t(track.node)].poseLocal;
        if (bit != io::kTranslationChannel)
            return false;
        for (const Vec3& t : track.translations)
            for (int c = 0; c < 3; ++c)
                if (std::abs(t[c] - local[3][c]) > 1e-5)
                    return false;
        return true;
    };
    for (auto& track : clip.tracks)
        for (unsigned bit : {io::kTranslationChannel, io::kScaleChannel})
            if (&track != first && (track.animated | track.held) & bit && !withinResolution(track, bit))
                expected.insert((track.controller ? scene.controllers[std::size_t(track.node)].name
                                                  : scene.joints[std::size_t(track.node)].name) +
                                (bit == io::kTranslationChannel ? " Lcl Translation" : " Lcl Scaling"));

    const auto bytes = io::fbxBytes(scene, io::conventionFor(io::ExportPreset::Gltf, true));
    ASSERT_TRUE(bytes);
    const test::FbxFile file = test::readFbx(*bytes);
    ASSERT_TRUE(file.error.empty()) << file.error;
    const test::FbxObjects objects(file);
    std::set<std::string> written;
    std::map<std::string, std::size_t> keys; // by "model property", the most keys of its curves
    for (const auto& [child, link] : objects.parents) {
        const auto* object = objects.byId.at(child);
        if (object->name == "AnimationCurveNode" && !link.second.empty())
            written.insert(test::fbxObjectName(*objects.byId.at(link.first)) + " " + link.second);
    }
    for (const auto& [child, link] : objects.parents) {
        const auto* object = objects.byId.at(child);
        if (object->name != "AnimationCurve")
            continue;
        for (const auto& [node, nodeLink] : objects.parents)
            if (node == link.first && !nodeLink.second.empty()) {
                const std::string key = test::fbxObjectName(*objects.byId.at(nodeLink.first)) + " " + nodeLink.second;
                keys[key] = std::max(keys[key], object->find("KeyTime")->properties[0].array.size());
            }
    }
    EXPECT_EQ(written, expected);
    const std::string name = scene.joints[std::size_t(first->node)].name;
    EXPECT_EQ(keys[name + " Lcl Translation"], 1u) << "held: one key";
    EXPECT_EQ(keys[name + " Lcl Rotation"], clip.times.size()) << "animated: every key";
}

// Controllers' custom attributes are written whenever controllers are, cleaned
// up or not, with the exported pose's values: glTF node extras rig.attributes,
// FBX animatable user properties (a double, or an enum with its labels).
TEST(FbxExport, ControllersCarryTheirAttributesInThePoseWithoutCleanup)
{
    const model::Rig& rig = biped();
    const auto ik = rig.findPath("arm.L::ctrls.ik");
    ASSERT_TRUE(ik);
    ASSERT_TRUE(rig.nodes[*ik].defaultValues.empty()) << "the sample is not cleaned up";
    model::PoseValues pose;
    pose[rig.nodes[*ik].key] = {{"stretch", 0.25}, {"space", 3.0}};
    io::ExportOptions options;
    options.controllers = true;
    options.pose = &pose;
    const std::string name = rig.nodes[*ik].name;

    const std::string glb = test::temporaryPath("attributes.glb");
    ASSERT_FALSE(hasErrors(io::exportRig(rig, glb, options)));
    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&m, &error, &warning, glb)) << error;
    bool inGltf = false;
    for (const auto& node : m.nodes) {
        if (node.name != name)
            continue;
        inGltf = true;
        const tinygltf::Value& a = node.extras.Get("rig").Get("attributes");
        ASSERT_TRUE(a.IsObject());
        EXPECT_EQ(a.Get("stretch").Get("value").GetNumberAsDouble(), 0.25);
        EXPECT_EQ(a.Get("stretch").Get("max").GetNumberAsDouble(), 1.0);
        EXPECT_EQ(a.Get("space").Get("value").GetNumberAsDouble(), 3.0);
        ASSERT_EQ(a.Get("space").Get("labels").ArrayLen(), 5u);
        EXPECT_EQ(a.Get("space").Get("labels").Get(3).Get<std::string>(), "chest");
        for (const auto& attribute : rig.nodes[*ik].attributes)
            if (attribute.name == "soft_ik") {
                EXPECT_EQ(a.Get("soft_ik").Get("value").GetNumberAsDouble(), attribute.value)
                    << "an attribute the pose leaves has its default";
            }
    }
    EXPECT_TRUE(inGltf) << name;

    const auto prepared = io::prepareExport(rig, options);
    ASSERT_TRUE(prepared.scene);
    const auto bytes = io::fbxBytes(*prepared.scene, io::conventionFor(io::ExportPreset::Gltf, true));
    ASSERT_TRUE(bytes);
    const test::FbxFile file = test::readFbx(*bytes);
    ASSERT_TRUE(file.error.empty()) << file.error;
    const test::FbxObjects objects(file);
    bool inFbx = false;
    for (const auto* model : objects.ofKind("Model", "Null")) {
        if (test::fbxObjectName(*model) != name)
            continue;
        inFbx = true;
        std::map<std::string, const test::FbxRecord*> user;
        for (const auto& p : model->find("Properties70")->children)
            if (p.properties.at(3).text == "A+U")
                user[p.properties[0].text] = &p;
        ASSERT_TRUE(user.count("stretch") && user.count("space") && user.count("soft_ik")) << user.size();
        EXPECT_EQ(user["stretch"]->properties.at(1).text, "double");
        EXPECT_EQ(user["stretch"]->properties.at(4).number, 0.25);
        EXPECT_EQ(user["space"]->properties.at(1).text, "enum");
        EXPECT_EQ(user["space"]->properties.at(4).integer, 3);
        EXPECT_EQ(user["space"]->properties.at(5).text, "world~root~cog~chest~head");
    }
    EXPECT_TRUE(inFbx) << name;
}
