// Enforces the layer rules of ../shared/STYLE.md by scanning #include lines:
// core includes no Qt/GL, viewport and widgets never include each other, and
// yaml-cpp / tinygltf types stay out of core headers outside io/.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Include {
    std::string file;
    int line;
    std::string target;
};

std::vector<fs::path> sources(const std::string& folder)
{
    std::vector<fs::path> out;
    const fs::path root = fs::path(RIGSMITH_SOURCE_DIR) / folder;
    if (!fs::exists(root))
        return out;
    for (const auto& e : fs::recursive_directory_iterator(root))
        if (e.is_regular_file() && (e.path().extension() == ".h" || e.path().extension() == ".cpp"))
            out.push_back(e.path());
    return out;
}

std::vector<Include> includesOf(const std::string& folder)
{
    static const std::regex pattern(R"(^\s*#\s*include\s*[<"]([^>"]+)[>"])");
    std::vector<Include> out;
    for (const auto& path : sources(folder)) {
        std::ifstream in(path);
        std::string text;
        for (int line = 1; std::getline(in, text); ++line) {
            std::smatch m;
            if (std::regex_search(text, m, pattern))
                out.push_back({fs::relative(path, RIGSMITH_SOURCE_DIR).string(), line, m[1]});
        }
    }
    return out;
}

std::set<std::string> headerNames(const std::string& folder)
{
    std::set<std::string> names;
    for (const auto& path : sources(folder))
        if (path.extension() == ".h")
            names.insert(path.filename().string());
    return names;
}

bool isQtOrGl(const std::string& target)
{
    return std::regex_search(target, std::regex(R"(^(Q[A-Za-z]|qt|Qt|GL/|GLFW/|epoxy/|qopengl))"));
}

} // namespace

TEST(Layering, CoreIncludesNoQtAndNoGl)
{
    for (const auto& inc : includesOf("core"))
        EXPECT_FALSE(isQtOrGl(inc.target)) << inc.file << ":" << inc.line << ": core includes " << inc.target;
}

TEST(Layering, CoreIncludesNoViewportOrWidgets)
{
    const auto viewport = headerNames("viewport");
    const auto widgets = headerNames("widgets");
    for (const auto& inc : includesOf("core")) {
        const std::string name = fs::path(inc.target).filename().string();
        EXPECT_FALSE(viewport.count(name) || widgets.count(name) || inc.target.rfind("viewport/", 0) == 0 ||
                     inc.target.rfind("widgets/", 0) == 0)
            << inc.file << ":" << inc.line << ": core includes " << inc.target;
    }
}

TEST(Layering, ViewportAndWidgetsNeverIncludeEachOther)
{
    const auto viewport = headerNames("viewport");
    const auto widgets = headerNames("widgets");
    ASSERT_FALSE(viewport.empty());
    ASSERT_FALSE(widgets.empty());
    for (const auto& inc : includesOf("viewport")) {
        const std::string name = fs::path(inc.target).filename().string();
        EXPECT_FALSE((widgets.count(name) && !viewport.count(name)) || inc.target.find("widgets/") != std::string::npos)
            << inc.file << ":" << inc.line << ": viewport includes widgets header " << inc.target;
    }
    for (const auto& inc : includesOf("widgets")) {
        const std::string name = fs::path(inc.target).filename().string();
        EXPECT_FALSE((viewport.count(name) && !widgets.count(name)) || inc.target.find("viewport/") != std::string::npos)
            << inc.file << ":" << inc.line << ": widgets includes viewport header " << inc.target;
    }
}

TEST(Layering, ThirdPartyFormatTypesStayInCoreSources)
{
    for (const auto& inc : includesOf("core")) {
        if (inc.file.size() < 2 || inc.file.substr(inc.file.size() - 2) != ".h" || inc.file.rfind("core/io/", 0) == 0)
            continue;
        EXPECT_TRUE(inc.target.find("yaml-cpp") == std::string::npos && inc.target.find("tiny_gltf") == std::string::npos &&
                    inc.target.find("assimp") == std::string::npos && inc.target != "io/YamlSupport.h")
            << inc.file << ":" << inc.line << ": a core header outside io/ includes " << inc.target;
    }
}

TEST(Layering, ScannerSeesAQtIncludeAsQt)
{
    // Guards the guard: the pattern must catch the includes it is meant to catch.
    EXPECT_TRUE(isQtOrGl("QWidget"));
    EXPECT_TRUE(isQtOrGl("QtCore/QString"));
    EXPECT_TRUE(isQtOrGl("epoxy/gl.h"));
    EXPECT_FALSE(isQtOrGl("glm/glm.hpp"));
}
