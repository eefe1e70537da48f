// rigsmith-cli joint: a guide joint placed without a display, as the editor's
// move tool places it (children follow, mirrored branches and, with
// --symmetric, twin instances follow mirrored); every refusal leaves the guide
// byte for byte. The saved guide is read back with core's reader.
#include "CliSupport.h"

#include "io/GuideFile.h"
#include "io/TemplateFolders.h"
#include "session/MirroredGuides.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using rs::clitest::CliRun;
using rs::clitest::freshFolder;
using rs::clitest::readText;

namespace {

CliRun runCli(const std::vector<std::string>& args)
{
    return rs::clitest::runCli(args, freshFolder("joint-stderr"));
}

// A hull 1 m up carrying a quad.leg `leg` with its default branches [L, R].
fs::path legGuide(const std::string& name)
{
    const fs::path guide = freshFolder(name) / "guide.yml";
    const std::vector<std::vector<std::string>> steps = {
        {"new", guide.string()},
        {"add", guide.string(), "world.character", "--name", "world"},
        {"add", guide.string(), "core.xform", "--under", "world", "--name", "hull", "--at", "0,1,0"},
        {"add", guide.string(), "quad.leg", "--under", "hull", "--name", "leg", "--at", "0.15,0,0.3"},
    };
    for (const auto& step : steps) {
        const CliRun run = runCli(step);
        EXPECT_EQ(run.exitCode, 0) << step[0] << ": " << run.errors;
    }
    return guide;
}

rs::model::GuideDocument readGuide(const fs::path& path)
{
    auto guide = rs::io::readGuideFile(path.string());
    EXPECT_TRUE(guide.ok()) << path;
    return guide ? *guide : rs::model::GuideDocument{};
}

// World positions (metres) of an instance's guide joints, in its joint order.
std::vector<rs::Vec3> worldPositions(const rs::model::GuideDocument& guide, const std::string& instance)
{
    std::vector<rs::Vec3> out;
    if (const auto* found = guide.instanceNamed(instance))
        for (const auto& joint : found->joints)
            out.push_back(rs::translationOf(guide.jointWorldMatrix(joint.id)));
    return out;
}

void expectNear(const rs::Vec3& actual, const rs::Vec3& expected, const std::string& what)
{
    EXPECT_LT(glm::length(actual - expected), 1e-6) << what << ": (" << actual.x << ", " << actual.y << ", "
                                                    << actual.z << ") expected (" << expected.x << ", " << expected.y
                                                    << ", " << expected.z << ")";
}

} // namespace

// quad.leg's chain: pelvis, limb1 (hip), limb2 (stifle), limb3 (hock), limb4 (fetlock), ball, toe.
TEST(CliJoint, MovingAJointMovesItAndEveryJointBelowFollows)
{
    const fs::path guide = legGuide("joint-move");
    const auto before = worldPositions(readGuide(guide), "leg");
    ASSERT_EQ(before.size(), 10u);
    const CliRun run = runCli({"joint", guide.string(), "leg", "limb2", "--move", "0,-0.02,0.05", "--space", "world"});
    ASSERT_EQ(run.exitCode, 0) << run.errors;
    const auto after = worldPositions(readGuide(guide), "leg");
    ASSERT_EQ(after.size(), before.size());
    const rs::Vec3 delta(0.0, -0.02, 0.05);
    for (std::size_t i = 0; i < after.size(); ++i) // joints 0, 1 are above limb2; every other one hangs below it
        expectNear(after[i], i < 2 ? before[i] : before[i] + delta, "joint " + std::to_string(i));

    // --at in the parent's space sets the value the guide file writes.
    const CliRun at = runCli({"joint", guide.string(), "leg", "limb3", "--at", "0,-0.3,-0.1"});
    ASSERT_EQ(at.exitCode, 0) << at.errors;
    const auto document = readGuide(guide);
    const auto* leg = document.instanceNamed("leg");
    ASSERT_NE(leg, nullptr);
    expectNear(leg->joints[3].local.translate, rs::Vec3(0.0, -0.3, -0.1), "limb3's local position");
}

TEST(CliJoint, TheMirroredBranchFollowsItsAuthoredSide)
{
    const fs::path guide = legGuide("joint-branch");
    ASSERT_EQ(runCli({"joint", guide.string(), "leg", "toe", "--at", "0.3,0.02,1.2", "--space", "world"}).exitCode, 0);
    const auto document = readGuide(guide);
    const auto authored = worldPositions(document, "leg");
    expectNear(authored.at(6), rs::Vec3(0.3, 0.02, 1.2), "the toe");
    rs::Diagnostics diagnostics;
    const auto templates = rs::io::loadDefaultTemplates(diagnostics);
    std::vector<rs::Vec3> mirrored;
    for (const auto& joint : rs::session::mirroredGuideJoints(document, *templates))
        if (joint.owner == document.instanceNamed("leg")->id)
            mirrored.push_back(joint.position);
    ASSERT_EQ(mirrored.size(), authored.size());
    for (std::size_t i = 0; i < authored.size(); ++i)
        expectNear(mirrored[i], rs::Vec3(-authored[i].x, authored[i].y, authored[i].z), "R joint " + std::to_string(i));
}

