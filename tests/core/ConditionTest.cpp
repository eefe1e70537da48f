#include "templates/Condition.h"

#include <gtest/gtest.h>

using namespace rs;
using namespace rs::templates;

TEST(Condition, EvaluatesBooleanExpressionsOverOptions)
{
    const std::map<std::string, Value> options{{"clavicle", true}, {"unchain", false}, {"orient", std::string("auto")},
                                               {"count", 3LL}};
    std::string error;
    EXPECT_EQ(evaluateCondition("clavicle", options, error), true);
    EXPECT_EQ(evaluateCondition("not unchain", options, error), true);
    EXPECT_EQ(evaluateCondition("orient == auto", options, error), true);
    EXPECT_EQ(evaluateCondition("orient != 'auto'", options, error), false);
    EXPECT_EQ(evaluateCondition("clavicle and (unchain or count == 3)", options, error), true);
    EXPECT_EQ(evaluateCondition("count", options, error), true);
}

TEST(Condition, RejectsUnknownOptionsAndBadSyntaxWithoutRunningAnything)
{
    const std::map<std::string, Value> options{{"a", true}};
    std::string error;
    EXPECT_FALSE(evaluateCondition("b", options, error));
    EXPECT_EQ(error, "unknown option 'b'");
    EXPECT_FALSE(evaluateCondition("(a", options, error));
    EXPECT_EQ(error, "missing ')'");
    EXPECT_FALSE(evaluateCondition("a and", options, error));
    EXPECT_EQ(error, "expression ends too early");
    EXPECT_FALSE(evaluateCondition("__import__('os')", options, error));
}
