// The Unity preset's humanoid map is keyed by what survives a rename (the
// template, the side, the tag), resolved to node keys through the guide: a
// biped whose instances are renamed, by command or in the file, still maps
// every bone and exports with the preset.
#include "TestSupport.h"

#include "edit/GuideEdits.h"
#include "io/ExportRequest.h"
#include "io/GuideFile.h"
#include "io/HumanoidMap.h"
#include "model/Skeleton.h"
#include "rigging/RigBuilder.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <map>

using namespace rs;

namespace {

// Unity bone -> the key of the skeleton joint that carries it; fails the test
// on a bone without one.
std::map<std::string, NodeKey> mappedBones(const model::GuideDocument& guide)
{
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    const auto skeleton = model::extractSkeleton(rig);
    EXPECT_TRUE(skeleton.ok());
    const auto named = io::applyNameMap(rig, *skeleton, io::unityHumanoidMap(guide, rig));
    std::map<std::string, NodeKey> keys;
    for (const model::SkeletonJoint& joint : named.joints)
        if (joint.node != model::kNoNode)
            keys[joint.name] = rig.nodes[joint.node].key;
    for (const io::HumanoidBone& bone : io::unityHumanoidBones(guide, rig))
        EXPECT_TRUE(keys.count(bone.bone)) << bone.bone << " wanted " << bone.wanted;
    std::map<std::string, NodeKey> out;
    for (const io::HumanoidBone& bone : io::unityHumanoidBones(guide, rig))
        if (keys.count(bone.bone))
            out[bone.bone] = keys[bone.bone];
    return out;
}

// Exports `guide` with the Unity preset as the CLI and the editor do, and
// returns the glTF's node names.
std::vector<std::string> exportedNames(const model::GuideDocument& guide, const std::string& file)
{
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    io::ExportRequest request;
    request.path = test::temporaryPath(file);
    request.preset = io::ExportPreset::Unity;
    const Diagnostics report = io::runExport(guide, rig, {}, request);
    EXPECT_FALSE(hasErrors(report)) << formatAll(report);
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, request.path)) << error;
    std::vector<std::string> names;
    for (const auto& node : model.nodes)
        names.push_back(node.name);
    return names;
}

} // namespace

TEST(HumanoidMap, TheBipedMapsAllFiftyTwoBonesToTheirTemplatesTags)
{
    const model::GuideDocument guide = test::loadSample("biped");
    const auto bones = mappedBones(guide);
    EXPECT_EQ(bones.size(), 52u); // 6 of the spine and neck, 23 on each side
    const model::InstanceId spine = guide.instanceNamed("spine")->id, arm = guide.instanceNamed("arm")->id;
    EXPECT_EQ(bones.at("Hips"), (NodeKey{spine, "", "skin.0"}));
    EXPECT_EQ(bones.at("RightHand"), (NodeKey{arm, "R", "skin.limb.2"}));
    EXPECT_EQ(bones.at("LeftThumbProximal"), (NodeKey{guide.instanceNamed("thumb")->id, "L", "skin.0"}));
    EXPECT_EQ(bones.at("LeftLittleDistal"), (NodeKey{guide.instanceNamed("pinky")->id, "L", "skin.3"}));
}

TEST(HumanoidMap, RenamingInstancesByCommandKeepsEveryBoneAndTheUnityExport)
{
    model::GuideDocument guide = test::loadSample("biped");
    const auto before = mappedBones(guide);
    edit::History history(guide);
    for (const auto& [from, to] : {std::pair{"spine", "torso"}, {"arm", "limb"}, {"index", "pointer"}, {"leg", "hind"}})
        ASSERT_TRUE(test::succeeded(edit::renameInstance(history, guide.instanceNamed(from)->id, to))) << from;
    EXPECT_EQ(mappedBones(guide), before);
    const auto names = exportedNames(guide, "unity-renamed.glb");
    for (const auto& [bone, key] : before)
        EXPECT_NE(std::find(names.begin(), names.end(), bone), names.end()) << bone;
}

TEST(HumanoidMap, RenamingInstancesInTheGuideFileKeepsEveryBoneAndTheUnityExport)
{
    const model::GuideDocument guide = test::loadSample("biped");
    std::string text = io::writeGuideText(guide);
    for (const auto& [from, to] : {std::pair{"    name: spine\n", "    name: torso\n"}, {"    name: middle\n", "    name: long\n"}}) {
        const auto at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, std::string(from).size(), to); // what a rigger does in a text editor
    }
    auto renamed = io::readGuideText(text, "renamed.yml");
    ASSERT_TRUE(renamed.ok()) << formatAll(renamed.diagnostics());
    ASSERT_TRUE(renamed->instanceNamed("torso"));
    EXPECT_EQ(mappedBones(*renamed), mappedBones(guide));
    const auto names = exportedNames(*renamed, "unity-file-renamed.glb");
    for (const auto& [bone, key] : mappedBones(guide))
        EXPECT_NE(std::find(names.begin(), names.end(), bone), names.end()) << bone;
}