TEST(CliJoint, SymmetricMovesTheTwinInstanceMirrored)
{
    const fs::path guide = freshFolder("joint-twin") / "guide.yml";
    ASSERT_EQ(runCli({"new", guide.string()}).exitCode, 0);
    ASSERT_EQ(runCli({"add", guide.string(), "core.joints", "--name", "fin_L", "--at", "0.2,1,0"}).exitCode, 0);
    ASSERT_EQ(runCli({"add", guide.string(), "core.joints", "--name", "fin_R", "--at", "-0.2,1,0"}).exitCode, 0);
    const auto before = worldPositions(readGuide(guide), "fin_R");
    const CliRun run = runCli({"joint", guide.string(), "fin_L", ".", "--move", "0.1,0.05,0", "--space", "world", "--symmetric"});
    ASSERT_EQ(run.exitCode, 0) << run.errors;
    const auto document = readGuide(guide);
    expectNear(worldPositions(document, "fin_L").at(0), rs::Vec3(0.3, 1.05, 0.0), "fin_L");
    expectNear(worldPositions(document, "fin_R").at(0), before.at(0) + rs::Vec3(-0.1, 0.05, 0.0), "fin_R");
}

TEST(CliJoint, EveryRefusalSaysWhyAndLeavesTheGuideByteForByte)
{
    const fs::path guide = legGuide("joint-refused");
    const std::string text = readText(guide);
    struct Case {
        std::vector<std::string> args;
        int exitCode;
        std::string message;
    };
    const std::string g = guide.string();
    const std::vector<Case> cases = {
        {{(guide.parent_path() / "missing.yml").string(), "leg", "toe", "--at", "0,0,0"}, 1, "missing.yml: error: cannot open"},
        {{g, "arm", "toe", "--at", "0,0,0"}, 1, "error: no instance named 'arm'"},
        {{g, "leg_R", "toe", "--at", "0,0,0"}, 1, "'leg_R' is the mirrored R branch of instance 'leg', which the guide file holds once: edit 'leg'"},
        {{g, "leg_L", "toe", "--at", "0,0,0"}, 1, "'leg_L' is the L branch of instance 'leg', which the guide file holds once: edit 'leg'"},
        {{g, "leg", "hand", "--at", "0,0,0"}, 1, "instance 'leg' has no joint 'hand' (joints: pelvis, limb1, limb2"},
        {{g, "leg", "limb", "--at", "0,0,0"}, 1, "joint 'limb' of instance 'leg' names 4 joints, not one"},
        {{g, "leg", "toe", "--at", "nan,0,0"}, 2, "--at wants finite values from -1000 to 1000 metres, got 'nan,0,0'"},
        {{g, "leg", "toe", "--move", "0,inf,0"}, 2, "--move wants finite values"},
        {{g, "leg", "toe", "--at", "0,0,1e300"}, 2, "--at wants finite values"},
        {{g, "leg", "toe", "--at", "0,0"}, 2, "--at expects X,Y,Z, got '0,0'"},
        {{g, "leg", "toe", "--rotate", "0,400,0"}, 2, "--rotate wants finite values from -360 to 360 degrees"},
        {{g, "leg", "toe", "--move", "0,0,999.9", "--space", "world"}, 2, "past 1000 metres from the origin"},
        {{g, "leg", "toe", "--at", "0,0,0", "--space", "local"}, 2, "--space is world or parent, not 'local'"},
        {{g, "leg", "toe", "--at", "0,0,0", "--move", "0,0,1"}, 2, "give --at or --move, not both"},
        {{g, "leg", "toe"}, 2, "nothing to do"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args{"joint"};
        args.insert(args.end(), c.args.begin(), c.args.end());
        const CliRun run = runCli(args);
        EXPECT_EQ(run.exitCode, c.exitCode) << c.message << ": " << run.errors;
        EXPECT_NE(run.errors.find(c.message), std::string::npos) << run.errors;
        EXPECT_EQ(readText(guide), text) << c.message;
    }
    // A joint already where it is asked to be: a note, success, and the file as it was.
    const CliRun same = runCli({"joint", g, "leg", "pelvis", "--at", "0.15,0,0.3"});
    EXPECT_EQ(same.exitCode, 0) << same.errors;
    EXPECT_NE(same.errors.find("is already there; the guide is unchanged"), std::string::npos) << same.errors;
    EXPECT_EQ(readText(guide), text);
}
