#include "core/TestSupport.h"
#include "edit/GuideEdits.h"
#include "edit/SkinEdits.h"
#include "io/GuideFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

using namespace rs;

TEST(GuideFile, LoadThenSaveIsByteIdentical)
{
    const std::string original = test::readText(test::samplePath("biped"));
    auto doc = io::readGuideText(original, "biped.yml");
    ASSERT_TRUE(doc.ok()) << formatAll(doc.diagnostics());
    EXPECT_TRUE(doc.diagnostics().empty());
    EXPECT_EQ(io::writeGuideText(*doc), original);
}

TEST(GuideFile, RoundTripsEveryFieldExactly)
{
    model::GuideDocument doc;
    doc.name = "prop 1";
    model::TemplateInstance a;
    a.id = 4;
    a.templateId = "core.joints";
    a.name = "chain";
    a.options = {{"number", 5LL}, {"flag", false}, {"ratio", 0.1}, {"label", std::string("on")},
                 {"pos", Vec3(0.1, -2.5e-7, 3)}};
    a.joints = {{7, 0, {Vec3(0.1, 0.2, 0.3), Vec3(10, -20, 1e-3), Vec3(1, 2, 1)}, {"heel", "bank in"}, {}}};
    doc.insertInstance(a, 0);
    const std::string text = io::writeGuideText(doc);
    auto back = io::readGuideText(text, "x.yml");
    ASSERT_TRUE(back.ok()) << formatAll(back.diagnostics()) << text;
    EXPECT_EQ(*back, doc) << text;
    EXPECT_EQ(io::writeGuideText(*back), text);
}

TEST(GuideFile, ReportsEveryBrokenReferenceWithItsLine)
{
    const std::string text =
        "rigsmith_guide: 1\n"
        "instances:\n"
        "  - id: 1\n    template: core.joints\n    name: a\n    joints:\n      - {id: 1, t: [0, 0, 0]}\n"
        "  - id: 2\n    template: core.joints\n    name: a\n    parent: 1\n    hook: 9\n"
        "    joints:\n      - {id: 2, t: [0, 0, 0]}\n      - {id: 3, parent: 8, t: [0, 1, 0]}\n";
    auto doc = io::readGuideText(text, "g.yml");
    ASSERT_FALSE(doc.ok());
    const auto& d = doc.diagnostics();
    ASSERT_EQ(d.size(), 3u) << formatAll(d);
    EXPECT_EQ(d[0].format(), "g.yml:8:5: error: duplicate instance name 'a'");
    EXPECT_EQ(d[1].format(), "g.yml:8:5: error: instance 'a': hook 9 is not a joint of its parent 'a'");
    EXPECT_EQ(d[2].format(), "g.yml:8:5: error: instance 'a': joint 3 must name a parent joint listed before it");
}

TEST(GuideFile, ReportsMalformedYamlAndWrongTypes)
{
    auto broken = io::readGuideText("rigsmith_guide: 1\ninstances: [\n", "g.yml");
    ASSERT_FALSE(broken.ok());
    EXPECT_EQ(broken.diagnostics()[0].where.line, 3);
    auto typed = io::readGuideText("rigsmith_guide: 1\ninstances:\n  - id: one\n", "g.yml");
    ASSERT_FALSE(typed.ok());
    EXPECT_EQ(typed.diagnostics()[0].format(), "g.yml:3:9: error: instance id must be an integer, got 'one'");
    auto newer = io::readGuideText("rigsmith_guide: 99\n", "g.yml");
    ASSERT_FALSE(newer.ok());
    EXPECT_NE(newer.diagnostics()[0].message.find("newer"), std::string::npos);
    auto other = io::readGuideText("name: x\n", "g.yml");
    ASSERT_FALSE(other.ok());
    EXPECT_NE(other.diagnostics()[0].message.find("not a Rigsmith guide"), std::string::npos);
}

