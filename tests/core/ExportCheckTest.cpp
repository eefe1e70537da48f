// The pre-export validator: clean samples pass, broken skeletons are reported
// per node, the export refuses them unless forced, and safe renames fix names.
#include "build/RigBuilder.h"
#include "core/TestSupport.h"
#include "io/ExportCheck.h"
#include "io/GltfExport.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

using namespace rs;

namespace {

model::Rig sampleRig(const std::string& name) { return build::buildRig(test::loadSample(name), test::builtinTemplates()); }

// The biped with two naming problems and one non-uniformly scaled joint.
model::Rig brokenBiped()
{
    model::Rig rig = sampleRig("biped");
    rig.nodes[*rig.find("arm.L::skin.limb.0")].name = "upper arm.L"; // not engine-safe
    rig.nodes[*rig.find("arm.L::skin.limb.1")].name = "SK_ARM1_R";   // sk_arm1_R's name, ignoring case
    auto& hand = rig.nodes[*rig.find("arm.L::skin.limb.2")];
    hand.worldMatrix = hand.worldMatrix * glm::scale(Mat4(1.0), Vec3(1.0, 2.0, 1.0));
    return rig;
}

} // namespace

TEST(ExportCheck, TheSamplesExportCleanly)
{
    for (const char* sample : {"biped", "quadruped", "prop"}) {
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
        bySubject[d.subject] += d.message + "\n";
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
    EXPECT_EQ(recheck.problems.front().subject, "arm.L::skin.limb.2");
}

TEST(ExportCheck, TheExportRefusesErrorsUnlessForced)
{
    const model::Rig rig = brokenBiped();
    const std::string path = test::temporaryPath("broken.glb");
    std::filesystem::remove(path);
    auto d = io::exportGltf(rig, path, {});
    EXPECT_TRUE(hasErrors(d));
    EXPECT_FALSE(std::filesystem::exists(path));
    EXPECT_EQ(d.front().where.file, path);
    io::GltfExportOptions fix;
    fix.fixNames = true;
    d = io::exportGltf(rig, path, fix); // names fixed, the scale still refuses
    ASSERT_EQ(d.size(), 1u);
    EXPECT_TRUE(hasErrors(d));
    EXPECT_FALSE(std::filesystem::exists(path));
    io::GltfExportOptions force;
    force.force = true;
    d = io::exportGltf(rig, path, force);
    EXPECT_FALSE(hasErrors(d));
    EXPECT_FALSE(d.empty());
    EXPECT_EQ(d.front().message.rfind("exported anyway (forced): ", 0), 0u);
    EXPECT_TRUE(std::filesystem::exists(path));
}
