// Issue 18 items 5, 6, 8, 9 and 11: hostile input gets a clear error at its
// file:line, never a crash, a hang or a path out of its folder.
#include "core/TestSupport.h"
#include "io/GuideFile.h"
#include "io/ManifestReader.h"
#include "io/RigExport.h"
#include "io/ShapeFile.h"
#include "io/TemplateFolders.h"
#include "io/YamlText.h"
#include "rigging/RigBuilder.h"
#include "templates/Condition.h"
#include "templates/TemplateRegistry.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

using namespace rs;
namespace fs = std::filesystem;

namespace {

std::string guideWithInstance(const std::string& name, const std::string& options, const std::string& translate)
{
    return "rigsmith_guide: 1\n"
           "instances:\n"
           "  - id: 1\n"
           "    template: core.joints\n"
           "    name: " + name + "\n" // line 5
           "    options: {" + options + "}\n" // line 6
           "    joints:\n"
           "      - {id: 1, t: " + translate + "}\n"; // line 8
}

Result<templates::TemplateManifest> manifest(const std::string& text)
{
    return io::readManifestText(text, "tpl/template.yml", "arm", "test");
}

// Nested aliases: 9 levels of 9 copies expand to 9^9 (387 million) scalars.
std::string billionLaughs(const std::string& prefix)
{
    std::string text = prefix + "a0: &a0 [x, x, x, x, x, x, x, x, x]\n";
    for (int level = 1; level < 9; ++level) {
        const std::string previous = "*a" + std::to_string(level - 1);
        text += "a" + std::to_string(level) + ": &a" + std::to_string(level) + " [";
        for (int k = 0; k < 9; ++k)
            text += (k ? ", " : "") + previous;
        text += "]\n";
    }
    return text;
}

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A FIFO nobody writes to: opening it for reading blocks unless the reader refuses it.
fs::path makeFifo(const fs::path& path)
{
    fs::create_directories(path.parent_path());
    fs::remove(path);
    EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0);
    return path;
}

} // namespace

TEST(GuideFile, RefusesANameThatIsNotUtf8AtItsLine)
{
    auto doc = io::readGuideText(guideWithInstance("arm\xff", "", "[0, 0, 0]"), "g.yml");
    ASSERT_FALSE(doc.ok());
    ASSERT_EQ(doc.diagnostics().size(), 1u) << formatAll(doc.diagnostics());
    EXPECT_EQ(doc.diagnostics()[0].format(), "g.yml:5:11: error: text is not valid UTF-8 (byte 0xff at offset 3 of the value)");
    // An escape for a lone UTF-16 surrogate is refused by the YAML parser itself.
    auto escaped = io::readGuideText(guideWithInstance("\"arm\\udc00\"", "", "[0, 0, 0]"), "g.yml");
    ASSERT_FALSE(escaped.ok());
    EXPECT_NE(escaped.diagnostics()[0].format().find("g.yml:5:"), std::string::npos) << formatAll(escaped.diagnostics());
    EXPECT_TRUE(io::readGuideText(guideWithInstance("bras_gauche_é_腕", "", "[0, 0, 0]"), "g.yml").ok());
}

TEST(ManifestReader, RefusesTextThatIsNotUtf8AtItsLine)
{
    auto m = manifest("name: arm\nnames:\n  ctrls.fk: \"fk\xc0\xaf\"\n");
    ASSERT_FALSE(m.ok());
    EXPECT_EQ(m.diagnostics()[0].format(), "tpl/template.yml:3:13: error: text is not valid UTF-8 (byte 0xc0 at offset 2 of the value)");
}

TEST(GltfExport, ReportsANameThatIsNotUtf8InsteadOfThrowing)
{
    model::Rig rig = rigging::buildRig(test::loadSample("prop"), test::builtinTemplates());
    ASSERT_FALSE(rig.nodes.empty());
    rig.nodes.back().name += "\xff";
    for (const char* file : {"bad-name.gltf", "bad-name.glb", "bad-name.fbx"}) {
        const std::string path = test::temporaryPath(file);
        fs::remove(path);
        Diagnostics d;
        EXPECT_NO_THROW(d = io::exportRig(rig, path));
        ASSERT_TRUE(hasErrors(d)) << file;
        EXPECT_NE(firstError(d).find("is not valid UTF-8"), std::string::npos) << formatAll(d);
        EXPECT_FALSE(fs::exists(path)) << file;
    }
}

