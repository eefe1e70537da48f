// Enforces the layer rules of ../shared/STYLE.md and core/README.md by scanning
// #include lines of a source tree (core/, viewport/, widgets/, app/):
//   - each core folder includes only the core layers the table below allows it;
//   - core includes no Qt/GL and nothing from viewport/ or widgets/;
//   - viewport and widgets never include each other, nor the builder (rigging/);
//   - yaml-cpp, tiny_gltf and assimp headers (and io/YamlSupport.h) are
//     included only from core/io/.
// The same scanner runs over the real tree (no violation) and over a fixture
// tree, tests/data/Layering/violations/, whose planted violations it must report
// exactly, as file:line, so a scanner that stopped seeing them would fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// The core layers, lowest first, and the core layers each may include (besides
// itself). A layer may only name layers before it, so the graph has no cycle;
// core/CMakeLists.txt links the same way. core/README.md explains the order.
struct Layer {
    std::string folder;
    std::set<std::string> mayInclude;
};
const std::vector<Layer> kCoreLayers = {
    {"base", {}},
    {"model", {"base"}},
    {"eval", {"base", "model"}},
    {"skin", {"base", "model"}},
    {"templates", {"base", "model"}},
    {"rigging", {"base", "model", "eval", "templates"}},
    {"edit", {"base", "model", "eval"}},
    {"session", {"base", "model", "eval", "templates", "rigging", "edit", "skin"}},
    {"io", {"base", "model", "eval", "templates", "skin"}},
};

const std::vector<std::string> kScannedFolders = {"core", "viewport", "widgets", "app"};

struct Include {
    std::string file; // relative to the scanned root, '/'-separated
    int line;
    std::string target;
};

std::vector<Include> includesUnder(const fs::path& root, const std::string& folder)
{
    static const std::regex pattern(R"(^\s*#\s*include\s*[<"]([^>"]+)[>"])");
    std::vector<fs::path> files;
    if (fs::is_directory(root / folder))
        for (const auto& e : fs::recursive_directory_iterator(root / folder))
            if (e.is_regular_file() && (e.path().extension() == ".h" || e.path().extension() == ".cpp"))
                files.push_back(e.path());
    std::sort(files.begin(), files.end());
    std::vector<Include> out;
    for (const auto& path : files) {
        std::ifstream in(path);
        std::string text;
        for (int line = 1; std::getline(in, text); ++line) {
            std::smatch m;
            if (std::regex_search(text, m, pattern))
                out.push_back({fs::relative(path, root).generic_string(), line, m[1]});
        }
    }
    return out;
}

std::set<std::string> headerNames(const fs::path& root, const std::string& folder)
{
    std::set<std::string> names;
    if (fs::is_directory(root / folder))
        for (const auto& e : fs::recursive_directory_iterator(root / folder))
            if (e.is_regular_file() && e.path().extension() == ".h")
                names.insert(e.path().filename().string());
    return names;
}

