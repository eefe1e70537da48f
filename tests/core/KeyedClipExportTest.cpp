// Issue 21 item 1 in the files: a keyed clip (the biped's left arm keyed in
// FK at three poses) is written as glTF CUBICSPLINE samplers (in-tangent,
// value, out-tangent per key, slopes per second) and as FBX cubic keys with
// user slopes on the clip's half-frame grid, byte-identical for the same
// input. With $RIGSMITH_KEYED_CLIP_DIR set, the .glb and .fbx also go there for
// the consumer checks (ctest Export.KeyedClip.ThreeMidKeys / BlenderMidKeys).
#include "core/FbxReader.h"
#include "core/KeyedClipFixture.h"
#include "core/TestSupport.h"
#include "eval/RigProgram.h"
#include "io/FbxAnimation.h"
#include "io/FbxDocument.h"
#include "io/FbxExport.h"
#include "io/GltfExport.h"
#include "rigging/RigBuilder.h"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace rs;
using test::keyed::armWave;
using test::keyed::clipNamed;
using test::keyed::keyedScene;

namespace {

// Every joint's head (world, the rig's Y-up metres) on the clip's curves at
// 120 Hz (a quarter of each 30 fps frame), as JSON for the Blender check
// (Blender 3.4's glTF importer drops CUBICSPLINE tangents: it is given the
// curve the glTF spec plays instead of its own glTF import).
void writeSamples(const io::ExportScene& scene, const io::ExportClip& clip, const std::string& path)
{
    std::vector<const io::ExportTrack*> trackOf(scene.joints.size(), nullptr);
    for (const auto& track : clip.tracks)
        if (track.isJoint())
            trackOf[std::size_t(track.node)] = &track;
    std::ostringstream out;
    out.precision(9);
    out << "{\"clip\": \"" << clip.name << "\", \"joints\": [";
    for (std::size_t j = 0; j < scene.joints.size(); ++j)
        out << (j ? ", " : "") << '"' << scene.joints[j].name << '"';
    out << "], \"samples\": [";
    const int count = int(std::lround(clip.times.back() * 120.0));
    for (int i = 0; i <= count; ++i) {
        const double time = i / 120.0;
        std::vector<Mat4> world(scene.joints.size());
        out << (i ? ",\n" : "\n") << "{\"time\": " << time << ", \"heads\": [";
        for (std::size_t j = 0; j < scene.joints.size(); ++j) {
            const auto* t = trackOf[j];
            const Mat4 local = t ? translationMatrix(io::trackTranslationAt(*t, clip.times, time)) *
                                       Mat4(glm::mat3_cast(io::trackRotationAt(*t, clip.times, time))) *
                                       glm::scale(Mat4(1.0), io::trackScaleAt(*t, clip.times, time))
                                 : scene.joints[j].poseLocal;
            const int parent = scene.joints[j].parent;
            world[j] = parent < 0 ? local : world[std::size_t(parent)] * local;
            const Vec3 head = translationOf(world[j]);
            out << (j ? ", " : "") << '[' << head.x << ", " << head.y << ", " << head.z << ']';
        }
        out << "]}";
    }
    out << "]}\n";
    std::ofstream(path) << out.str();
}

} // namespace

