// Issue 21 item 1: authored keys stay cubic. A keyed clip (io::KeyedClip: the
// biped's left arm keyed in FK at three poses) gives cubic tracks with spline
// slopes that keep the curve between keys once converted; a bad clip is
// refused with its name; clip files read keyed poses as the guide's pose
// records (keys out of order at their line) and export beside the range of
// motion, which stays linear. The glTF and FBX files: KeyedClipExportTest.cpp.
#include "core/KeyedClipFixture.h"
#include "core/TestSupport.h"
#include "eval/RigProgram.h"
#include "io/ClipFile.h"
#include "io/ExportRequest.h"
#include "io/GltfExport.h"
#include "io/RigExport.h"
#include "model/Skeleton.h"
#include "rigging/RigBuilder.h"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cmath>
#include <filesystem>

using namespace rs;
using test::keyed::armWave;
using test::keyed::biped;
using test::keyed::bipedGuide;
using test::keyed::clipNamed;
using test::keyed::keyedScene;

TEST(KeyedClip, KeysAreTheRigsPosesWithCubicSplineSlopes)
{
    const auto clips = armWave();
    const io::ExportScene scene = keyedScene(clips);
    const io::ExportClip* clip = clipNamed(scene, "wave");
    ASSERT_NE(clip, nullptr);
    EXPECT_EQ(clip->times, clips[0].times);
    ASSERT_FALSE(clip->tracks.empty());

    auto program = eval::RigProgram::compile(biped());
    ASSERT_TRUE(program);
    eval::EvalState state = program->makeState();
    const auto skeleton = model::extractSkeleton(biped());
    bool rotates = false;
    for (const auto& track : clip->tracks) {
        EXPECT_EQ(track.cubic, track.animated);
        ASSERT_EQ(track.rotationSlopes.size(), clip->times.size());
        rotates = rotates || (track.cubic & io::kRotationChannel);
        // Spline slopes: flat at the ends, (next - previous) / 1 s at the middle key.
        EXPECT_LT(glm::length(glm::vec4(track.rotationSlopes.front().x, track.rotationSlopes.front().y,
                                        track.rotationSlopes.front().z, track.rotationSlopes.front().w)), 1e-12);
        const Quat middle = (track.rotations[2] - track.rotations[0]) * (1.0 / 1.0);
        EXPECT_LT(std::abs(glm::dot(middle - track.rotationSlopes[1], middle - track.rotationSlopes[1])), 1e-20);
        // The curve passes through its keys, and leaves the straight line between them.
        for (std::size_t k = 0; k < clip->times.size(); ++k)
            EXPECT_GT(std::abs(glm::dot(io::trackRotationAt(track, clip->times, clip->times[k]), track.rotations[k])),
                      1.0 - 1e-12);
    }
    EXPECT_TRUE(rotates);
    // The keys are the rig evaluated at the keyed poses (a turning joint's local rotation).
    const auto& elbowTrack = *std::find_if(clip->tracks.begin(), clip->tracks.end(), [&](const io::ExportTrack& t) {
        return t.isJoint() && (t.cubic & io::kRotationChannel) && scene.joints[std::size_t(t.node)].parent >= 0;
    });
    for (std::size_t k = 0; k < clip->times.size(); ++k) {
        program->evaluate(eval::poseFromValues(biped(), program->channels(), clips[0].poses[k]), state);
        const std::size_t j = std::size_t(elbowTrack.node);
        const int parent = scene.joints[j].parent;
        const Mat4 local = glm::inverse(state.worldMatrix(skeleton->joints[std::size_t(parent)].node)) *
                           state.worldMatrix(skeleton->joints[j].node);
        Vec3 t, s;
        Quat r;
        decompose(local, t, r, s);
        EXPECT_GT(std::abs(glm::dot(r, elbowTrack.rotations[k])), 1.0 - 1e-9) << "key " << k;
    }
}

TEST(KeyedClip, ABadClipIsRefusedWithItsName)
{
    auto clips = armWave();
    clips[0].times = {0.0, 0.4, 0.4};
    io::ExportOptions options;
    options.keyedClips = &clips;
    options.force = true;
    const auto prepared = io::prepareExport(biped(), options);
    EXPECT_FALSE(prepared.scene);
    EXPECT_NE(formatAll(prepared.report).find("clip 'wave' needs at least two keys"), std::string::npos)
        << formatAll(prepared.report);
}
TEST(ClipFile, ReadsKeyedPosesAsTheGuidesPoseRecords)
{
    auto read = io::readClipFile(std::string(RIGSMITH_TEST_DATA) + "/Export/keyed-clip/wave.yml");
    ASSERT_TRUE(read) << formatAll(read.diagnostics());
    const io::KeyedClip clip = read.take();
    const io::KeyedClip expected = armWave().front();
    EXPECT_EQ(clip.name, expected.name);
    EXPECT_EQ(clip.times, expected.times);
    EXPECT_EQ(clip.poses, expected.poses);
}

