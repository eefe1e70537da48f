// Issue 18 items 5, 7 and 8, from the command line: every numeric option is
// range-checked (no overflow, no huge allocation, no nan or inf) and names must
// be UTF-8; a refused argument is a message and exit code 2, and nothing is written.
#include "CliSupport.h"

#include <gtest/gtest.h>

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

// At most 2 GB of address space, so a runaway allocation fails fast instead of swapping the machine.
CliRun runCli(const std::vector<std::string>& args)
{
    return rs::clitest::runCli(args, freshFolder("stderr"), {0, std::size_t(2) << 30});
}

} // namespace

TEST(Cli, RefusesAProxyMeshOutOfRange)
{
    const fs::path out = freshFolder("proxy") / "rig.glb";
    for (const std::string count : {"99999999999999999999", "18446744073709551615", "4000000000", "1000001", "0", "-5",
                                     " 12", "1e9", "0x10", "nan"}) {
        const CliRun run = runCli({"build", kBiped, "-o", out.string(), "--proxy-mesh", count});
        EXPECT_EQ(run.exitCode, 2) << count << ": " << run.errors;
        EXPECT_NE(run.errors.find("--proxy-mesh wants a vertex count from 1 to 1000000, not '" + count + "'"), std::string::npos)
            << run.errors;
        EXPECT_FALSE(fs::exists(out)) << count;
    }
    const CliRun ok = runCli({"build", kBiped, "-o", out.string(), "--proxy-mesh", "1000"});
    EXPECT_EQ(ok.exitCode, 0) << ok.errors;
}

TEST(Cli, RefusesNonFiniteAndOutOfRangeNumbersInAdd)
{
    const fs::path guide = freshFolder("add") / "guide.yml";
    ASSERT_EQ(runCli({"new", guide.string()}).exitCode, 0);
    const std::string before = readText(guide);
    struct Case {
        std::vector<std::string> extra;
        std::string message;
    };
    const std::vector<Case> cases = {
        {{"--at", "nan,0,0"}, "--at wants finite values"},
        {{"--at", "0,inf,0"}, "--at wants finite values"},
        {{"--at", "0,0,1e300"}, "--at wants finite values"},
        {{"--set", "length=nan"}, "--set length: 'nan' is not a finite number"},
        {{"--set", "length=-Infinity"}, "--set length: '-Infinity' is not a finite number"},
        {{"--set", "length=1e400"}, "--set length: '1e400' is out of range"},
        {{"--set", "number=99999999999999999999"}, "--set number: '99999999999999999999' is out of range"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args{"add", guide.string(), "core.joints"};
        args.insert(args.end(), c.extra.begin(), c.extra.end());
        const CliRun run = runCli(args);
        EXPECT_EQ(run.exitCode, 2) << c.extra.back() << ": " << run.errors;
        EXPECT_NE(run.errors.find(c.message), std::string::npos) << run.errors;
        EXPECT_EQ(readText(guide), before) << c.extra.back();
    }
    const CliRun ok = runCli({"add", guide.string(), "core.joints", "--at", "0,1.5,0", "--set", "length=0.25"});
    EXPECT_EQ(ok.exitCode, 0) << ok.errors;
}

// A vector option (core.joints' up_dir) is set as the guide writes it, "[X, Y, Z]", or as --at takes
// coordinates, "X,Y,Z"; anything else is refused and nothing is added.
TEST(Cli, AddTakesAVectorOptionAsTheGuideOrAsAtWritesIt)
{
    const fs::path guide = freshFolder("add-vector") / "guide.yml";
    ASSERT_EQ(runCli({"new", guide.string()}).exitCode, 0);
    const CliRun bracketed = runCli({"add", guide.string(), "core.joints", "--name", "a", "--set", "up_dir=[1, 0, 0]"});
    EXPECT_EQ(bracketed.exitCode, 0) << bracketed.errors;
    const CliRun commas = runCli({"add", guide.string(), "core.joints", "--name", "b", "--set", "up_dir=0,-1,0.5"});
    EXPECT_EQ(commas.exitCode, 0) << commas.errors;
    const std::string text = readText(guide);
    EXPECT_NE(text.find("up_dir: [1, 0, 0]"), std::string::npos) << text;
    EXPECT_NE(text.find("up_dir: [0, -1, 0.5]"), std::string::npos) << text;
    for (const std::string bad : {"up_dir=[1, 0]", "up_dir=[1, 0, 0, 0]", "up_dir=[x, 0, 0]", "up_dir=1,,0"}) {
        const CliRun run = runCli({"add", guide.string(), "core.joints", "--name", "c", "--set", bad});
        EXPECT_NE(run.exitCode, 0) << bad;
        EXPECT_NE(run.errors.find("--set up_dir was not taken; nothing was added"), std::string::npos) << bad << ": " << run.errors;
        EXPECT_EQ(readText(guide), text) << bad;
    }
}

TEST(Cli, RefusesANameThatIsNotUtf8)
{
    const fs::path folder = freshFolder("utf8");
    const CliRun created = runCli({"new", (folder / "a.yml").string(), "--name", "rig\xff"});
    EXPECT_EQ(created.exitCode, 2) << created.errors;
    EXPECT_NE(created.errors.find("--name is not valid UTF-8"), std::string::npos) << created.errors;
    EXPECT_FALSE(fs::exists(folder / "a.yml"));

    ASSERT_EQ(runCli({"new", (folder / "b.yml").string()}).exitCode, 0);
    const CliRun added = runCli({"add", (folder / "b.yml").string(), "core.joints", "--name", "tail\xc3"});
    EXPECT_EQ(added.exitCode, 2) << added.errors;
    // A guide that already holds such a name is refused at its line.
    std::ofstream(folder / "c.yml") << "rigsmith_guide: 1\ninstances:\n  - id: 1\n    template: core.joints\n"
                                       "    name: tail\xe2\x82\n    joints:\n      - {id: 1, t: [0, 0, 0]}\n";
    const CliRun built = runCli({"build", (folder / "c.yml").string(), "-o", (folder / "c.gltf").string()});
    EXPECT_EQ(built.exitCode, 1) << built.errors;
    EXPECT_NE(built.errors.find((folder / "c.yml").string() + ":5:11: error: text is not valid UTF-8"), std::string::npos)
        << built.errors;
    EXPECT_FALSE(fs::exists(folder / "c.gltf"));
}
