// What a bone-inferring importer (Blender's FBX importer) makes of an export:
// a Y-up file's root joints are turned into a Z-up frame so the hips are not
// connected to the root (their location curves would be ignored), world
// transforms unchanged at every time; the rigger's joints whose child lies on
// their +Y axis and translates are named (io/BoneInference.h). Blender itself
// checks the samples: ctest Export.<sample>.BlenderMidKeys.*.
#include "core/TestSupport.h"
#include "io/BoneInference.h"
#include "io/ExportScene.h"
#include "io/RigExport.h"
#include "rigging/RigBuilder.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <optional>

using namespace rs;

namespace {

// World matrices of every joint at `time` of the scene's first clip (bind
// pose, written node transforms, when there is no clip).
std::vector<Mat4> jointWorlds(const io::ExportScene& scene, std::optional<double> time)
{
    std::vector<Mat4> local(scene.joints.size());
    for (std::size_t j = 0; j < scene.joints.size(); ++j)
        local[j] = scene.joints[j].poseLocal;
    if (time && !scene.clips.empty()) {
        const io::ExportClip& clip = scene.clips.front();
        for (const io::ExportTrack& track : clip.tracks)
            if (track.isJoint())
                local[std::size_t(track.node)] = translationMatrix(io::trackTranslationAt(track, clip.times, *time)) *
                                                 Mat4(glm::mat3_cast(io::trackRotationAt(track, clip.times, *time))) *
                                                 glm::scale(Mat4(1.0), io::trackScaleAt(track, clip.times, *time));
    }
    std::vector<Mat4> world(local.size());
    for (std::size_t j = 0; j < local.size(); ++j)
        world[j] = scene.joints[j].parent < 0 ? local[j] : world[std::size_t(scene.joints[j].parent)] * local[j];
    return world;
}

io::ExportScene bipedWithRangeOfMotion()
{
    static const model::Rig rig = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    io::ExportOptions options;
    options.rangeOfMotion = true;
    auto prepared = io::prepareExport(rig, options);
    EXPECT_TRUE(prepared.scene);
    return std::move(*prepared.scene);
}

} // namespace

TEST(BoneInference, AYUpRootIsTurnedSoItsYAxisMissesTheHipsAndEveryJointStaysPut)
{
    const io::ExportScene scene = bipedWithRangeOfMotion();
    ASSERT_EQ(scene.joints.front().name, "sk_world_root");
    ASSERT_EQ(scene.joints[1].name, "sk_spine_hips");
    // Before: an identity root whose +Y points straight at the hips, which translate in the clip.
    ASSERT_EQ(io::connectedMovingJoints(scene), std::vector<int>{1});

    const io::ExportScene out = io::converted(scene, io::conventionFor(io::ExportPreset::Gltf, true));
    EXPECT_TRUE(io::connectedMovingJoints(out).empty());
    const Mat4& root = out.joints.front().bindWorld;
    EXPECT_LT(glm::length(Vec3(root[2]) - Vec3(0, 1, 0)), 1e-12) << "the root's Z is up";
    EXPECT_LT(glm::length(Vec3(root[1]) - Vec3(0, 0, -1)), 1e-12) << "its Y points back";
    for (std::size_t j = 0; j < scene.joints.size(); ++j) {
        EXPECT_LT(glm::length(translationOf(out.joints[j].bindWorld) - translationOf(scene.joints[j].bindWorld)), 1e-12);
        if (j > 0) {
            EXPECT_LT(maxAbsDifference(out.joints[j].bindWorld, scene.joints[j].bindWorld), 1e-12) << scene.joints[j].name;
        }
    }
    const io::ExportClip& clip = scene.clips.front();
    ASSERT_GT(clip.times.size(), 10u);
    double worst = 0.0;
    for (std::size_t k = 0; k + 1 < clip.times.size(); k += 7)
        for (double time : {clip.times[k], 0.5 * (clip.times[k] + clip.times[k + 1])}) {
            const auto before = jointWorlds(scene, time), after = jointWorlds(out, time);
            for (std::size_t j = 0; j < before.size(); ++j)
                worst = std::max(worst, glm::length(translationOf(after[j]) - translationOf(before[j])));
        }
    EXPECT_LT(worst, 1e-9) << "every joint plays where it did, at keys and between them";
}

TEST(BoneInference, AZUpFileKeepsItsRootFrame)
{
    io::ExportScene scene = bipedWithRangeOfMotion();
    const io::ExportScene out = io::converted(scene, io::conventionFor(io::ExportPreset::Unreal, true));
    // Conjugated into Z-up, the identity root stays identity: its +Y is horizontal there.
    EXPECT_LT(maxAbsDifference(Mat4(Mat3(out.joints.front().bindWorld)), Mat4(1.0)), 1e-12);
    EXPECT_TRUE(io::connectedMovingJoints(out).empty());
}

TEST(BoneInference, AJointOnItsParentsYAxisThatTranslatesIsNamedAndTheFbxExportWarns)
{
    // A chain built with the rigger's identity frames going up: each child on its parent's +Y.
    model::GuideDocument guide = test::loadSample("prop");
    model::TemplateInstance* antenna = guide.instance(guide.instanceNamed("antenna")->id);
    ASSERT_NE(antenna, nullptr);
    antenna->options.erase("orient"); // copy: the guides' own (identity) frames
    for (auto& joint : antenna->joints) {
        if (joint.parent == kNoId) {
            joint.local.rotateDegrees = Vec3(0.0);
        } else {
            joint.local.translate = Vec3(0.0, 0.1, 0.0);
        }
    }
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    io::ExportOptions options;
    options.rangeOfMotion = true;
    const Diagnostics fbx = io::exportRig(rig, test::temporaryPath("bone-inference-prop.fbx"), options);
    const Diagnostics glb = io::exportRig(rig, test::temporaryPath("bone-inference-prop.glb"), options);
    EXPECT_FALSE(hasErrors(fbx)) << formatAll(fbx);
    int warned = 0;
    for (const Diagnostic& d : fbx)
        if (d.message.find("Blender's FBX importer will connect joint 'sk_antenna") != std::string::npos) {
            ++warned;
            EXPECT_EQ(d.subject.kind, Subject::Kind::Node) << "the warning selects the joint";
        }
    EXPECT_EQ(warned, 3) << formatAll(fbx); // antenna 2, 3 and 4
    for (const Diagnostic& d : glb) {
        EXPECT_EQ(d.message.find("Blender's FBX importer"), std::string::npos) << "glTF importers infer no connection";
    }

    // The sample's antenna is oriented along the chain (orient auto, X up): nothing to say.
    const model::Rig sample = rigging::buildRig(test::loadSample("prop"), test::builtinTemplates());
    const Diagnostics clean = io::exportRig(sample, test::temporaryPath("bone-inference-sample.fbx"), options);
    EXPECT_TRUE(clean.empty()) << formatAll(clean);
}
