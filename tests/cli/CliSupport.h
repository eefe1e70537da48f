#pragma once
// Running rigsmith-cli as a process in the CLI tests: exit code, stderr, and
// optional limits on the files it may write (a full disk) and its memory.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace rs::clitest {

struct CliRun {
    int exitCode = -1;  // -1: killed by a signal (a crash, an uncaught exception)
    std::string errors; // stderr
};

struct CliLimits {
    std::size_t fileBytes = 0;    // files may not grow past this (EFBIG, SIGXFSZ ignored); 0: no limit
    std::size_t addressBytes = 0; // address space, so a runaway allocation fails fast; 0: no limit
};

// rigsmith-cli with `args`, run in `folder` (its stderr kept there as
// stderr.txt, stdout discarded).
CliRun runCli(const std::vector<std::string>& args, const std::filesystem::path& folder, CliLimits limits = {});

std::string readText(const std::filesystem::path& path);
// An empty folder `name` under this test process's own temporary folder.
std::filesystem::path freshFolder(const std::string& name);

} // namespace rs::clitest