TEST(GltfExport, KeyedClipsAreCubicSplineSamplersWithSlopesPerSecond)
{
    const auto clips = armWave();
    const io::ExportScene scene = keyedScene(clips, true);
    const io::ExportClip* wave = clipNamed(scene, "wave");
    ASSERT_NE(wave, nullptr);
    const std::string path = test::temporaryPath("keyed-clip.glb");
    ASSERT_TRUE(io::writeGltf(scene, path, "test").empty());
    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&m, &err, &warn, path)) << err;
    ASSERT_EQ(m.animations.size(), scene.clips.size()); // the range of motion in clips of a minute, and the wave
    auto floats = [&](int accessor) {
        const auto& a = m.accessors[std::size_t(accessor)];
        const auto& view = m.bufferViews[std::size_t(a.bufferView)];
        const float* data = reinterpret_cast<const float*>(m.buffers[0].data.data() + view.byteOffset + a.byteOffset);
        return std::vector<float>(data, data + a.count * std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(a.type))));
    };
    std::size_t cubicSamplers = 0;
    for (const auto& animation : m.animations) {
        for (std::size_t c = 0; c < animation.channels.size(); ++c) {
            const auto& sampler = animation.samplers[std::size_t(animation.channels[c].sampler)];
            if (animation.name != "wave") {
                EXPECT_EQ(sampler.interpolation, "LINEAR") << "the range of motion is baked";
                continue;
            }
            ASSERT_EQ(sampler.interpolation, "CUBICSPLINE");
            ++cubicSamplers;
            const auto times = floats(sampler.input);
            const auto output = floats(sampler.output);
            ASSERT_EQ(times.size(), 3u);
            ASSERT_EQ(m.accessors[std::size_t(sampler.output)].count, 9u) << "in-tangent, value, out-tangent per key";
            if (animation.channels[c].target_path != "rotation")
                continue;
            const int node = animation.channels[c].target_node;
            const auto& track = *std::find_if(wave->tracks.begin(), wave->tracks.end(), [&](const io::ExportTrack& t) {
                return t.isJoint() && t.node == node;
            });
            for (std::size_t k = 0; k < 3; ++k) // glTF's x y z w are glm's [0..3]
                for (int i = 0; i < 4; ++i) {
                    EXPECT_NEAR(output[12 * k + 4 + std::size_t(i)], track.rotations[k][i], 1e-6);
                    EXPECT_NEAR(output[12 * k + std::size_t(i)], track.rotationSlopes[k][i], 1e-6) << "in-tangent";
                    EXPECT_NEAR(output[12 * k + 8 + std::size_t(i)], track.rotationSlopes[k][i], 1e-6) << "out-tangent";
                }
            // Played as the glTF spec says (slopes times the key interval),
            // the file gives the clip's own curve between keys.
            const double time = 0.7;
            const double span = times[2] - times[1], s = (time - times[1]) / span;
            Quat q;
            for (int i = 0; i < 4; ++i)
                q[i] = (2 * s * s * s - 3 * s * s + 1) * output[16 + std::size_t(i)] +
                       (s * s * s - 2 * s * s + s) * span * output[20 + std::size_t(i)] +
                       (-2 * s * s * s + 3 * s * s) * output[28 + std::size_t(i)] +
                       (s * s * s - s * s) * span * output[24 + std::size_t(i)];
            EXPECT_GT(std::abs(glm::dot(glm::normalize(q), io::trackRotationAt(track, wave->times, time))), 1.0 - 1e-9);
        }
    }
    EXPECT_GT(cubicSamplers, 2u);
}

