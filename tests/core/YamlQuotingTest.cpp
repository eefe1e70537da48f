// Issue 18 item 3: a name or text that YAML would read as something else (a
// null, a bool, a number, syntax) is quoted, so every guide Rigsmith saves opens.
#include "io/GuideFile.h"
#include "io/YamlText.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <string>
#include <vector>

using namespace rs;

namespace {

// Every YAML 1.1 / 1.2 special form we know of, and a few plain names that must stay plain.
std::vector<std::string> specialForms()
{
    std::vector<std::string> forms = {
        "null", "Null", "NULL", "~", "nULL",
        "1e3", "1E3", "-1e3", "+1", "-1", "1", "0", "1.5", ".5", "5.", "-.5", "1_000", "1,000", "0x1F", "0X1f", "0o17",
        "0b101", "017", "1:30", "190:20:30", "2001-12-14", "2001-12-14t21:59:43.10-05:00", ".inf", "-.inf", "+.inf",
        ".Inf", ".INF", ".nan", ".NaN", ".NAN", "nan", "NaN", "inf", "Infinity", "-inf",
        " leading", "trailing ", " both ", "two  spaces", "a: b", "a:b", ":", "key:", "a #b", "#", "# comment", "- ",
        "- x", "-", "--", "---", "...", "[", "]", "[x]", "{", "}", "{x: y}", "&", "&anchor", "*", "*alias", "!", "!tag",
        "!!str", "|", ">", "|-", "%", "%YAML", "@", "@x", "`", "`x`", "'", "\"", "'x'", "\"x\"", "it's", "say \"hi\"",
        "", "a\nb", "\n", "a\tb", "\t", "a\rb", "back\\slash", "?", "? x", ",", "a,b", "=", "<<", "\x01", "\x7f",
        "ünïcödé", "日本語", "emoji 🦴", "x y", "/abs/path", "_", "joint_1", "2ndJoint", "arm.L",
    };
    for (const char* word : {"y", "n", "yes", "no", "on", "off", "true", "false"}) {
        std::string lower = word, upper = word, title = word;
        for (char& c : upper) c = char(std::toupper(static_cast<unsigned char>(c)));
        title[0] = char(std::toupper(static_cast<unsigned char>(title[0])));
        for (const std::string& form : {lower, upper, title})
            if (std::find(forms.begin(), forms.end(), form) == forms.end())
                forms.push_back(form);
    }
    return forms;
}

} // namespace

TEST(YamlQuoting, EverySpecialFormReadsBackAsTheSameString)
{
    for (const std::string& form : specialForms()) {
        const std::string text = "key: " + io::quoteIfNeeded(form) + "\n" + io::quoteIfNeeded(form) + ": value\n";
        YAML::Node node;
        ASSERT_NO_THROW(node = YAML::Load(text)) << "'" << form << "' written as " << text;
        ASSERT_TRUE(node["key"].IsScalar()) << "'" << form << "' written as " << text;
        EXPECT_EQ(node["key"].Scalar(), form) << text;
        const bool plain = io::quoteIfNeeded(form) == form;
        EXPECT_TRUE(!plain || node["key"].Tag() == "?") << text; // a plain scalar stays an untyped string
        ASSERT_EQ(node.size(), 2u) << text;
        auto key = ++node.begin();
        EXPECT_EQ(key->first.Scalar(), form) << text;
    }
    EXPECT_EQ(io::quoteIfNeeded("arm.L"), "arm.L") << "ordinary names stay plain";
    EXPECT_EQ(io::quoteIfNeeded("joint_1"), "joint_1");
    EXPECT_EQ(io::quoteIfNeeded("Null"), "\"Null\"");
}

TEST(YamlQuoting, AGuideWithSpecialNamesSavesAndOpensWithTheSameNames)
{
    model::GuideDocument doc;
    doc.name = "Null";
    model::InstanceId id = 1;
    model::JointId joint = 1;
    for (const std::string& form : specialForms()) {
        model::TemplateInstance instance;
        instance.id = id++;
        instance.templateId = "core.joints";
        instance.name = form.empty() ? "empty" : form;
        instance.options = {{"label", form}};
        instance.names = {{form, form}};
        instance.structure = {{"chain", form}};
        instance.joints = {{joint++, 0, {}, form.empty() ? std::vector<std::string>{} : std::vector<std::string>{form}, form}};
        doc.insertInstance(instance, doc.instances().size());
    }
    const std::string text = io::writeGuideText(doc);
    auto back = io::readGuideText(text, "special.yml");
    ASSERT_TRUE(back.ok()) << formatAll(back.diagnostics());
    ASSERT_EQ(back->instances().size(), doc.instances().size());
    for (std::size_t i = 0; i < doc.instances().size(); ++i) {
        const auto& a = doc.instances()[i];
        const auto& b = back->instances()[i];
        EXPECT_EQ(b.name, a.name);
        EXPECT_EQ(b.options, a.options) << a.name;
        EXPECT_EQ(b.names, a.names) << a.name;
        EXPECT_EQ(b.structure, a.structure) << a.name;
        EXPECT_EQ(b.joints[0].name, a.joints[0].name);
        EXPECT_EQ(b.joints[0].tags, a.joints[0].tags);
    }
    EXPECT_EQ(*back, doc);
    EXPECT_EQ(io::writeGuideText(*back), text);
}
