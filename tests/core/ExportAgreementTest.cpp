// glTF and FBX of one rig and clip agree between keys in Assimp (issue 21 item
// 2; three.js and Blender make the same comparison in tests/tools,
// compare-three.mjs and blender-compare.py, ctest Export.<sample>.Three /
// .BlenderMidKeys). Both files are read back with Assimp and played the way a
// player plays Assimp's keys (translations and scales linearly, rotations by
// slerp, aiQuaternion::Interpolate); every joint's world position is sampled
// at 4x the key rate (each interval between two key times cut in four).
//
// Tolerance 1e-4 m: both files store floats (glTF quaternions, FBX Euler
// degrees), about 1e-7 relative, which makes a few micrometres over a chain
// of ten joints a metre and a half long; Blender's single precision maths
// adds about as much (its comparison is worst at 3e-5 m).
#include "core/TestSupport.h"
#include "io/RigExport.h"
#include "rigging/RigBuilder.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

using namespace rs;

namespace {

constexpr double kTolerance = 1e-4; // metres

// One file as Assimp gives it, played like a player plays it.
class AssimpPlayer {
public:
    explicit AssimpPlayer(const std::string& path)
    {
        m_scene = m_importer.ReadFile(path, 0);
        if (!m_scene)
            return;
        collect(m_scene->mRootNode);
        play(0);
    }
    // Plays the file's `index`-th clip (none: every node at its transform).
    void play(unsigned index)
    {
        m_channels.clear();
        if (index >= m_scene->mNumAnimations)
            return;
        const aiAnimation& clip = *m_scene->mAnimations[index];
        m_ticksPerSecond = clip.mTicksPerSecond > 0.0 ? clip.mTicksPerSecond : 1.0;
        for (unsigned c = 0; c < clip.mNumChannels; ++c)
            m_channels[clip.mChannels[c]->mNodeName.C_Str()] = clip.mChannels[c];
    }
    const aiScene* scene() const { return m_scene; }
    const aiNode* node(const std::string& name) const
    {
        const auto it = m_nodes.find(name);
        return it == m_nodes.end() ? nullptr : it->second;
    }
    // The times (seconds) of the clip's keys, all channels merged.
    std::vector<double> keyTimes() const
    {
        std::set<double> times;
        auto add = [&](double ticks) { times.insert(std::round(ticks / m_ticksPerSecond * 1e6) / 1e6); };
        for (const auto& [name, channel] : m_channels) {
            for (unsigned k = 0; k < channel->mNumPositionKeys; ++k)
                add(channel->mPositionKeys[k].mTime);
            for (unsigned k = 0; k < channel->mNumRotationKeys; ++k)
                add(channel->mRotationKeys[k].mTime);
            for (unsigned k = 0; k < channel->mNumScalingKeys; ++k)
                add(channel->mScalingKeys[k].mTime);
        }
        return {times.begin(), times.end()};
    }
    // The world positions of `nodes` at `seconds`.
    std::vector<Vec3> worldPositions(const std::vector<const aiNode*>& nodes, double seconds) const
    {
        std::map<const aiNode*, aiMatrix4x4> worlds;
        std::vector<Vec3> out;
        for (const aiNode* node : nodes) {
            const aiMatrix4x4& world = worldOf(node, seconds * m_ticksPerSecond, worlds);
            out.emplace_back(world.a4, world.b4, world.c4);
        }
        return out;
    }

private:
    const aiMatrix4x4& worldOf(const aiNode* node, double ticks, std::map<const aiNode*, aiMatrix4x4>& worlds) const
    {
        if (const auto it = worlds.find(node); it != worlds.end())
            return it->second;
        aiMatrix4x4 world = local(node, ticks);
        if (node->mParent)
            world = worldOf(node->mParent, ticks, worlds) * world;
        return worlds[node] = world;
    }
    void collect(const aiNode* node)
    {
        m_nodes.emplace(node->mName.C_Str(), node);
        for (unsigned c = 0; c < node->mNumChildren; ++c)
            collect(node->mChildren[c]);
    }
    // The key pair around `ticks` and the fraction between them (clamped at the ends).
    template <typename Key>
    static std::pair<const Key*, std::pair<const Key*, double>> around(const Key* keys, unsigned count, double ticks)
    {
        if (count == 1 || ticks <= keys[0].mTime)
            return {&keys[0], {&keys[0], 0.0}};
        const Key* next = std::lower_bound(keys, keys + count, ticks, [](const Key& k, double t) { return k.mTime < t; });
        if (next == keys + count)
            return {&keys[count - 1], {&keys[count - 1], 0.0}};
        const Key* a = next - 1;
        return {a, {next, (ticks - a->mTime) / (next->mTime - a->mTime)}};
    }
    aiMatrix4x4 local(const aiNode* node, double ticks) const
    {
        const auto it = m_channels.find(node->mName.C_Str());
        if (it == m_channels.end())
            return node->mTransformation;
        const aiNodeAnim& channel = *it->second;
        aiVector3D rest_s, rest_t;
        aiQuaternion rest_r;
        node->mTransformation.Decompose(rest_s, rest_r, rest_t);
        aiVector3D t = rest_t, s = rest_s;
        aiQuaternion r = rest_r;
        if (channel.mNumPositionKeys > 0) {
            const auto [a, next] = around(channel.mPositionKeys, channel.mNumPositionKeys, ticks);
            t = a->mValue + (next.first->mValue - a->mValue) * ai_real(next.second);
        }
        if (channel.mNumScalingKeys > 0) {
            const auto [a, next] = around(channel.mScalingKeys, channel.mNumScalingKeys, ticks);
            s = a->mValue + (next.first->mValue - a->mValue) * ai_real(next.second);
        }
        if (channel.mNumRotationKeys > 0) {
            const auto [a, next] = around(channel.mRotationKeys, channel.mNumRotationKeys, ticks);
            aiQuaternion::Interpolate(r, a->mValue, next.first->mValue, ai_real(next.second));
            r.Normalize();
        }
        return aiMatrix4x4(s, r, t);
    }

