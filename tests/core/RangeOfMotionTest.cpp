// Issue 21 items 3 and 4: a range of motion a rigger would keep (from the test
// pose, FK exercised in FK, nothing stretched, no dead segments, no constant
// channels, keys on a frame grid, named ranges) and presets that tell the truth.
#include "core/TestSupport.h"
#include "eval/RigProgram.h"
#include "io/RangeOfMotion.h"
#include "io/RigExport.h"
#include "model/Skeleton.h"
#include "rigging/RigBuilder.h"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <variant>

using namespace rs;

namespace {

const model::Rig& sample(const std::string& name)
{
    static std::map<std::string, model::Rig> rigs;
    auto found = rigs.find(name);
    if (found == rigs.end())
        found = rigs.emplace(name, rigging::buildRig(test::loadSample(name), test::builtinTemplates())).first;
    return found->second;
}

io::ExportScene romScene(const model::Rig& rig, io::ExportOptions options = {})
{
    options.rangeOfMotion = true;
    auto prepared = io::prepareExport(rig, options);
    EXPECT_TRUE(prepared.scene) << formatAll(prepared.report);
    return prepared.scene ? *prepared.scene : io::ExportScene{};
}

Mat4 trs(const Vec3& t, const Quat& r, const Vec3& s)
{
    return translationMatrix(t) * Mat4(glm::mat3_cast(r)) * glm::scale(Mat4(1.0), s);
}

// Every joint's world matrix at every key of the clip (a joint without a track keeps its written transform).
std::vector<std::vector<Mat4>> jointWorlds(const io::ExportScene& scene, const io::ExportClip& clip)
{
    std::vector<const io::ExportTrack*> trackOf(scene.joints.size(), nullptr);
    for (const auto& track : clip.tracks)
        if (track.isJoint())
            trackOf[std::size_t(track.node)] = &track;
    std::vector<std::vector<Mat4>> out(clip.times.size(), std::vector<Mat4>(scene.joints.size()));
    for (std::size_t k = 0; k < clip.times.size(); ++k)
        for (std::size_t j = 0; j < scene.joints.size(); ++j) {
            const auto* t = trackOf[j];
            const Mat4 local = t ? trs(t->translations[k], t->rotations[k], t->scales[k]) : scene.joints[j].poseLocal;
            const int parent = scene.joints[j].parent;
            out[k][j] = parent < 0 ? local : out[k][std::size_t(parent)] * local;
        }
    return out;
}

// The largest relative lengthening of a joint's offset from its parent over the clip.
double worstStretch(const io::ExportScene& scene, const io::ExportClip& clip)
{
    double worst = 0.0;
    for (const auto& track : clip.tracks) {
        if (!track.isJoint() || scene.joints[std::size_t(track.node)].parent < 0)
            continue;
        const double rest = glm::length(translationOf(scene.joints[std::size_t(track.node)].bindLocal));
        if (rest < 1e-3)
            continue;
        for (const Vec3& t : track.translations)
            worst = std::max(worst, glm::length(t) / rest - 1.0);
    }
    return worst;
}

// The exporter's rule for a still channel: every key within 1e-6 of the
// first on each axis (metres, or scale factor).
bool farther(const Vec3& a, const Vec3& b)
{
    return std::abs(a.x - b.x) > 1e-6 || std::abs(a.y - b.y) > 1e-6 || std::abs(a.z - b.z) > 1e-6;
}

bool changes(const io::ExportTrack& track, unsigned bit)
{
    for (std::size_t k = 1; k < track.translations.size(); ++k) {
        if (bit == io::kTranslationChannel && farther(track.translations[k], track.translations[0]))
            return true;
        if (bit == io::kRotationChannel && std::abs(glm::dot(track.rotations[k], track.rotations[0])) < 1.0 - 1e-12)
            return true;
        if (bit == io::kScaleChannel && farther(track.scales[k], track.scales[0]))
            return true;
    }
    return false;
}

} // namespace