TEST(Condition, RefusesExpressionsNestedTooDeeply)
{
    const std::map<std::string, Value> options{{"on_", true}};
    for (const std::string& opener : {std::string("("), std::string("not ")}) {
        std::string deep;
        for (int i = 0; i < 200000; ++i) deep += opener;
        deep += "on_";
        if (opener == "(") deep += std::string(200000, ')');
        const auto holds = templates::evaluateCondition(deep, options);
        ASSERT_FALSE(holds.ok()) << opener;
        EXPECT_NE(firstError(holds.diagnostics()).find("nested too deeply"), std::string::npos) << firstError(holds.diagnostics());
    }
    // At the cap it still evaluates.
    std::string atCap(templates::kMaxConditionDepth, '(');
    atCap += "on_" + std::string(templates::kMaxConditionDepth, ')');
    const auto holds = templates::evaluateCondition(atCap, options);
    ASSERT_TRUE(holds.ok()) << formatAll(holds.diagnostics());
    EXPECT_TRUE(*holds);
}

TEST(GuideFile, RefusesNanAndInfinityAtTheirLine)
{
    auto option = io::readGuideText(guideWithInstance("arm", "length: nan", "[0, 0, 0]"), "g.yml");
    ASSERT_FALSE(option.ok());
    EXPECT_EQ(option.diagnostics()[0].format(), "g.yml:6:23: error: option length must be a finite number, got 'nan' (quote it for text)");
    auto joint = io::readGuideText(guideWithInstance("arm", "", "[0, -inf, 0]"), "g.yml");
    ASSERT_FALSE(joint.ok());
    EXPECT_EQ(joint.diagnostics()[0].format(),
              "g.yml:8:24: error: joint translate 't' must be a list of 3 finite numbers, got '-inf' at index 1");
    auto quoted = io::readGuideText(guideWithInstance("arm", "label: 'nan'", "[0, 0, 0]"), "g.yml");
    EXPECT_TRUE(quoted.ok()) << formatAll(quoted.diagnostics());
}

TEST(ManifestReader, RefusesNanAndInfinityAtTheirLine)
{
    auto m = manifest("name: arm\nguides:\n  length:\n    value: 1\n    min: NaN\n    max: infinity\n"
                      "shapes:\n  ctrls.a:\n    shape: circle\n    size: inf\n");
    ASSERT_FALSE(m.ok());
    ASSERT_EQ(m.diagnostics().size(), 3u) << formatAll(m.diagnostics());
    EXPECT_EQ(m.diagnostics()[0].format(), "tpl/template.yml:5:10: error: guides.length.min must be a finite number, got 'NaN'");
    EXPECT_EQ(m.diagnostics()[1].format(), "tpl/template.yml:6:10: error: guides.length.max must be a finite number, got 'infinity'");
    EXPECT_EQ(m.diagnostics()[2].format(), "tpl/template.yml:10:11: error: shapes.ctrls.a.size must be a finite number, got 'inf'");
}

TEST(ShapeFile, RefusesANanPointAtItsLine)
{
    Diagnostics d;
    EXPECT_FALSE(io::readShapeText("- degree: 1\n  points: [[0, 0, 0], [nan, 1, 0]]\n", "shapes/bad.yml", d));
    ASSERT_FALSE(d.empty());
    EXPECT_EQ(d[0].format(), "shapes/bad.yml:2:24: error: curve 0 point must be a list of 3 finite numbers, got 'nan' at index 0");
}

TEST(RigBuilder, RefusesANonFiniteOptionSetByAnEdit)
{
    model::GuideDocument guide = test::loadSample("prop");
    model::TemplateInstance* antenna = guide.instance(guide.instanceNamed("antenna")->id);
    for (const double bad : {std::nan(""), std::numeric_limits<double>::infinity()}) {
        antenna->options["length"] = bad;
        const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
        ASSERT_TRUE(hasErrors(rig.diagnostics));
        EXPECT_NE(formatAll(rig.diagnostics).find("option 'length' = " + formatValue(Value(bad)) + " is not a finite number"),
                  std::string::npos) << formatAll(rig.diagnostics);
        EXPECT_EQ(formatAll(rig.diagnostics).find("using nan"), std::string::npos);
    }
}