TEST(ClipFile, ReportsKeysOutOfOrderAtTheirLine)
{
    const std::string path = std::string(RIGSMITH_TEST_DATA) + "/Export/keyed-clip/backwards.yml";
    auto read = io::readClipFile(path);
    ASSERT_FALSE(read);
    EXPECT_NE(formatAll(read.diagnostics()).find("backwards.yml:6:"), std::string::npos) << formatAll(read.diagnostics());
    EXPECT_NE(formatAll(read.diagnostics()).find("key times must increase"), std::string::npos);
    auto empty = io::readClipText("rigsmith_clip: 1\nname: x\nkeys: [{time: 0}]\n", "one.yml");
    ASSERT_FALSE(empty);
    EXPECT_NE(formatAll(empty.diagnostics()).find("at least two keys"), std::string::npos);
}

// What `rigsmith-cli build GUIDE --rom --clip wave.yml -o OUT.glb` runs: the
// range of motion baked and linear, the keyed clip cubic.
TEST(RigExport, AClipFileExportsBesideTheRangeOfMotionWithCubicKeys)
{
    io::ExportRequest request;
    request.path = test::temporaryPath("clip-file.glb");
    request.rangeOfMotion = true;
    request.clips = {std::string(RIGSMITH_TEST_DATA) + "/Export/keyed-clip/wave.yml"};
    const Diagnostics report = io::runExport(bipedGuide(), biped(), {}, request);
    ASSERT_FALSE(hasErrors(report)) << formatAll(report);
    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&m, &err, &warn, request.path)) << err;
    ASSERT_GE(m.animations.size(), 2u);
    EXPECT_EQ(m.animations[0].name, "range_of_motion_1"); // the biped's range, in clips of a minute
    EXPECT_EQ(m.animations[0].samplers[0].interpolation, "LINEAR");
    EXPECT_EQ(m.animations.back().name, "wave");
    for (const auto& sampler : m.animations.back().samplers)
        EXPECT_EQ(sampler.interpolation, "CUBICSPLINE");

    request.clips = {std::string(RIGSMITH_TEST_DATA) + "/Export/keyed-clip/backwards.yml"};
    request.path = test::temporaryPath("clip-file-refused.glb");
    EXPECT_TRUE(hasErrors(io::runExport(bipedGuide(), biped(), {}, request)));
    EXPECT_FALSE(std::filesystem::exists(request.path)) << "a bad clip writes nothing";
}

// Unreal's FBX is Z-up centimetres: the slopes turn and scale with their
// values, so the converted curves are the converted clip between keys too.
TEST(KeyedClip, ConvertedSlopesKeepTheCurveBetweenKeys)
{
    const auto clips = armWave();
    io::ExportScene scene = keyedScene(clips);
    io::ExportTrack& track = scene.clips.front().tracks.front();
    for (std::size_t k = 0; k < track.scales.size(); ++k) { // a scale curve too (the arm keeps its scale)
        track.scales[k] = Vec3(1.0 + 0.1 * double(k), 1.0, 1.0 + 0.2 * double(k * k));
    }
    track.scaleSlopes = io::splineSlopes(track.scales, scene.clips.front().times);
    track.animated |= io::kScaleChannel;
    track.cubic |= io::kScaleChannel;
    const io::ExportScene out = io::converted(scene, io::conventionFor(io::ExportPreset::Unreal, true));
    const Mat4 basis = rotationMatrix(Vec3(1, 0, 0), glm::radians(90.0));
    const Quat q = glm::quat_cast(Mat3(basis));
    const auto& times = scene.clips.front().times;
    for (std::size_t n = 0; n < out.clips.front().tracks.size(); ++n) {
        const auto& before = scene.clips.front().tracks[n];
        const auto& after = out.clips.front().tracks[n];
        for (double time : {0.1, 0.3, 0.55, 0.9}) {
            const Vec3 t = Mat3(basis) * io::trackTranslationAt(before, times, time) * 100.0;
            EXPECT_LT(glm::length(io::trackTranslationAt(after, times, time) - t), 1e-9);
            const Quat r = q * io::trackRotationAt(before, times, time) * glm::conjugate(q);
            EXPECT_GT(std::abs(glm::dot(io::trackRotationAt(after, times, time), r)), 1.0 - 1e-12);
            const Vec3 s = glm::abs(Mat3(basis) * io::trackScaleAt(before, times, time));
            EXPECT_LT(glm::length(io::trackScaleAt(after, times, time) - s), 1e-9) << time;
        }
    }
}
