#include "core/TestSupport.h"

#include "io/GuideFile.h"
#include "io/TemplateFolders.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <csignal>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace rs::test {

std::string dataPath(const std::string& relative) { return std::string(RIGSMITH_TEST_DATA) + "/" + relative; }
std::string samplePath(const std::string& name) { return std::string(RIGSMITH_SOURCE_DIR) + "/resources/samples/" + name + ".yml"; }

std::string readText(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

const templates::TemplateRegistry& builtinTemplates()
{
    static const auto registry = [] {
        auto r = std::make_shared<templates::TemplateRegistry>();
        const auto d = io::scanTemplates(*r, {std::string(RIGSMITH_SOURCE_DIR) + "/templates"}, std::string(RIGSMITH_SOURCE_DIR) + "/resources/icons");
        EXPECT_FALSE(hasErrors(d)) << formatAll(d);
        return r;
    }();
    return *registry;
}

model::GuideDocument loadSample(const std::string& name)
{
    auto doc = io::readGuideFile(samplePath(name));
    EXPECT_TRUE(doc.ok()) << formatAll(doc.diagnostics());
    return doc.ok() ? doc.take() : model::GuideDocument{};
}

const model::RigNode& node(const model::Rig& rig, const std::string& id)
{
    auto index = rig.findPath(id);
    EXPECT_TRUE(index.has_value()) << "no rig node " << id;
    static const model::RigNode none;
    return index ? rig.nodes[*index] : none;
}

model::GuideDocument loadGuide(const std::string& dataRelativePath)
{
    auto doc = io::readGuideFile(dataPath(dataRelativePath));
    EXPECT_TRUE(doc.ok()) << formatAll(doc.diagnostics());
    return doc.ok() ? doc.take() : model::GuideDocument{};
}

void expectMatchesGolden(const std::string& actual, const std::string& goldenRelativePath)
{
    const std::string path = dataPath(goldenRelativePath);
    if (const char* update = std::getenv("RIGSMITH_UPDATE_GOLDEN"); update && std::string(update) == "1") {
        std::filesystem::create_directories(std::filesystem::path(path).parent_path());
        std::ofstream(path, std::ios::binary) << actual;
        return;
    }
    ASSERT_TRUE(std::filesystem::exists(path)) << "missing golden file " << path << " (run with RIGSMITH_UPDATE_GOLDEN=1)";
    EXPECT_EQ(actual, readText(path)) << "differs from " << path;
}

std::string temporaryPath(const std::string& name)
{
    const auto dir = std::filesystem::temp_directory_path() / ("rigsmith-test-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

::testing::AssertionResult succeeded(const Status& status)
{
    if (status.ok())
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "failed:\n" << status.message();
}

std::string refusal(const Status& status)
{
    if (status.ok())
        return {};
    for (const Diagnostic& d : status.diagnostics())
        if (d.severity == Severity::Error)
            return d.message;
    return "(a failure without an error)";
}

bool runWithFileSizeLimit(std::size_t limitBytes, const std::function<bool()>& write)
{
    const pid_t child = fork();
    if (child == 0) {
        std::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{rlim_t(limitBytes), rlim_t(limitBytes)};
        setrlimit(RLIMIT_FSIZE, &limit);
        _exit(write() ? 0 : 1);
    }
    int status = 0;
    return child > 0 && waitpid(child, &status, 0) == child && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

} // namespace rs::test
