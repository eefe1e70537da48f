// Golden tests of the template format, one case per folder:
//   tests/data/ManifestReader/<case>/template.yml -> what was understood of every key
//   tests/data/Structure/<case>/{template.yml,guide.yml} -> joints of every tag and hook
//   tests/data/Malformed/<case>/{template.yml|shape.yml} -> the exact diagnostics
// Add a folder to add a case; RIGSMITH_UPDATE_GOLDEN=1 writes expected.txt.
#include "rigging/RigBuilder.h"
#include "core/TestSupport.h"
#include "io/GuideFile.h"
#include "templates/ManifestDump.h"
#include "io/ManifestReader.h"
#include "io/ShapeFile.h"
#include "templates/HookPoints.h"
#include "templates/ShapeLibrary.h"
#include "templates/Structure.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

using namespace rs;

namespace {

std::vector<std::string> casesIn(const std::string& suite)
{
    std::vector<std::string> out;
    for (const auto& entry : std::filesystem::directory_iterator(test::dataPath(suite)))
        if (entry.is_directory())
            out.push_back(entry.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
}

std::string caseName(const ::testing::TestParamInfo<std::string>& info) { return info.param; }

Result<templates::TemplateManifest> readCaseManifest(const std::string& suite, const std::string& name, const std::string& module)
{
    const std::string text = test::readText(test::dataPath(suite + "/" + name + "/template.yml"));
    return io::readManifestText(text, name + "/template.yml", "test", module);
}

std::string diagnosticLines(const Diagnostics& diagnostics)
{
    std::string out;
    for (const auto& d : diagnostics)
        out += d.format() + "\n";
    return out;
}

} // namespace

class ManifestGolden : public ::testing::TestWithParam<std::string> {};

TEST_P(ManifestGolden, DescribesEveryKeyAsWritten)
{
    auto manifest = readCaseManifest("ManifestReader", GetParam(), GetParam());
    std::string out = diagnosticLines(manifest.diagnostics());
    ASSERT_TRUE(manifest.ok()) << out;
    out += "---\n" + templates::describeManifest(*manifest);
    test::expectMatchesGolden(out, "ManifestReader/" + GetParam() + "/expected.txt");
}

INSTANTIATE_TEST_SUITE_P(Cases, ManifestGolden, ::testing::ValuesIn(casesIn("ManifestReader")), caseName);

class StructureGolden : public ::testing::TestWithParam<std::string> {};

TEST_P(StructureGolden, ResolvesEveryTagAndHook)
{
    const std::string dir = test::dataPath("Structure/" + GetParam());
    auto guide = io::readGuideFile(dir + "/guide.yml");
    ASSERT_TRUE(guide.ok()) << formatAll(guide.diagnostics());
    std::ostringstream out;
    for (const model::TemplateInstance& instance : guide->instances()) {
        const std::string module = instance.templateId.substr(instance.templateId.find('.') + 1);
        auto manifest = readCaseManifest("Structure", GetParam(), module);
        ASSERT_TRUE(manifest.ok()) << formatAll(manifest.diagnostics());
        out << "instance " << instance.name << ":\n";
        templates::StructureResolver resolver(*manifest, instance);
        for (const auto& [tag, address] : manifest->structure) {
            auto joints = resolver.tag(tag);
            auto override = instance.structure.find(tag);
            if (override != instance.structure.end())
                out << "  " << tag << " (instance override " << override->second << "): ";
            else
                out << "  " << tag << " (" << (address.empty() ? "explicit" : address) << "): ";
            if (!joints) {
                out << "error: " << firstError(joints.diagnostics()) << '\n';
                continue;
            }
            out << '[';
            for (std::size_t i = 0; i < joints->size(); ++i)
                out << (i ? ", " : "") << (*joints)[i];
            out << "]\n";
        }
        for (const templates::HookPoint& hook : templates::hookPoints(*manifest, instance))
            out << "  hook " << hook.label << ": " << hook.joint << '\n';
    }
    test::expectMatchesGolden(out.str(), "Structure/" + GetParam() + "/expected.txt");
}

INSTANTIATE_TEST_SUITE_P(Cases, StructureGolden, ::testing::ValuesIn(casesIn("Structure")), caseName);

class MalformedCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(MalformedCorpus, GivesTheExactMessageAndNeverCrashes)
{
    const std::string dir = test::dataPath("Malformed/" + GetParam());
    Diagnostics diagnostics;
    bool loaded = false;
    if (std::filesystem::exists(dir + "/shape.yml")) {
        loaded = io::readShapeText(test::readText(dir + "/shape.yml"), GetParam() + "/shape.yml", diagnostics).has_value();
    } else {
        auto manifest = readCaseManifest("Malformed", GetParam(), "case");
        loaded = manifest.ok();
        diagnostics = manifest.diagnostics();
    }
    ASSERT_FALSE(diagnostics.empty()) << "a corpus case must produce a diagnostic";
    EXPECT_EQ(loaded, !hasErrors(diagnostics)) << "errors refuse the file; warnings never do";
    test::expectMatchesGolden(diagnosticLines(diagnostics), "Malformed/" + GetParam() + "/expected.txt");
}

INSTANTIATE_TEST_SUITE_P(Cases, MalformedCorpus, ::testing::ValuesIn(casesIn("Malformed")), caseName);

TEST(MalformedCorpus, HoldsAtLeastThirtyCases)
{
    EXPECT_GE(casesIn("Malformed").size(), 30u);
}