TEST(RangeOfMotion, EverySampleMovesEveryExercisedControlWithoutStretchOnTheFrameGrid)
{
    for (const std::string name : {"biped", "quadruped", "prop", "vehicle", "robot", "cart", "strider"}) {
        SCOPED_TRACE(name);
        const model::Rig& rig = sample(name);
        const io::ExportScene scene = romScene(rig);
        ASSERT_FALSE(scene.clips.empty());
        std::set<std::string> names;
        for (const io::ExportClip& clip : scene.clips) {
            SCOPED_TRACE(clip.name);
            EXPECT_EQ(clip.framesPerSecond, 30.0);
            for (double t : clip.times)
                EXPECT_NEAR(t * 30.0, std::round(t * 30.0), 1e-9) << "a key off the 30 fps grid at " << t;
            EXPECT_LE(worstStretch(scene, clip), 0.01);

            // One named range per exercised controller; each moves some joint.
            ASSERT_FALSE(clip.markers.empty());
            const auto worlds = jointWorlds(scene, clip);
            for (const auto& marker : clip.markers) {
                EXPECT_TRUE(names.insert(marker.name).second) << marker.name;
                ASSERT_TRUE(rig.findPath(marker.control)) << marker.control;
                EXPECT_EQ(rig.nodes[*rig.findPath(marker.control)].kind, model::RigNodeKind::Controller);
                double moved = 0.0;
                for (std::size_t k = 0; k < clip.times.size(); ++k)
                    if (clip.times[k] >= marker.start - 1e-9 && clip.times[k] <= marker.end + 1e-9)
                        for (std::size_t j = 0; j < scene.joints.size(); ++j) {
                            const auto& before = worlds[std::size_t(std::lround(marker.start * 3.0))][j]; // keys 1/3 s apart
                            moved = std::max(moved, maxAbsDifference(worlds[k][j], before));
                        }
                EXPECT_GT(moved, 1e-3) << marker.name << " moves no joint (a dead segment)";
        }

        // A written channel changes; one left out equals the node's transform.
        for (const auto& track : clip.tracks) {
            EXPECT_TRUE(track.animated | track.held);
            for (unsigned bit : {io::kTranslationChannel, io::kRotationChannel, io::kScaleChannel})
                EXPECT_EQ((track.animated & bit) != 0, changes(track, bit)) << "track of joint " << track.node;
        }
        }
    }
}

// Engines keep clip time in 32-bit floats (Godot 3 bakes at 15 fps by adding
// float(1/15) to a float time: 1.9 ms off 170 s into a clip), so the default
// layout splits a long range at controller boundaries into clips of a minute
// at most, each from time 0 on the start pose, every controller's range kept.
TEST(RangeOfMotion, LongRangesAreSplitIntoClipsOfAMinuteAtMostAtControllerBoundaries)
{
    const model::Rig& rig = sample("biped");
    const io::ExportScene scene = romScene(rig);
    io::ExportOptions perControl;
    perControl.clipPerControl = true;
    const std::size_t controllers = romScene(rig, perControl).clips.size();
    ASSERT_GT(scene.clips.size(), 1u) << "the biped's range lasts minutes";
    std::size_t markers = 0;
    const auto worlds0 = jointWorlds(scene, scene.clips.front());
    for (std::size_t c = 0; c < scene.clips.size(); ++c) {
        const io::ExportClip& clip = scene.clips[c];
        EXPECT_EQ(clip.name, "range_of_motion_" + std::to_string(c + 1));
        EXPECT_EQ(clip.times.front(), 0.0);
        EXPECT_LE(clip.times.back(), 60.0 + 1e-9) << clip.name;
        EXPECT_DOUBLE_EQ(clip.markers.front().start, 0.0);
        EXPECT_DOUBLE_EQ(clip.markers.back().end, clip.times.back());
        markers += clip.markers.size();
        const auto worlds = jointWorlds(scene, clip);
        double first = 0.0, last = 0.0;
        for (std::size_t j = 0; j < scene.joints.size(); ++j) {
            first = std::max(first, maxAbsDifference(worlds.front()[j], worlds0.front()[j]));
            last = std::max(last, maxAbsDifference(worlds.back()[j], worlds0.front()[j]));
        }
        EXPECT_LT(first, 1e-5) << clip.name << " starts on the start pose";
        EXPECT_LT(last, 1e-5) << clip.name << " ends on it";
    }
    EXPECT_EQ(markers, controllers);
    EXPECT_EQ(romScene(sample("prop")).clips.size(), 1u) << "a short range stays one clip";
    EXPECT_EQ(romScene(sample("prop")).clips[0].name, "range_of_motion");
}

