#pragma once
// Conditions in manifest `hierarchy.<id>.opts` keys: boolean expressions over
// option values, parsed by a small safe parser (no code runs from data).
// Grammar: expr := and ('or' and)*; and := unary ('and' unary)*;
// unary := 'not' unary | '(' expr ')' | operand [('=='|'!=') operand];
// an operand is an option name (its value) or a literal (number, on/off, text).
// A lone option is true when it is on, non-zero or non-empty.
#include "model/Value.h"

#include <map>
#include <optional>
#include <string>

namespace rs::templates {

// nullopt and `error` set when the expression is malformed or names an unknown option.
std::optional<bool> evaluateCondition(const std::string& expression, const std::map<std::string, Value>& options,
                                      std::string& error);

} // namespace rs::templates
