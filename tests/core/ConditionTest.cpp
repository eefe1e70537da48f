#include "templates/Condition.h"

#include <gtest/gtest.h>

using namespace rs;
using namespace rs::templates;

TEST(Condition, EvaluatesBooleanExpressionsOverOptions)
{
    const std::map<std::string, Value> options{{"clavicle", true}, {"unchain", false}, {"orient", std::string("auto")},
                                               {"count", 3LL}};
    auto value = [&](const std::string& expression) {
        const auto holds = evaluateCondition(expression, options);
        EXPECT_TRUE(holds) << expression << ": " << formatAll(holds.diagnostics());
        return holds ? std::optional(*holds) : std::nullopt;
    };
    EXPECT_EQ(value("clavicle"), true);
    EXPECT_EQ(value("not unchain"), true);
    EXPECT_EQ(value("orient == auto"), true);
    EXPECT_EQ(value("orient != 'auto'"), false);
    EXPECT_EQ(value("clavicle and (unchain or count == 3)"), true);
    EXPECT_EQ(value("count"), true);
}

TEST(Condition, RejectsUnknownOptionsAndBadSyntaxWithoutRunningAnything)
{
    const std::map<std::string, Value> options{{"a", true}};
    auto errorOf = [&](const std::string& expression) {
        const auto holds = evaluateCondition(expression, options);
        EXPECT_FALSE(holds) << expression;
        return firstError(holds.diagnostics());
    };
    EXPECT_EQ(errorOf("b"), "unknown option 'b'");
    EXPECT_EQ(errorOf("(a"), "missing ')'");
    EXPECT_EQ(errorOf("a and"), "expression ends too early");
    EXPECT_NE(errorOf("__import__('os')"), "");
}