TEST(RangeOfMotion, ExercisesFkControlsInFkAndSwitchesBackAfter)
{
    const model::Rig& rig = sample("biped");
    auto program = eval::RigProgram::compile(rig);
    ASSERT_TRUE(program);
    const eval::Pose start = program->channels().defaults();
    const io::RangeOfMotionPlan plan = io::planRangeOfMotion(rig, *program, start);
    // Every FK control of a switched chain: its keys have the chain's weight on FK, and the part ends on the start pose.
    const auto skeleton = model::extractSkeleton(rig);
    eval::EvalState before = program->makeState(), after = program->makeState();
    std::size_t checked = 0, switched = 0;
    for (const auto& c : rig.constraints) {
        const auto* blend = std::get_if<model::BlendConstraint>(&c.settings);
        if (!blend || rig.nodes[c.targets[0]].kind != model::RigNodeKind::Controller)
            continue;
        const int weight = *program->channels().find(blend->weight);
        const auto part = std::find_if(plan.parts.begin(), plan.parts.end(), [&](const auto& p) { return p.control == c.targets[0]; });
        ASSERT_NE(part, plan.parts.end()) << rig.nodes[c.targets[0]].path << " is not exercised";
        for (std::size_t k = part->firstKey + 1; k < part->lastKey; ++k)
            EXPECT_EQ(plan.keys[k][std::size_t(weight)], 0.0) << rig.nodes[c.targets[0]].path;
        EXPECT_EQ(plan.keys[part->lastKey], start);
        ++checked;
        // The switch to FK moves no joint: FK was matched to where the chain was.
        if (start[std::size_t(weight)] == 0.0)
            continue; // already in FK: no switch
        ++switched;
        program->evaluate(plan.keys[part->firstKey], before);
        program->evaluate(plan.keys[part->firstKey + 1], after);
        for (const auto& joint : skeleton->joints)
            EXPECT_LT(glm::length(translationOf(after.worldMatrix(joint.node)) - translationOf(before.worldMatrix(joint.node))), 1e-6)
                << rig.nodes[c.targets[0]].path << " switching moves " << joint.name;
    }
    EXPECT_GE(checked, 10u);
    EXPECT_GE(switched, 8u) << "the biped's arms and legs start in IK";
}

TEST(RangeOfMotion, StartsFromTheGuidesTestPoseAndSettings)
{
    model::GuideDocument guide = test::loadSample("biped");
    const model::Rig& rig = sample("biped");
    const auto& fk = test::node(rig, "arm.L::ctrls.fk.1");
    const auto& settings = test::node(rig, "arm.L::ctrls.switch");
    model::PoseValues pose;
    pose[fk.key]["rz"] = 40.0;
    pose[settings.key]["ik_blend"] = 0.0; // the arm in FK, bent
    io::ExportOptions options;
    options.testPose = &pose;
    const io::ExportScene scene = romScene(rig, options);
    ASSERT_FALSE(scene.clips.empty());
    const auto& clip = scene.clips[0];

    auto program = eval::RigProgram::compile(rig);
    ASSERT_TRUE(program);
    eval::EvalState state = program->makeState();
    program->evaluate(eval::poseFromValues(rig, program->channels(), pose), state);
    const auto worlds = jointWorlds(scene, clip);
    const auto skeleton = model::extractSkeleton(rig);
    double worst = 0.0;
    for (std::size_t j = 0; j < scene.joints.size(); ++j)
        worst = std::max(worst, maxAbsDifference(worlds.front()[j], state.worldMatrix(skeleton->joints[j].node)));
    EXPECT_LT(worst, 1e-5) << "the first key is the test pose";
    EXPECT_LT(maxAbsDifference(worlds.back().back(), worlds.front().back()), 1e-5) << "and so is the last";
    EXPECT_LE(worstStretch(scene, clip), 0.01);
}

