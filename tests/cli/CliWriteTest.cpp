// Issue 18 item 2, from the command line: every file rigsmith-cli writes
// (exports, rig dumps, export references, guides) fails on a full disk with
// a message on stderr and a non-zero exit, and leaves the previous file.
#include "CliSupport.h"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using rs::clitest::CliRun;
using rs::clitest::freshFolder;
using rs::clitest::readText;

namespace {

const std::string kBiped = RIGSMITH_SOURCE_DIR "/resources/samples/biped.yml";

// rigsmith-cli whose files may not grow past `limitBytes` (a full disk), its stderr beside `errorsFile`'s folder.
CliRun runCli(const std::vector<std::string>& args, std::size_t limitBytes, const fs::path& errorsFile)
{
    return rs::clitest::runCli(args, errorsFile.parent_path(), {limitBytes, 0});
}

} // namespace

TEST(Cli, AFullDiskFailsEveryWriteWithAMessageAndKeepsThePreviousFiles)
{
    const fs::path folder = freshFolder("full");
    const fs::path errors = fs::temp_directory_path() / ("rigsmith-cli-tests-" + std::to_string(getpid())) / "stderr.txt";
    struct Case {
        std::vector<std::string> args;
        std::vector<fs::path> outputs;
    };
    const fs::path gltf = folder / "rig.gltf", bin = folder / "rig.bin", glb = folder / "rig.glb", fbx = folder / "rig.fbx";
    const fs::path dump = folder / "rig.yml", reference = folder / "reference.json", guide = folder / "guide.yml";
    fs::copy_file(kBiped, guide);
    const std::vector<Case> cases = {
        {{"build", kBiped, "-o", gltf.string()}, {gltf, bin}},
        {{"build", kBiped, "-o", glb.string()}, {glb}},
        {{"build", kBiped, "-o", fbx.string(), "--preset", "unreal", "--proxy-mesh", "2000"}, {fbx}},
        {{"build", kBiped, "--dump", dump.string()}, {dump}},
        {{"build", kBiped, "--reference", reference.string()}, {reference}},
        {{"add", guide.string(), "core.joints", "--name", "tail"}, {guide}},
    };
    for (const Case& c : cases) {
        const std::string what = c.args[0] + " " + c.outputs[0].filename().string();
        // First the real files (no limit), then a full disk over them.
        if (c.args[0] == "build") {
            const CliRun ok = runCli(c.args, std::size_t(1) << 30, errors);
            ASSERT_EQ(ok.exitCode, 0) << what << ": " << ok.errors;
        }
        std::vector<std::string> previous; // an export's previous bytes are its own; the guide must stay a guide
        for (const fs::path& out : c.outputs) {
            if (out != guide)
                std::ofstream(out, std::ios::binary) << "previous " << out.filename().string() << "\n";
            previous.push_back(readText(out));
        }
        const CliRun full = runCli(c.args, 512, errors);
        EXPECT_NE(full.exitCode, 0) << what;
        EXPECT_NE(full.errors.find(c.outputs[0].string() + ": error: cannot write: File too large"), std::string::npos)
            << what << ": " << full.errors;
        for (std::size_t i = 0; i < c.outputs.size(); ++i)
            EXPECT_EQ(readText(c.outputs[i]), previous[i]) << what;
    }
    for (const auto& entry : fs::directory_iterator(folder))
        EXPECT_EQ(entry.path().extension() == ".tmp", false) << "left behind: " << entry.path();
}