// Mikan's manifests and hand-written guides write lists of names unquoted:
// they load as the quoted text the editor writes.
TEST(GuideFile, AnUnquotedListOfNamesLoadsAsItsQuotedText)
{
    const std::string quoted = test::readText(test::samplePath("vehicle"));
    std::string plain = quoted;
    for (std::size_t at = plain.find("\"[L, R]\""); at != std::string::npos; at = plain.find("\"[L, R]\""))
        plain.replace(at, 8, "[L, R]");
    ASSERT_NE(plain, quoted);
    auto a = io::readGuideText(quoted, "quoted.yml");
    auto b = io::readGuideText(plain, "plain.yml");
    ASSERT_TRUE(a) << formatAll(a.diagnostics());
    ASSERT_TRUE(b) << formatAll(b.diagnostics());
    EXPECT_EQ(*a, *b);
    EXPECT_EQ(io::writeGuideText(*b), io::writeGuideText(*a)) << "written back quoted";
    EXPECT_NE(io::writeGuideText(*b).find("branches: \"[L, R]\""), std::string::npos);
    // Three numbers stay a vector; a list mixing names and numbers is refused at its line.
    auto mixed = io::readGuideText(std::string(quoted).replace(quoted.find("\"[L, R]\""), 8, "[L, 2]"), "mixed.yml");
    EXPECT_FALSE(mixed);
    EXPECT_NE(formatAll(mixed.diagnostics()).find("mixed.yml:"), std::string::npos) << formatAll(mixed.diagnostics());
}

TEST(GuideFile, FailedSaveLeavesThePreviousFileUntouched)
{
    const std::string path = test::temporaryPath("keep.yml");
    std::ofstream(path) << "previous content\n";
    // A full disk: the child may write 1 KB, the guide is larger.
    EXPECT_TRUE(test::runWithFileSizeLimit(1024, [&] {
        const Status saved = io::saveGuideFile(test::loadSample("biped"), path);
        return saved.failed() && saved.message().find("keep.yml: error: cannot write") != std::string::npos;
    }));
    EXPECT_EQ(test::readText(path), "previous content\n");
    EXPECT_TRUE(io::saveGuideFile(test::loadSample("biped"), path).ok());
    EXPECT_EQ(test::readText(path), test::readText(test::samplePath("biped")));
}

TEST(GuideFile, KeepsNamingRulesAndRejectsAnUnknownPreset)
{
    auto doc = io::readGuideText("rigsmith_guide: 1\nnaming: suffix\ninstances: []\n", "g.yml");
    ASSERT_TRUE(doc.ok()) << formatAll(doc.diagnostics());
    EXPECT_EQ(doc->naming.controller, "_ctrl");
    EXPECT_NE(io::writeGuideText(*doc).find("naming: suffix\n"), std::string::npos);
    auto custom = io::readGuideText("rigsmith_guide: 1\nnaming: {preset: suffix, controller: _ctl}\ninstances: []\n", "g.yml");
    ASSERT_TRUE(custom.ok());
    auto again = io::readGuideText(io::writeGuideText(*custom), "g.yml");
    ASSERT_TRUE(again.ok()) << io::writeGuideText(*custom);
    EXPECT_EQ(again->naming, custom->naming);
    EXPECT_EQ(again->naming.controller, "_ctl");
    auto bad = io::readGuideText("rigsmith_guide: 1\nnaming: maya\ninstances: []\n", "g.yml");
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.diagnostics()[0].format(), "g.yml:2:9: error: unknown naming preset 'maya' (known: mikan, suffix)");
}

TEST(GuideFile, KeepsModelsRelativeToTheGuideAndReadsAnOlderReferenceModelAsOne)
{
    const auto dir = std::filesystem::temp_directory_path() / "rigsmith-guidefile-models";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir / "guides");
    model::GuideDocument doc = test::loadSample("biped");
    const model::GuideDocument original = doc;
    edit::History history(doc);
    const std::string model = (dir / "scans" / "actor.fbx").string();
    ASSERT_TRUE(test::succeeded(edit::addModel(history, model)));
    EXPECT_EQ(history.undoText(), "Add model actor.fbx");
    EXPECT_NE(test::refusal(edit::addModel(history, model)), "") << "the same model twice";

    const std::string path = (dir / "guides" / "hero.yml").string();
    ASSERT_TRUE(io::saveGuideFile(doc, path).ok());
    std::ifstream in(path);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("\nmodels:\n  - \"../scans/actor.fbx\"\n"), std::string::npos) << text;
    auto read = io::readGuideFile(path);
    ASSERT_TRUE(read) << formatAll(read.diagnostics());
    EXPECT_EQ(read->models, std::vector<std::string>{model}) << "absolute again in memory";
    EXPECT_TRUE(*read == doc);

    history.undo();
    EXPECT_TRUE(doc == original);

    // A guide written before models existed: its reference model is the first model, written back as one.
    std::ofstream(path) << io::writeGuideText(original) << "reference_model: \"../scans/actor.fbx\"\n";
    auto older = io::readGuideFile(path);
    ASSERT_TRUE(older) << formatAll(older.diagnostics());
    EXPECT_EQ(older->models, std::vector<std::string>{model});
    EXPECT_EQ(io::writeGuideText(*older).find("reference_model"), std::string::npos);
}