TEST(RangeOfMotion, FramesPerSecondAndOneClipPerControlAreOptions)
{
    io::ExportOptions options;
    options.framesPerSecond = 24.0;
    options.clipPerControl = true;
    const io::ExportScene scene = romScene(sample("prop"), options);
    ASSERT_GT(scene.clips.size(), 1u);
    for (const auto& clip : scene.clips) {
        EXPECT_EQ(clip.name.rfind("rom_", 0), 0u) << clip.name;
        EXPECT_EQ(clip.times.front(), 0.0);
        for (double t : clip.times)
            EXPECT_NEAR(t * 24.0, std::round(t * 24.0), 1e-9);
        ASSERT_EQ(clip.markers.size(), 1u);
        EXPECT_EQ("rom_" + clip.markers[0].name, clip.name);
    }
}

TEST(RangeOfMotion, TheGlbWritesOnlyChannelsThatChangeWithMarkersInExtras)
{
    io::ExportOptions options;
    options.rangeOfMotion = true;
    const std::string path = test::temporaryPath("rom-channels.glb");
    ASSERT_TRUE(io::exportRig(sample("biped"), path, options).empty());
    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&m, &error, &warning, path)) << error;
    ASSERT_GT(m.animations.size(), 1u);
    std::size_t markers = 0;
    for (const auto& animation : m.animations) {
        for (const auto& channel : animation.channels) {
            const auto& sampler = animation.samplers[std::size_t(channel.sampler)];
            const auto& output = m.accessors[std::size_t(sampler.output)];
            const auto& view = m.bufferViews[std::size_t(output.bufferView)];
            const float* values = reinterpret_cast<const float*>(m.buffers[0].data.data() + view.byteOffset + output.byteOffset);
            const std::size_t width = channel.target_path == "rotation" ? 4 : 3;
            bool varies = false;
            for (std::size_t i = width; i < output.count * width; ++i)
                varies = varies || values[i] != values[i % width];
            EXPECT_TRUE(varies || output.count == 1) << "a constant " << channel.target_path << " channel of node "
                                                     << m.nodes[std::size_t(channel.target_node)].name;
    }
    ASSERT_TRUE(animation.extras.Has("markers"));
    markers += animation.extras.Get("markers").ArrayLen();
    EXPECT_EQ(animation.extras.Get("fps").GetNumberAsDouble(), 30.0);
    }
    EXPECT_GT(markers, 10u);
}

TEST(RigExport, UnityPresetRefusesTheQuadrupedNamingTheBonesItCannotMapUnlessForced)
{
    const model::GuideDocument quadruped = test::loadSample("quadruped"), biped = test::loadSample("biped");
    io::ExportOptions options;
    options.preset = io::ExportPreset::Unity;
    auto refused = io::prepareExport(sample("quadruped"), options);
    EXPECT_NE(formatAll(refused.report).find("found through the rig's guide"), std::string::npos) << "no guide, no humanoid map";
    options.guide = &quadruped;
    refused = io::prepareExport(sample("quadruped"), options);
    EXPECT_FALSE(refused.scene);
    const std::string message = formatAll(refused.report);
    EXPECT_NE(message.find("LeftUpperArm (no left arm.limb instance)"), std::string::npos) << message;
    EXPECT_NE(message.find("--force"), std::string::npos);

    options.force = true;
    const std::string path = test::temporaryPath("unity-quadruped.glb");
    const Diagnostics forced = io::exportRig(sample("quadruped"), path, options);
    EXPECT_FALSE(hasErrors(forced)) << formatAll(forced);
    EXPECT_NE(formatAll(forced).find("exported anyway (forced)"), std::string::npos);
    EXPECT_TRUE(std::filesystem::exists(path));

    // The biped maps every bone; glTF is unaffected on the quadruped.
    options.force = false;
    options.guide = &biped;
    EXPECT_TRUE(io::prepareExport(sample("biped"), options).scene);
    EXPECT_TRUE(io::prepareExport(sample("quadruped"), io::ExportOptions{}).scene);
}
