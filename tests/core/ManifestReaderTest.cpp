#include "core/TestSupport.h"
#include "io/ManifestReader.h"
#include "io/TemplateFolders.h"
#include "templates/TemplateRegistry.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

using namespace rs;
using namespace rs::templates;

namespace {
Result<TemplateManifest> read(const std::string& text)
{
    return io::readManifestText(text, "tpl/template.yml", "arm", "test");
}
} // namespace

TEST(ManifestReader, ReadsBuiltinJointsTemplate)
{
    const TemplateManifest* m = test::builtinTemplates().find("core.joints");
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(m->id, "core.joints");
    EXPECT_EQ(m->name, "joints");
    ASSERT_NE(m->findGuide("number"), nullptr);
    EXPECT_EQ(std::get<long long>(m->findGuide("number")->value), 3);
    EXPECT_EQ(m->findGuide("number")->min, 1.0);
    EXPECT_EQ(m->icon, "bone");
    ASSERT_EQ(m->hooks.size(), 2u);
    EXPECT_EQ(m->hooks[0].label, "default");
    EXPECT_EQ(m->hooks[0].structure, "chain[-1]");
    EXPECT_NE(m->findOpt("do_skin"), nullptr) << "common options are layered under every template";
}

TEST(ManifestReader, ReportsMalformedYamlWithLineAndColumn)
{
    auto r = read("name: arm\nstructure:\n  limb1: .\n  limb2: [/1\n");
    ASSERT_FALSE(r.ok());
    ASSERT_EQ(r.diagnostics().size(), 1u);
    const Diagnostic& d = r.diagnostics()[0];
    EXPECT_EQ(d.where.file, "tpl/template.yml");
    EXPECT_EQ(d.where.line, 5);
    EXPECT_GT(d.where.column, 0);
    EXPECT_NE(d.format().find("tpl/template.yml:5:"), std::string::npos) << d.format();
    EXPECT_NE(d.message.find("malformed YAML"), std::string::npos);
}

TEST(ManifestReader, ReportsWrongTypesAtTheirPosition)
{
    auto r = read("name: arm\nguides:\n  number:\n    value: 3\n    min: lots\nshapes:\n  ctrls.0:\n    shape: circle\n    size: [1, 2]\n");
    ASSERT_FALSE(r.ok());
    ASSERT_EQ(r.diagnostics().size(), 2u) << formatAll(r.diagnostics());
    EXPECT_EQ(r.diagnostics()[0].format(), "tpl/template.yml:5:10: error: guides.number.min must be a number, got 'lots'");
    EXPECT_EQ(r.diagnostics()[1].format(), "tpl/template.yml:9:11: error: shapes.ctrls.0.size must be a number, got a list of 2 items");
}

TEST(ManifestReader, WarnsAboutUnknownKeysWithoutFailing)
{
    auto r = read("name: arm\nguide:\n  number: 3\nui:\n  icon: limb\n  colour: red\n");
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.diagnostics().size(), 2u);
    EXPECT_EQ(r.diagnostics()[0].format(), "tpl/template.yml:2:1: warning: unknown key 'guide' (ignored)");
    EXPECT_EQ(r.diagnostics()[1].format(), "tpl/template.yml:6:3: warning: unknown key 'colour' in ui");
}

TEST(ManifestReader, TypesValuesAndStoresEnumsAsLabels)
{
    auto r = read("opts:\n  flag: {value: on}\n  count: {value: 2}\n  ratio: {value: 0.5}\n  label: {value: hello}\n"
                  "  pos: {value: [1, 2, 3]}\n  orient: {value: 1, enum: [auto, copy, world]}\n"
                  "  axis: {value: y, enum: {0: x, 1: y, 2: z}}\n");
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics());
    const TemplateManifest& m = *r;
    EXPECT_EQ(m.findOpt("flag")->value, Value(true));
    EXPECT_EQ(m.findOpt("count")->value, Value(2LL));
    EXPECT_EQ(m.findOpt("ratio")->value, Value(0.5));
    EXPECT_EQ(m.findOpt("label")->value, Value(std::string("hello")));
    EXPECT_EQ(m.findOpt("pos")->value, Value(Vec3(1, 2, 3)));
    EXPECT_EQ(m.findOpt("orient")->value, Value(std::string("copy")));
    EXPECT_EQ(m.findOpt("axis")->value, Value(std::string("y")));
}

TEST(ManifestReader, ClampsOutOfRangeDefaultsWithAWarning)
{
    auto r = read("guides:\n  number: {value: 0, min: 1, max: 8}\n");
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->findGuide("number")->value, Value(1LL));
    ASSERT_EQ(r.diagnostics().size(), 1u);
    EXPECT_EQ(r.diagnostics()[0].format(), "tpl/template.yml:2:19: warning: guides.number.value 0 is out of range, clamped to 1");
}

