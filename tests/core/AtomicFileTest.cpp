// Issue 18 items 2, 4 and 10: every file is written whole or not at all, never
// through a planted link, and through a symlink to its target with its mode kept.
#include "core/TestSupport.h"
#include "io/AtomicFile.h"
#include "io/GuideFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace rs;
namespace fs = std::filesystem;

namespace {

fs::path freshFolder(const std::string& name)
{
    const fs::path folder = test::temporaryPath(name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

void writePlain(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

std::size_t entriesIn(const fs::path& folder)
{
    return std::size_t(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

} // namespace

TEST(AtomicFile, AFullDiskFailsWithAMessageAndKeepsThePreviousFile)
{
    const fs::path folder = freshFolder("atomic-full");
    const fs::path path = folder / "guide.yml";
    writePlain(path, "previous content\n");
    const std::string big(256 * 1024, 'x');
    const bool reportedFailure = test::runWithFileSizeLimit(64 * 1024, [&] {
        const Status written = io::writeFileAtomically(path.string(), big);
        return written.failed() && written.message().find(path.string()) != std::string::npos &&
               written.message().find("File too large") != std::string::npos;
    });
    EXPECT_TRUE(reportedFailure) << "the write fails with EFBIG, named in the message";
    EXPECT_EQ(test::readText(path.string()), "previous content\n");
    EXPECT_EQ(entriesIn(folder), 1u) << "no temp file is left behind";
    EXPECT_TRUE(test::runWithFileSizeLimit(1024 * 1024, [&] { return io::writeFileAtomically(path.string(), big).ok(); }));
    EXPECT_EQ(test::readText(path.string()), big);
}

TEST(AtomicFile, APlantedLinkAtTheOldTempNameIsNotFollowed)
{
    const fs::path folder = freshFolder("atomic-planted");
    const fs::path path = folder / "guide.yml";
    const fs::path victim = folder / "victim.txt";
    writePlain(path, "previous\n");
    writePlain(victim, "not yours\n");
    fs::create_symlink(victim, folder / "guide.yml.saving~"); // the name saves used to write through
    ASSERT_TRUE(io::saveGuideFile(test::loadSample("biped"), path.string()).ok());
    EXPECT_EQ(test::readText(victim.string()), "not yours\n");
    EXPECT_FALSE(fs::is_symlink(path));
    EXPECT_EQ(test::readText(path.string()), test::readText(test::samplePath("biped")));
}

TEST(AtomicFile, SavingThroughALinkWritesItsTargetAndKeepsModeAndOwner)
{
    const fs::path folder = freshFolder("atomic-link");
    fs::create_directories(folder / "real");
    const fs::path target = folder / "real" / "hero.yml";
    const fs::path link = folder / "hero.yml";
    writePlain(target, "previous\n");
    ASSERT_EQ(chmod(target.c_str(), 0600), 0);
    const bool root = geteuid() == 0;
    if (root) {
        ASSERT_EQ(chown(target.c_str(), 4321, 4321), 0);
    }
    fs::create_symlink("real/hero.yml", link); // relative, as links usually are
    const fs::path chained = folder / "chained.yml";
    fs::create_symlink("hero.yml", chained);    // a link to the link

    ASSERT_TRUE(io::saveGuideFile(test::loadSample("biped"), chained.string()).ok());
    EXPECT_TRUE(fs::is_symlink(link)) << "the link stays a link";
    EXPECT_TRUE(fs::is_symlink(chained));
    EXPECT_EQ(test::readText(target.string()), test::readText(test::samplePath("biped")));
    struct stat written {};
    ASSERT_EQ(stat(target.c_str(), &written), 0);
    EXPECT_EQ(written.st_mode & 07777, 0600u) << "permissions are not widened";
    if (root) {
        EXPECT_EQ(written.st_uid, 4321u);
        EXPECT_EQ(written.st_gid, 4321u);
    }
    EXPECT_EQ(entriesIn(folder / "real"), 1u);
}

TEST(AtomicFile, TwoConcurrentWritersLeaveOneWholeFile)
{
    const fs::path folder = freshFolder("atomic-concurrent");
    const fs::path path = folder / "guide.yml";
    const std::string a(3 * 1024 * 1024, 'a'), b(3 * 1024 * 1024, 'b');
    auto spawn = [&](const std::string& bytes) {
        const pid_t child = fork();
        if (child == 0) {
            bool ok = true;
            for (int i = 0; i < 20; ++i)
                ok = io::writeFileAtomically(path.string(), bytes).ok() && ok;
            _exit(ok ? 0 : 1);
        }
        return child;
    };
    const pid_t first = spawn(a), second = spawn(b);
    for (pid_t child : {first, second}) {
        int status = 0;
        ASSERT_EQ(waitpid(child, &status, 0), child);
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "every save of both writers succeeded";
    }
    const std::string result = test::readText(path.string());
    EXPECT_TRUE(result == a || result == b) << "one writer's whole content (size " << result.size() << ")";
    EXPECT_EQ(entriesIn(folder), 1u);
}

TEST(AtomicFile, ANewFileGetsTheUmaskModeAndAFolderTargetIsRefused)
{
    const fs::path folder = freshFolder("atomic-new");
    const mode_t previous = umask(022);
    ASSERT_TRUE(io::writeFileAtomically((folder / "new.txt").string(), "new\n").ok());
    umask(previous);
    struct stat created {};
    ASSERT_EQ(stat((folder / "new.txt").c_str(), &created), 0);
    EXPECT_EQ(created.st_mode & 0777, 0644u);
    fs::create_directories(folder / "sub");
    const Status refused = io::writeFileAtomically((folder / "sub").string(), "x");
    EXPECT_TRUE(refused.failed());
    EXPECT_NE(refused.message().find("not a regular file"), std::string::npos) << refused.message();
    EXPECT_TRUE(io::writeFileAtomically("", "x").failed());
    EXPECT_TRUE(io::writeFileAtomically((folder / "missing" / "x.txt").string(), "x").failed());
}
