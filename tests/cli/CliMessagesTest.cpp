// rigsmith-cli's messages (issue 18 item 13): an empty output path is an
// error, a repeated branch name is one error, and a guide whose instance uses
// a missing template says so when the CLI opens it.
#include "CliSupport.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using rs::clitest::CliRun;
using rs::clitest::freshFolder;
using rs::clitest::readText;
using rs::clitest::runCli;

namespace {

const std::string kBiped = RIGSMITH_SOURCE_DIR "/resources/samples/biped.yml";

// The biped with `from` replaced by `to` once, written to `folder`/`name`.
fs::path editedBiped(const fs::path& folder, const std::string& name, const std::string& from, const std::string& to)
{
    std::string text = readText(kBiped);
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos)
        text.replace(at, from.size(), to);
    std::ofstream(folder / name) << text;
    return folder / name;
}

std::size_t countLines(const std::string& text, const std::string& needle)
{
    std::size_t count = 0;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
        count += line.find(needle) != std::string::npos;
    return count;
}

} // namespace

TEST(Cli, AnEmptyPathForAnOutputOptionIsAnError)
{
    const fs::path folder = freshFolder("empty-output");
    for (const std::string option : {"-o", "--dump", "--reference", "--names"}) {
        const CliRun run = runCli({"build", kBiped, option, ""}, folder);
        EXPECT_NE(run.exitCode, 0) << option;
        EXPECT_NE(run.errors.find(option + " wants a file path"), std::string::npos) << option << ": " << run.errors;
    }
}

TEST(Cli, ARepeatedBranchNameIsOneErrorAboutTheInstance)
{
    const fs::path folder = freshFolder("repeated-branch");
    // The sample's arm has options already (fk_space): the branches go in the same block.
    const fs::path guide = editedBiped(folder, "guide.yml", "    hook: 7\n    options:\n",
                                       "    hook: 7\n    options:\n      branches: \"[L, L]\"\n");
    const CliRun run = runCli({"build", guide.string()}, folder);
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(countLines(run.errors, "error:"), 1u) << run.errors;
    EXPECT_NE(run.errors.find("instance 'arm': option 'branches' = '[L, L]' names branch 'L' twice"), std::string::npos)
        << run.errors;
}

TEST(Cli, AddingToAGuideWithAMissingTemplateWarnsAboutTheInstance)
{
    const fs::path folder = freshFolder("missing-template");
    const fs::path guide = editedBiped(folder, "guide.yml", "template: neck.head", "template: neck.gone");
    const CliRun run = runCli({"add", guide.string(), "core.xform"}, folder);
    EXPECT_EQ(run.exitCode, 0) << run.errors;
    EXPECT_NE(run.errors.find(guide.string() + ": warning: instance 'neck': unknown template 'neck.gone'"), std::string::npos)
        << run.errors;
}

TEST(Cli, TheUnityPresetExportsABipedWhoseSpineIsRenamed)
{
    // The humanoid map finds Hips by the spine.torso template's skin.0, not by the instance's name.
    const fs::path folder = freshFolder("unity-renamed");
    const fs::path guide = editedBiped(folder, "torso.yml", "    name: spine\n", "    name: torso\n");
    const fs::path glb = folder / "torso.glb";
    const CliRun run = runCli({"build", guide.string(), "-o", glb.string(), "--preset", "unity"}, folder);
    EXPECT_EQ(run.exitCode, 0) << run.errors;
    EXPECT_EQ(run.errors.find("no joint"), std::string::npos) << run.errors;
    EXPECT_NE(readText(glb).find("\"Hips\""), std::string::npos) << "the torso's first joint is Unity's Hips";
}