TEST(ManifestReader, OverridesOnePropertyOfACommonOption)
{
    auto r = read("opts:\n  branches:\n    value: '[L, R]'\n  own: {value: off}\n");
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics());
    const Parameter* branches = r->findOpt("branches");
    ASSERT_NE(branches, nullptr);
    EXPECT_EQ(branches->value, Value(std::string("[L, R]")));
    EXPECT_TRUE(branches->yaml) << "the other properties come from the common option";
    EXPECT_EQ(r->opts.front().name, "branches");
    EXPECT_EQ(r->opts.size(), io::commonOptions().size() + 1);
}

TEST(ManifestReader, RejectsAnEnumValueThatIsNoLabel)
{
    auto r = read("opts:\n  orient: {value: sideways, enum: [auto, copy]}\n");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.diagnostics()[0].format(), "tpl/template.yml:2:19: error: opts.orient.value 'sideways' is not one of the enum labels");
}

TEST(TemplateRegistry, ScansUserFoldersFromTheTemplatePathOverBuiltins)
{
    const std::filesystem::path user = test::temporaryPath("user-templates");
    std::filesystem::create_directories(user / "prop" / "lamp");
    std::filesystem::create_directories(user / "core" / "joints");
    std::ofstream(user / "prop" / "lamp" / "template.yml") << "name: lamp\ndesc: A lamp.\nstructure:\n  chain: /*\n";
    std::ofstream(user / "core" / "joints" / "template.yml") << "name: bones\nstructure:\n  chain: /*\n";
    ::setenv("RIGSMITH_TEMPLATE_PATH", ("/nonexistent/folder:" + user.string()).c_str(), 1);
    Diagnostics d;
    auto registry = io::loadDefaultTemplates(d);
    ::unsetenv("RIGSMITH_TEMPLATE_PATH");
    ASSERT_NE(registry->find("prop.lamp"), nullptr);
    EXPECT_EQ(registry->find("prop.lamp")->desc, "A lamp.");
    EXPECT_EQ(registry->find("core.joints")->name, "bones") << "a later folder overrides a built-in id";
    EXPECT_NE(registry->find("world.character"), nullptr);
    ASSERT_FALSE(d.empty());
    EXPECT_EQ(d[0].format(), "/nonexistent/folder: warning: template folder does not exist");
}

TEST(TemplateRegistry, AMissingIconFallsBackWithAWarningAtItsLine)
{
    const std::string folder = test::temporaryPath("icon-templates");
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder + "/extra/odd");
    std::ofstream(folder + "/extra/odd/template.yml") << "name: odd\nui:\n  icon: no_such_icon\n";
    TemplateRegistry registry;
    const std::string icons = std::string(RIGSMITH_SOURCE_DIR) + "/resources/icons";
    const Diagnostics d = io::scanTemplates(registry, {folder}, icons);
    ASSERT_EQ(d.size(), 1u) << formatAll(d);
    EXPECT_EQ(d[0].format(), folder + "/extra/odd/template.yml:3:9: warning: icon 'no_such_icon' not found in " + icons +
                                 " (the default icon is used)");
    EXPECT_EQ(registry.iconPath(*registry.find("extra.odd")), icons + "/template.svg");
}

// Mikan's digit.legacy clears a hook in a conditional override with a bare
// `hook:`; a YAML null where a value may be unset means "unset", not an error.
TEST(ManifestReader, AYamlNullUnsetsAHookOrParentInsteadOfFailing)
{
    auto r = read("name: digit\n"
                  "structure:\n  chain: /*\n  base: chain[:-1]\n"
                  "opts:\n  shear:\n    value: off\n"
                  "hierarchy:\n"
                  "  skin:\n    hook: base\n    chain: on\n"
                  "    opts:\n      shear:\n        chain: off\n        hook:\n"
                  "  ctrls:\n    parent:\n    root:\n    hook: base\n");
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics());
    EXPECT_FALSE(hasErrors(r.diagnostics()));
    const auto& h = r->hierarchy;
    ASSERT_EQ(h.size(), 2u);
    ASSERT_EQ(h[0].conditional.size(), 1u);
    const HierarchyRule& shear = h[0].conditional[0].second;
    ASSERT_TRUE(shear.hook.has_value()) << "a null hook overrides the base rule's";
    EXPECT_TRUE(shear.hook->empty());
    EXPECT_EQ(shear.chain, std::optional<bool>(false));
    ASSERT_TRUE(h[0].base.hook.has_value());
    EXPECT_EQ(*h[0].base.hook, std::vector<std::string>{"base"});
    ASSERT_TRUE(h[1].base.parent.has_value());
    EXPECT_TRUE(h[1].base.parent->empty());
    EXPECT_FALSE(h[1].base.root.has_value()) << "a null root leaves it unset";
}