    Assimp::Importer m_importer;
    const aiScene* m_scene = nullptr;
    std::map<std::string, const aiNode*> m_nodes;
    std::map<std::string, const aiNodeAnim*> m_channels;
    double m_ticksPerSecond = 1.0;
};

class ExportAgreement : public testing::TestWithParam<std::string> {};

} // namespace

TEST_P(ExportAgreement, AssimpPlaysTheGlbAndTheFbxAlikeBetweenKeys)
{
    const model::Rig rig = rigging::buildRig(test::loadSample(GetParam()), test::builtinTemplates());
    io::ExportOptions options;
    options.rangeOfMotion = true;
    const std::string glb = test::temporaryPath(GetParam() + "-agree.glb");
    const std::string fbx = test::temporaryPath(GetParam() + "-agree.fbx");
    ASSERT_FALSE(hasErrors(io::exportRig(rig, glb, options)));
    ASSERT_FALSE(hasErrors(io::exportRig(rig, fbx, options)));
    AssimpPlayer gltf(glb), other(fbx);
    ASSERT_NE(gltf.scene(), nullptr);
    ASSERT_NE(other.scene(), nullptr);
    const auto prepared = io::prepareExport(rig, options);
    ASSERT_TRUE(prepared.scene);
    // One animation per clip (the range of motion in clips of a minute), in the scene's order.
    ASSERT_EQ(gltf.scene()->mNumAnimations, prepared.scene->clips.size());
    ASSERT_EQ(other.scene()->mNumAnimations, prepared.scene->clips.size());
    std::vector<const aiNode*> gltfJoints, fbxJoints;
    for (const auto& joint : prepared.scene->joints) {
        gltfJoints.push_back(gltf.node(joint.name));
        fbxJoints.push_back(other.node(joint.name));
        ASSERT_NE(gltfJoints.back(), nullptr) << joint.name << " in the glb";
        ASSERT_NE(fbxJoints.back(), nullptr) << joint.name << " in the FBX";
    }
    double worst = 0.0, travel = 0.0;
    std::string where;
    std::vector<Vec3> start;
    std::size_t keys = 0;
    for (unsigned c = 0; c < prepared.scene->clips.size(); ++c) {
        const io::ExportClip& clip = prepared.scene->clips[c];
        EXPECT_NE(std::string(other.scene()->mAnimations[c]->mName.C_Str()).find(clip.name), std::string::npos)
            << other.scene()->mAnimations[c]->mName.C_Str();
        gltf.play(c);
        other.play(c);
        const std::vector<double> times = gltf.keyTimes();
        ASSERT_GT(times.size(), 10u);
        EXPECT_NEAR(times.back(), clip.times.back(), 1e-4);
        keys += times.size();
        for (std::size_t k = 0; k + 1 < times.size(); ++k)
            for (int q = 0; q < 4 || (q == 4 && k + 2 == times.size()); ++q) {
                const double t = times[k] + (times[k + 1] - times[k]) * q / 4.0;
                const std::vector<Vec3> as = gltf.worldPositions(gltfJoints, t), bs = other.worldPositions(fbxJoints, t);
                for (std::size_t j = 0; j < as.size(); ++j) {
                    const Vec3 a = as[j], b = bs[j];
                    if (start.size() < as.size())
                        start.push_back(a);
                    travel = std::max(travel, glm::length(a - start[j]));
                    if (const double d = glm::length(a - b); d > worst) {
                        worst = d;
                        where = prepared.scene->joints[j].name + " at " + std::to_string(t) + " s of " + clip.name;
                    }
                }
            }
    }
    EXPECT_GT(travel, 0.1) << "the clip moves the joints";
    EXPECT_LE(worst, kTolerance) << where;
    std::printf("%zu clips, %zu key times, %zu joints, joints travel up to %.3f m, worst %.2e m (%s)\n",
                prepared.scene->clips.size(), keys, gltfJoints.size(),
                travel, worst, where.c_str());
}

INSTANTIATE_TEST_SUITE_P(Samples, ExportAgreement, testing::Values("biped", "quadruped", "prop", "vehicle", "robot", "claw", "cart", "strider"),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });
