// `rigsmith-cli build --no-restore KIND`: the guide's overrides of that kind
// are left out of the build (the records stay in the guide); a bad kind is
// refused with the list of kinds.
#include "CliSupport.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using rs::clitest::freshFolder;
using rs::clitest::readText;
using rs::clitest::runCli;

namespace {

fs::path overriddenBiped(const fs::path& folder)
{
    const fs::path guide = folder / "overridden.yml";
    std::ofstream out(guide);
    out << readText(RIGSMITH_SOURCE_DIR "/resources/samples/biped.yml")
        << "overrides:\n"
           "  - instance: 4\n"
           "    branch: L\n"
           "    node: ctrls.fk.0\n"
           "    name: upperarm_ctl_L\n"
           "    pose: {rz: 30}\n";
    return guide;
}

} // namespace

TEST(Cli, NoRestoreLeavesOneKindOfOverrideOut)
{
    const fs::path folder = freshFolder("no-restore");
    const fs::path guide = overriddenBiped(folder);
    const auto all = runCli({"build", guide.string(), "--posed", "--dump", (folder / "all.yml").string()}, folder);
    ASSERT_EQ(all.exitCode, 0) << all.errors;
    EXPECT_NE(readText(folder / "all.yml").find("upperarm_ctl_L"), std::string::npos);
    EXPECT_NE(all.errors.find("posed with 1 posed nodes"), std::string::npos) << all.errors;

    const auto noNames = runCli({"build", guide.string(), "--posed", "--no-restore", "names", "--dump", (folder / "names.yml").string()},
                                folder);
    ASSERT_EQ(noNames.exitCode, 0) << noNames.errors;
    EXPECT_EQ(readText(folder / "names.yml").find("upperarm_ctl_L"), std::string::npos);
    EXPECT_NE(noNames.errors.find("posed with 1 posed nodes"), std::string::npos) << noNames.errors;

    const auto neither = runCli({"build", guide.string(), "--posed", "--no-restore", "names", "--no-restore", "pose", "--dump",
                                 (folder / "neither.yml").string()},
                                folder);
    ASSERT_EQ(neither.exitCode, 0) << neither.errors;
    EXPECT_NE(neither.errors.find("posed with 0 posed nodes"), std::string::npos) << neither.errors;
    EXPECT_EQ(readText(folder / "neither.yml").find("upperarm_ctl_L"), std::string::npos);

    const auto bad = runCli({"build", guide.string(), "--no-restore", "colours"}, folder);
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.errors.find("--no-restore wants shapes, defaults, limits, locks, post, names or pose, not 'colours'"),
              std::string::npos) << bad.errors;
}

TEST(Cli, NoRestoreAddsToTheGuidesSettingsAndCleanupFlagsReplaceItsOwn)
{
    const fs::path folder = freshFolder("guide-settings");
    const fs::path guide = overriddenBiped(folder);
    {
        std::ofstream out(guide, std::ios::app);
        out << "build:\n  cleanup: on\n  no_restore: [pose]\n";
    }
    // The guide leaves the pose out and cleans up; --no-restore names adds to it.
    const auto both = runCli({"build", guide.string(), "--posed", "--no-restore", "names", "--dump", (folder / "both.yml").string()},
                             folder);
    ASSERT_EQ(both.exitCode, 0) << both.errors;
    EXPECT_NE(both.errors.find("posed with 0 posed nodes"), std::string::npos) << both.errors;
    const std::string cleaned = readText(folder / "both.yml");
    EXPECT_EQ(cleaned.find("upperarm_ctl_L"), std::string::npos);
    EXPECT_NE(cleaned.find("hidden: [tx, ty, tz"), std::string::npos) << "cleaned up as the guide says";
    EXPECT_NE(cleaned.find("defaults: {"), std::string::npos);

    const auto raw = runCli({"build", guide.string(), "--no-cleanup", "--dump", (folder / "raw.yml").string()}, folder);
    ASSERT_EQ(raw.exitCode, 0) << raw.errors;
    EXPECT_EQ(readText(folder / "raw.yml").find("defaults: {"), std::string::npos) << "--no-cleanup wins over the guide";
    EXPECT_NE(readText(folder / "raw.yml").find("upperarm_ctl_L"), std::string::npos);

    const fs::path sample = RIGSMITH_SOURCE_DIR "/resources/samples/prop.yml";
    const auto on = runCli({"build", sample.string(), "--cleanup", "--dump", (folder / "prop.yml").string()}, folder);
    ASSERT_EQ(on.exitCode, 0) << on.errors;
    EXPECT_NE(readText(folder / "prop.yml").find("defaults: {"), std::string::npos) << "--cleanup on a guide without it";
}
