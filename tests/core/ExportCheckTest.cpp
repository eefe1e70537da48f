// The pre-export validator: clean samples pass, broken skeletons are reported
// per node, the export refuses them unless forced, and safe renames fix names.
#include "rigging/RigBuilder.h"
#include "core/TestSupport.h"
#include "io/ExportCheck.h"
#include "io/RigExport.h"
#include "io/HumanoidMap.h"
#include "io/NameMap.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

using namespace rs;

namespace {

model::Rig sampleRig(const std::string& name) { return rigging::buildRig(test::loadSample(name), test::builtinTemplates()); }

// The biped with two naming problems and one non-uniformly scaled joint.
model::Rig brokenBiped()
{
    model::Rig rig = sampleRig("biped");
    rig.nodes[*rig.findPath("arm.L::skin.limb.0")].name = "upper arm.L"; // not engine-safe
    rig.nodes[*rig.findPath("arm.L::skin.limb.1")].name = "SK_ARM1_R";   // sk_arm1_R's name, ignoring case
    auto& hand = rig.nodes[*rig.findPath("arm.L::skin.limb.2")];
    hand.worldMatrix = hand.worldMatrix * glm::scale(Mat4(1.0), Vec3(1.0, 2.0, 1.0));
    return rig;
}

} // namespace

TEST(ExportCheck, TheSamplesExportCleanly)
{
    for (const char* sample : {"biped", "quadruped", "prop", "face", "vehicle", "robot", "claw", "cart", "strider"}) {
        const model::Rig rig = sampleRig(sample);
        auto skeleton = model::extractSkeleton(rig);
        ASSERT_TRUE(skeleton.ok()) << sample;
        const auto check = io::checkSkeleton(rig, *skeleton);
        EXPECT_TRUE(check.problems.empty()) << sample << ": " << check.problems.front().format();
        EXPECT_TRUE(check.renames.empty());
    }
}

TEST(ExportCheck, ReportsEachProblemWithItsNodeAndOffersSafeRenames)
{
    const model::Rig rig = brokenBiped();
    const auto skeleton = model::extractSkeleton(rig).take();
    const auto check = io::checkSkeleton(rig, skeleton);
    ASSERT_TRUE(check.hasErrors());
    std::map<std::string, std::string> bySubject;
    for (const auto& d : check.problems)
        if (const auto node = rig.find(d.subject.node); node && d.subject.kind == Subject::Kind::Node)
            bySubject[rig.nodes[*node].path] += d.message + "\n";
    EXPECT_NE(bySubject["arm.L::skin.limb.0"].find("not engine-safe"), std::string::npos);
    EXPECT_NE(bySubject["arm.L::skin.limb.0"].find("safe fix: rename to 'upper_arm_L'"), std::string::npos);
    const std::string clash = bySubject["arm.L::skin.limb.1"] + bySubject["arm.R::skin.limb.0"];
    EXPECT_NE(clash.find("used by another joint (names are compared ignoring case); safe fix: rename to"), std::string::npos)
        << clash;
    EXPECT_NE(bySubject["arm.L::skin.limb.2"].find("non-uniform scale (1.000000, 2.000000, 1.000000)"), std::string::npos);
    // Exactly one of each case-insensitive pair is renamed, to a free name.
    const auto fixed = io::applyRenames(skeleton, check);
    std::set<std::string> names;
    for (const auto& joint : fixed.joints) {
        EXPECT_TRUE(io::isEngineSafeName(joint.name)) << joint.name;
        std::string lower = joint.name;
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        EXPECT_TRUE(names.insert(lower).second) << joint.name;
    }
    const auto recheck = io::checkSkeleton(rig, fixed);
    ASSERT_EQ(recheck.problems.size(), 1u); // only the scale is left: no safe fix changes the rig
    EXPECT_EQ(recheck.problems.front().subject, Subject::ofNode(test::node(rig, "arm.L::skin.limb.2").key));
}

TEST(ExportCheck, TheExportRefusesErrorsUnlessForced)
{
    const model::Rig rig = brokenBiped();
    const std::string path = test::temporaryPath("broken.glb");
    std::filesystem::remove(path);
    auto d = io::exportRig(rig, path, {});
    EXPECT_TRUE(hasErrors(d));
    EXPECT_FALSE(std::filesystem::exists(path));
    EXPECT_EQ(d.front().where.file, path);
    io::ExportOptions fix;
    fix.fixNames = true;
    d = io::exportRig(rig, path, fix); // names fixed, the scale still refuses
    ASSERT_EQ(d.size(), 1u);
    EXPECT_TRUE(hasErrors(d));
    EXPECT_FALSE(std::filesystem::exists(path));
    io::ExportOptions force;
    force.force = true;
    d = io::exportRig(rig, path, force);
    EXPECT_FALSE(hasErrors(d));
    EXPECT_FALSE(d.empty());
    EXPECT_EQ(d.front().message.rfind("exported anyway (forced): ", 0), 0u);
    EXPECT_TRUE(std::filesystem::exists(path));
}

TEST(NameMap, UnityHumanoidNamesTheBipedAndStaysValid)
{
    const model::GuideDocument guide = test::loadSample("biped");
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    const io::NameMap unity = io::unityHumanoidMap(guide, rig);
    const auto skeleton = io::applyNameMap(rig, model::extractSkeleton(rig).take(), unity);
    std::set<std::string> names;
    for (const auto& joint : skeleton.joints)
        names.insert(joint.name);
    for (const char* expected : {"Hips", "Spine", "Chest", "UpperChest", "Neck", "Head", "LeftShoulder", "LeftUpperArm",
                                 "RightLowerArm", "RightHand", "LeftUpperLeg", "RightFoot", "RightToes", "LeftThumbDistal",
                                 "RightLittleProximal", "LeftIndexIntermediate"})
        EXPECT_TRUE(names.count(expected)) << expected;
    EXPECT_TRUE(io::checkSkeleton(rig, skeleton).problems.empty());
    // The export writes them.
    const std::string path = test::temporaryPath("unity.glb");
    io::ExportOptions options;
    options.names = &unity;
    ASSERT_TRUE(io::exportRig(rig, path, options).empty());
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, path)) << error;
    EXPECT_EQ(model.nodes[1].name, "Hips");
}

TEST(NameMap, ReadsIdsAndNamesFromYamlAndReportsBadEntriesWithTheirLine)
{
    const auto map = io::readNameMapText("rigsmith_names: 1\nnames:\n  \"spine::skin.0\": pelvis\n  sk_arm1_L: upperarm_l\n", "map.yml");
    ASSERT_TRUE(map.ok());
    const model::Rig rig = sampleRig("biped");
    const auto skeleton = io::applyNameMap(rig, model::extractSkeleton(rig).take(), *map);
    EXPECT_EQ(skeleton.joints[1].name, "pelvis");
    bool renamed = false;
    for (const auto& joint : skeleton.joints)
        renamed = renamed || (joint.name == "upperarm_l" && rig.nodes[joint.node].path == "arm.L::skin.limb.0");
    EXPECT_TRUE(renamed);

    const auto bad = io::readNameMapText("rigsmith_names: 1\nnames:\n  sk_arm1_L: [a, b]\n", "bad.yml");
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.diagnostics().front().format().rfind("bad.yml:3:14: error:", 0), 0u) << bad.diagnostics().front().format();
    const auto notAMap = io::readNameMapText("names: {}\n", "other.yml");
    ASSERT_FALSE(notAMap.ok());
    EXPECT_NE(notAMap.diagnostics().front().message.find("not a Rigsmith name map"), std::string::npos);
}
