#include "CliSupport.h"

#include <csignal>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace rs::clitest {

CliRun runCli(const std::vector<std::string>& args, const fs::path& folder, CliLimits limits)
{
    const fs::path errorsFile = folder / "stderr.txt";
    const pid_t child = fork();
    if (child == 0) {
        if (chdir(folder.c_str()) != 0 || !std::freopen(errorsFile.c_str(), "w", stderr) ||
            !std::freopen("/dev/null", "w", stdout))
            _exit(126);
        if (limits.fileBytes > 0) {
            std::signal(SIGXFSZ, SIG_IGN); // kept across exec: a write past the limit fails instead of killing
            const rlimit size{rlim_t(limits.fileBytes), rlim_t(limits.fileBytes)};
            setrlimit(RLIMIT_FSIZE, &size);
        }
        if (limits.addressBytes > 0) {
            const rlimit memory{rlim_t(limits.addressBytes), rlim_t(limits.addressBytes)};
            setrlimit(RLIMIT_AS, &memory);
        }
        std::vector<char*> argv{const_cast<char*>(RIGSMITH_CLI)};
        for (const std::string& a : args)
            argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(RIGSMITH_CLI, argv.data());
        _exit(127);
    }
    CliRun run;
    int status = 0;
    if (waitpid(child, &status, 0) == child && WIFEXITED(status))
        run.exitCode = WEXITSTATUS(status);
    run.errors = readText(errorsFile);
    return run;
}

std::string readText(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

fs::path freshFolder(const std::string& name)
{
    const fs::path folder = fs::temp_directory_path() / ("rigsmith-cli-tests-" + std::to_string(getpid())) / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

} // namespace rs::clitest
