#pragma once
// Conditions in manifest `hierarchy.<id>.opts` keys: boolean expressions over
// option values, parsed by a small safe parser (no code runs from data).
// Grammar: expr := and ('or' and)*; and := unary ('and' unary)*;
// unary := 'not' unary | '(' expr ')' | operand [('=='|'!=') operand];
// an operand is an option name (its value) or a literal (number, on/off, text).
// A lone option is true when it is on, non-zero or non-empty.
#include "base/Result.h"
#include "model/Value.h"

#include <map>
#include <optional>
#include <string>

namespace rs::templates {

// Deepest nesting of 'not' and '(' accepted; deeper expressions fail (the
// parser recurses, and a hostile manifest must not overflow the stack).
constexpr int kMaxConditionDepth = 64;

// Fails (an error without a file position: the caller knows where the
// expression was written) when it is malformed or names an unknown option.
Result<bool> evaluateCondition(const std::string& expression, const std::map<std::string, Value>& options);

} // namespace rs::templates