TEST(FbxExport, KeyedClipsAreCubicKeysWithUserSlopesOnTheHalfFrameGrid)
{
    const auto clips = armWave();
    const io::ExportScene scene = keyedScene(clips);
    const char* dir = std::getenv("RIGSMITH_KEYED_CLIP_DIR");
    if (dir)
        std::filesystem::create_directories(dir);
    const std::string base = dir ? std::string(dir) + "/keyed-clip" : test::temporaryPath("keyed-clip");
    ASSERT_TRUE(io::writeFbx(scene, base + ".fbx", {}).empty());
    ASSERT_TRUE(io::writeGltf(scene, base + ".glb", "test").empty());
    const std::string bytes = test::readFileBytes(base + ".fbx");
    ASSERT_TRUE(io::writeFbx(scene, base + "-again.fbx", {}).empty());
    EXPECT_EQ(bytes, test::readFileBytes(base + "-again.fbx")) << "byte-identical for the same input";

    writeSamples(scene, scene.clips.front(), base + "-samples.json");

    const test::FbxFile file = test::readFbx(bytes);
    ASSERT_TRUE(file.error.empty()) << file.error;
    const test::FbxObjects objects(file);
    const io::ExportClip& wave = scene.clips.front();
    std::size_t cubicCurves = 0;
    for (const auto* curve : objects.ofKind("AnimationCurve", "")) {
        const auto& times = curve->find("KeyTime")->properties[0].array;
        const auto& values = curve->find("KeyValueFloat")->properties[0].array;
        if (times.size() < 2)
            continue;
        const auto& flags = curve->find("KeyAttrFlags")->properties[0].array;
        const auto& data = curve->find("KeyAttrDataFloat")->properties[0].array;
        const auto& refs = curve->find("KeyAttrRefCount")->properties[0].array;
        ASSERT_EQ(flags.size(), times.size());
        ASSERT_EQ(data.size(), 4 * times.size());
        ASSERT_EQ(refs, std::vector<double>(times.size(), 1.0));
        for (double f : flags)
            EXPECT_EQ(f, double(0x408)) << "cubic, user slopes";
        // One key per half frame at 30 fps over the clip's second.
        ASSERT_EQ(times.size(), 61u);
        for (std::size_t k = 0; k < times.size(); ++k)
            EXPECT_NEAR(times[k], double(k) / 60.0 * double(io::fbx::kTicksPerSecond), 1.0);
        // Each key's right slope is the next key's left slope when it has one (user tangents, C1).
        for (std::size_t k = 0; k + 1 < times.size(); ++k)
            EXPECT_EQ(data[4 * k + 1], data[4 * (k + 1)]);
        ASSERT_EQ(values.size(), times.size());
        ++cubicCurves;
    }
    EXPECT_GT(cubicCurves, 2u);

    // Between its keys the FBX plays the clip's own curve: each rotating
    // joint's three Euler curves, played as Hermite with the file's slopes at a
    // quarter, half and three quarters of every half frame, give the glTF curve's rotation.
    double worst = 0.0;
    std::size_t checked = 0;
    for (const auto& track : wave.tracks) {
        if (!track.isJoint() || !(track.cubic & io::kRotationChannel))
            continue;
        const std::string name = scene.joints[std::size_t(track.node)].name;
        for (const auto& [child, link] : objects.parents) {
            const auto* node = objects.byId.at(child);
            if (node->name != "AnimationCurveNode" || link.second != "Lcl Rotation" ||
                test::fbxObjectName(*objects.byId.at(link.first)) != name)
                continue;
            Vec3 defaults(0.0);
            for (const auto* p : node->find("Properties70")->all("P"))
                defaults[p->properties[0].text == "d|X" ? 0 : p->properties[0].text == "d|Y" ? 1 : 2] = p->properties[4].number;
            const test::FbxRecord* curves[3] = {nullptr, nullptr, nullptr};
            for (const auto& [curveId, curveLink] : objects.parents)
                if (curveLink.first == child)
                    curves[curveLink.second == "d|X" ? 0 : curveLink.second == "d|Y" ? 1 : 2] = objects.byId.at(curveId);
            auto eulerAt = [&](double time) {
                Vec3 out = defaults;
                for (int axis = 0; axis < 3; ++axis) {
                    if (!curves[axis])
                        continue;
                    const auto& times = curves[axis]->find("KeyTime")->properties[0].array;
                    const auto& values = curves[axis]->find("KeyValueFloat")->properties[0].array;
                    const auto& data = curves[axis]->find("KeyAttrDataFloat")->properties[0].array;
                    out[axis] = values[0];
                    for (std::size_t k = 0; k + 1 < times.size(); ++k) {
                        const double t0 = times[k] / double(io::fbx::kTicksPerSecond);
                        const double t1 = times[k + 1] / double(io::fbx::kTicksPerSecond);
                        if (time >= t0 && time <= t1)
                            out[axis] = io::hermite(values[k], data[4 * k], values[k + 1], data[4 * k + 1], t0, t1, time);
                    }
                }
                return out;
            };
            for (int key = 0; key < 60; ++key)
                for (double f : {0.25, 0.5, 0.75}) {
                    const double time = (key + f) / 60.0;
                    const Vec3 e = glm::radians(eulerAt(time));
                    const Quat fbx = glm::angleAxis(e.z, Vec3(0, 0, 1)) * glm::angleAxis(e.y, Vec3(0, 1, 0)) *
                                     glm::angleAxis(e.x, Vec3(1, 0, 0));
                    const double dot = std::min(1.0, std::abs(glm::dot(fbx, io::trackRotationAt(track, wave.times, time))));
                    worst = std::max(worst, glm::degrees(2.0 * std::acos(dot)));
                    ++checked;
                }
        }
    }
    EXPECT_GT(checked, 180u);
    EXPECT_LT(worst, 1e-3) << "degrees between FBX keys";
}
