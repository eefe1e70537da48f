// base/TextScalars: the scalars and flow lists every layer reads without yaml-cpp.
// The flow-list reader is also checked against yaml-cpp on the forms it accepts.
#include "base/TextScalars.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

using namespace rs;

namespace {

using Items = std::vector<std::string>;

std::optional<Items> flow(const std::string& text)
{
    auto items = parseFlowList(text);
    EXPECT_EQ(items.ok(), firstError(items.diagnostics()).empty()) << "'" << text << "': an error message exactly when it fails";
    return items ? std::optional(items.take()) : std::nullopt;
}

std::string errorOf(const std::string& text)
{
    const auto items = parseFlowList(text);
    EXPECT_FALSE(items) << text;
    return firstError(items.diagnostics());
}

} // namespace

TEST(TextScalars, ReadsBooleansAsMikansYaml11)
{
    for (const char* t : {"on", "On", "true", "True", "TRUE", "yes", "Yes"})
        EXPECT_EQ(parseBool(t), true) << t;
    for (const char* t : {"off", "Off", "false", "False", "FALSE", "no", "No"})
        EXPECT_EQ(parseBool(t), false) << t;
    for (const char* t : {"", "ON", "y", "1", " on", "maybe"})
        EXPECT_FALSE(parseBool(t)) << t;
}

TEST(TextScalars, ReadsIntegersAndNumbers)
{
    EXPECT_EQ(parseInteger("42"), 42);
    EXPECT_EQ(parseInteger("+7"), 7);
    EXPECT_EQ(parseInteger("-3"), -3);
    for (const char* t : {"", "+", "1.5", " 1", "1 ", "0x10", "1e3", "--1"})
        EXPECT_FALSE(parseInteger(t)) << t;
    EXPECT_EQ(parseNumber("1.5"), 1.5);
    EXPECT_EQ(parseNumber("+2"), 2.0);
    EXPECT_EQ(parseNumber("-1e-3"), -1e-3);
    for (const char* t : {"", "+", "1.5.2", " 1", "abc", "1,5"})
        EXPECT_FALSE(parseNumber(t)) << t;
}

TEST(TextScalars, ReadsFlowListsOfOptions)
{
    EXPECT_EQ(flow("[L, R]"), (Items{"L", "R"}));
    EXPECT_EQ(flow("[hook, world, '*::space.cog']"), (Items{"hook", "world", "*::space.cog"}));
    EXPECT_EQ(flow("up"), (Items{"up"}));
    EXPECT_EQ(flow(""), Items{});
    EXPECT_EQ(flow("   "), Items{});
    EXPECT_EQ(flow("[]"), Items{});
    EXPECT_EQ(flow("[ ]"), Items{});
    EXPECT_EQ(flow("~"), Items{});
    EXPECT_EQ(flow("  [  L ,R  ]  "), (Items{"L", "R"}));
    EXPECT_EQ(flow("[L, R,]"), (Items{"L", "R"})) << "a trailing comma is allowed";
    EXPECT_EQ(flow("[left arm, right arm]"), (Items{"left arm", "right arm"}));
    EXPECT_EQ(flow("['it''s', \"a \\\"b\\\"\", 'x, y']"), (Items{"it's", "a \"b\"", "x, y"}));
    EXPECT_EQ(flow("['']"), (Items{""}));
    EXPECT_EQ(flow("[a:b, c]"), (Items{"a:b", "c"}));
    EXPECT_EQ(flow("[L, R] # mirrored"), (Items{"L", "R"}));
    EXPECT_EQ(flow("'quoted text'"), (Items{"quoted text"}));
}

TEST(TextScalars, RefusesWhatIsNotAFlowListOfPlainValues)
{
    EXPECT_EQ(errorOf("[a, [b]]"), "list items must be plain values");
    EXPECT_EQ(errorOf("[a, {b: 1}]"), "list items must be plain values");
    EXPECT_EQ(errorOf("[a: 1]"), "list items must be plain values");
    EXPECT_EQ(errorOf("[a, ~]"), "list items must be plain values");
    EXPECT_EQ(errorOf("{a: 1}"), "expected a list");
    EXPECT_EQ(errorOf("a: 1"), "expected a list");
    EXPECT_EQ(errorOf("[a, b"), "missing ']' at the end of the list");
    EXPECT_EQ(errorOf("[a, , b]"), "empty list item");
    EXPECT_EQ(errorOf("[a] b"), "unexpected 'b' after the list");
    EXPECT_EQ(errorOf("['a, b]"), "missing closing quote");
    EXPECT_EQ(errorOf("[a b' c, *ref]"), "unsupported YAML syntax '*'");
    EXPECT_EQ(errorOf("- a"), "unsupported YAML syntax '-'");
    EXPECT_EQ(errorOf("[\"\\q\"]"), "unknown escape '\\q' in a quoted item");
}

TEST(TextScalars, FlowListsReadAsYamlCppReadsThem)
{
    // Every form the reader accepts or refuses, compared with yaml-cpp (what
    // io/YamlSupport used before the reader moved to base/). One difference on
    // purpose: yaml-cpp drops text after a closed list ("[a] b" reads as [a]);
    // the reader refuses it (see RefusesWhatIsNotAFlowListOfPlainValues).
    const std::vector<std::string> texts = {
        "[L, R]", "[hook, world, '*::space.cog']", "up", "", "[]", "~", "null", "  [  L ,R  ]  ", "[L, R,]",
        "[left arm, right arm]", "['it''s', \"a \\\"b\\\"\", 'x, y']", "['']", "[a:b, c]", "[L, R] # mirrored",
        "'quoted text'", "[a, [b]]", "[a, {b: 1}]", "[a: 1]", "[a, ~]", "{a: 1}", "a: 1", "[a, b",
        "['a, b]", "[A.L, ft, bk]", "[1, 2.5, on]", "[\"x\ty\"]"};
    for (const std::string& text : texts) {
        std::optional<Items> expected;
        try {
            const YAML::Node node = YAML::Load(text);
            if (node.IsNull()) {
                expected = Items{};
            } else if (node.IsScalar()) {
                expected = Items{node.Scalar()};
            } else if (node.IsSequence()) {
                expected = Items{};
                for (const auto& item : node) {
                    if (!item.IsScalar()) { expected.reset(); break; }
                    expected->push_back(item.Scalar());
                }
            }
        } catch (const YAML::Exception&) {
        }
        auto items = parseFlowList(text);
        const std::string error = firstError(items.diagnostics());
        EXPECT_EQ(items ? std::optional(items.take()) : std::nullopt, expected) << "'" << text << "': " << error;
    }
}