TEST(GuideFile, RefusesNestedAliasesQuickly)
{
    const auto start = std::chrono::steady_clock::now();
    auto doc = io::readGuideText(billionLaughs("rigsmith_guide: 1\n"), "g.yml");
    EXPECT_LT(secondsSince(start), 2.0);
    ASSERT_FALSE(doc.ok());
    EXPECT_NE(firstError(doc.diagnostics()).find("aliases of aliases"), std::string::npos) << formatAll(doc.diagnostics());
    EXPECT_EQ(doc.diagnostics()[0].where.file, "g.yml");
}

TEST(ManifestReader, RefusesNestedAliasesQuickly)
{
    const auto start = std::chrono::steady_clock::now();
    auto m = manifest(billionLaughs("name: arm\n"));
    EXPECT_LT(secondsSince(start), 2.0);
    ASSERT_FALSE(m.ok());
    EXPECT_NE(firstError(m.diagnostics()).find("aliases of aliases"), std::string::npos) << formatAll(m.diagnostics());
}

TEST(YamlText, RefusesAFifoWithoutWaiting)
{
    const fs::path fifo = makeFifo(test::temporaryPath("hostile-fifo/guide.yml"));
    const auto start = std::chrono::steady_clock::now();
    auto guide = io::readGuideFile(fifo.string());
    ASSERT_FALSE(guide.ok());
    EXPECT_EQ(guide.diagnostics()[0].format(), fifo.string() + ": error: not a regular file (a FIFO, socket or device); refused");
    Diagnostics shape;
    EXPECT_FALSE(io::readShapeFile(fifo.string(), shape));
    EXPECT_FALSE(io::readManifest(fifo.string(), "arm", "limb").ok());
    EXPECT_FALSE(io::readTextFile(fifo.parent_path().string()).ok()); // a folder
    EXPECT_LT(secondsSince(start), 2.0);
}

TEST(TemplateFolders, RefusesATemplateManifestThatIsAFifo)
{
    const fs::path folder = test::temporaryPath("hostile-templates");
    fs::remove_all(folder);
    const fs::path fifo = makeFifo(folder / "arm" / "stuck" / "template.yml");
    templates::TemplateRegistry registry;
    const Diagnostics d = io::scanTemplates(registry, {folder.string()}, test::dataPath("none"));
    ASSERT_TRUE(hasErrors(d));
    EXPECT_NE(formatAll(d).find(fifo.string() + ": error: not a regular file"), std::string::npos) << formatAll(d);
    EXPECT_EQ(registry.find("arm.stuck"), nullptr);
}

TEST(YamlText, RefusesAFileLargerThanTheLimit)
{
    const std::string path = test::temporaryPath("hostile-huge.yml");
    { std::ofstream(path) << "rigsmith_guide: 1\n"; }
    fs::resize_file(path, io::kMaxTextFileBytes + 1); // sparse: no disk used
    auto text = io::readTextFile(path);
    fs::remove(path);
    ASSERT_FALSE(text.ok());
    EXPECT_NE(firstError(text.diagnostics()).find("larger than the 128 MB limit"), std::string::npos) << formatAll(text.diagnostics());
}

TEST(ManifestReader, RefusesIconPathsOutsideTheIconsFolder)
{
    for (const char* icon : {"../../../etc/passwd", "/etc/passwd", "\"limb\\0.svg\"", "sub/limb", ".hidden", "..", "a\\\\b"}) {
        auto m = manifest(std::string("name: arm\nui:\n  icon: ") + icon + "\n");
        ASSERT_FALSE(m.ok()) << icon;
        EXPECT_EQ(m.diagnostics()[0].format(),
                  "tpl/template.yml:3:9: error: ui.icon must be a file name in the icons folder (letters, digits, _ - .), not a path")
            << icon;
    }
    EXPECT_TRUE(manifest("name: arm\nui:\n  icon: limb-2.v1\n").ok());
}

TEST(TemplateRegistry, IconPathNeverLeavesTheIconsFolder)
{
    const fs::path icons = fs::path(test::temporaryPath("hostile-icons")) / "icons";
    fs::create_directories(icons);
    { std::ofstream(icons.parent_path() / "secret.svg") << "<svg/>"; }
    { std::ofstream(icons / "template.svg") << "<svg/>"; }
    templates::TemplateRegistry registry;
    registry.reset(icons.string());
    templates::TemplateManifest m;
    for (const std::string& icon : std::vector<std::string>{"../secret", icons.parent_path().string() + "/secret", std::string("template\0x", 10)}) {
        m.icon = icon;
        EXPECT_EQ(registry.iconPath(m), (icons / "template.svg").string()) << icon;
    }
}