bool startsWith(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

// The first path component of an include ("rigging" for "rigging/RigBuilder.h"), or "".
std::string topFolder(const std::string& target)
{
    const auto slash = target.find('/');
    return slash == std::string::npos ? std::string() : target.substr(0, slash);
}

bool isQtOrGl(const std::string& target)
{
    return std::regex_search(target, std::regex(R"(^(Q[A-Za-z]|qt|Qt|GL/|GLFW/|epoxy/|qopengl))"));
}

// Third-party format libraries whose types stay inside core/io/.
bool isFormatLibrary(const std::string& target)
{
    return startsWith(target, "yaml-cpp/") || target.find("tiny_gltf") != std::string::npos ||
           startsWith(target, "assimp/") || target == "io/YamlSupport.h";
}

const Layer* layerNamed(const std::string& folder)
{
    for (const Layer& layer : kCoreLayers)
        if (layer.folder == folder)
            return &layer;
    return nullptr;
}

// Every broken rule under `root`, as "file:line: message", sorted.
std::vector<std::string> layeringViolations(const fs::path& root)
{
    std::vector<std::string> out;
    auto report = [&](const Include& inc, const std::string& message) {
        out.push_back(inc.file + ":" + std::to_string(inc.line) + ": " + message);
    };
    const std::set<std::string> viewportHeaders = headerNames(root, "viewport");
    const std::set<std::string> widgetsHeaders = headerNames(root, "widgets");
    // A bare include ("OutlinerView.h") names a header of the folder it belongs to.
    auto names = [](const std::string& target, const std::set<std::string>& headers) {
        return target.find('/') == std::string::npos && headers.count(target) > 0;
    };
    for (const std::string& folder : kScannedFolders) {
        for (const Include& inc : includesUnder(root, folder)) {
            const std::string& t = inc.target;
            if (isFormatLibrary(t) && !startsWith(inc.file, "core/io/"))
                report(inc, "only core/io/ may include " + t);
            if (folder == "core") {
                const std::string own = topFolder(inc.file.substr(5));
                const Layer* layer = layerNamed(own);
                if (!layer) {
                    report(inc, "core/" + own + " is not a layer of the table in LayeringTest.cpp");
                } else if (const std::string used = topFolder(t); layerNamed(used) && used != own &&
                                                                   !layer->mayInclude.count(used)) {
                    report(inc, own + " may not include " + t);
                }
                if (isQtOrGl(t))
                    report(inc, "core includes Qt/GL header " + t);
                if (startsWith(t, "viewport/") || startsWith(t, "widgets/") || names(t, viewportHeaders) ||
                    names(t, widgetsHeaders))
                    report(inc, "core includes " + t + " from viewport/widgets");
            } else if (folder == "viewport" || folder == "widgets") {
                const bool viewport = folder == "viewport";
                const std::string other = viewport ? "widgets" : "viewport";
                const auto& ownHeaders = viewport ? viewportHeaders : widgetsHeaders;
                const auto& otherHeaders = viewport ? widgetsHeaders : viewportHeaders;
                if (startsWith(t, other + "/") || (names(t, otherHeaders) && !ownHeaders.count(t)))
                    report(inc, folder + " includes " + other + " header " + t);
                if (startsWith(t, "rigging/"))
                    report(inc, folder + " includes builder internals " + t + " (use the session or templates)");
            }
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

TEST(Layering, TheSourceTreeBreaksNoRule)
{
    const std::vector<std::string> violations = layeringViolations(RIGSMITH_SOURCE_DIR);
    for (const std::string& v : violations)
        ADD_FAILURE() << v;
    EXPECT_TRUE(violations.empty());
    EXPECT_FALSE(includesUnder(RIGSMITH_SOURCE_DIR, "core").empty()) << "the scanner found the sources";
}

TEST(Layering, ThePlantedViolationsAreReportedAtTheirLines)
{
    const fs::path fixture = fs::path(RIGSMITH_TEST_DATA) / "Layering" / "violations";
    const std::vector<std::string> expected = {
        "app/Bad.cpp:2: only core/io/ may include assimp/scene.h",
        "core/base/Bad.cpp:2: core includes Qt/GL header QtCore/QString",
        "core/base/Bad.cpp:3: core includes OutlinerView.h from viewport/widgets",
        "core/base/Bad.cpp:4: base may not include model/GuideDocument.h",
        "core/extra/Thing.h:2: core/extra is not a layer of the table in LayeringTest.cpp",
        "core/model/Bad.h:3: model may not include rigging/RigBuilder.h",
        "core/templates/Bad.cpp:2: only core/io/ may include io/YamlSupport.h",
        "core/templates/Bad.cpp:2: templates may not include io/YamlSupport.h",
        "core/templates/Bad.cpp:3: only core/io/ may include yaml-cpp/yaml.h",
        "viewport/Bad.h:3: viewport includes widgets header widgets/LogPanel.h",
        "widgets/Bad.cpp:2: only core/io/ may include yaml-cpp/yaml.h",
        "widgets/Bad.cpp:3: widgets includes viewport header ViewportWidget.h",
        "widgets/Bad.cpp:4: widgets includes builder internals rigging/BranchStage.h (use the session or templates)",
    };
    EXPECT_EQ(layeringViolations(fixture), expected);
}

TEST(Layering, EachLayerIncludesOnlyLayersBelowIt)
{
    // The table itself runs one way: no layer names itself, an unknown layer or a later one.
    std::set<std::string> below;
    for (const Layer& layer : kCoreLayers) {
        for (const std::string& used : layer.mayInclude)
            EXPECT_TRUE(below.count(used)) << layer.folder << " may include " << used << ", which is not below it";
        below.insert(layer.folder);
    }
    // Every core folder is in the table.
    for (const auto& e : fs::directory_iterator(fs::path(RIGSMITH_SOURCE_DIR) / "core")) {
        if (e.is_directory()) {
            EXPECT_NE(layerNamed(e.path().filename().string()), nullptr) << "core/" << e.path().filename().string();
        }
    }
}

TEST(Layering, ScannerSeesAQtIncludeAsQt)
{
    // Guards the guard: the patterns must catch the includes they are meant to catch.
    EXPECT_TRUE(isQtOrGl("QWidget"));
    EXPECT_TRUE(isQtOrGl("QtCore/QString"));
    EXPECT_TRUE(isQtOrGl("epoxy/gl.h"));
    EXPECT_TRUE(isQtOrGl("GLFW/glfw3.h"));
    EXPECT_FALSE(isQtOrGl("glm/glm.hpp"));
    EXPECT_TRUE(isFormatLibrary("yaml-cpp/yaml.h"));
    EXPECT_TRUE(isFormatLibrary("tiny_gltf.h"));
    EXPECT_TRUE(isFormatLibrary("assimp/Importer.hpp"));
    EXPECT_FALSE(isFormatLibrary("io/YamlText.h"));
}
