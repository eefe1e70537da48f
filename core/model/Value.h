#pragma once
// The typed value of a template parameter (manifest `guides`/`opts`) or of an
// instance's option. The type is fixed by the manifest default.
#include "base/Math.h"

#include <string>
#include <variant>

namespace rs {

using Value = std::variant<bool, long long, double, std::string, Vec3>;

enum class ValueType { Bool, Int, Float, String, Vec3 };

ValueType typeOf(const Value& value);
const char* typeName(ValueType type);

// Shortest text that reads back to the same value ("0.1", "on", "[0, 1, 0]").
std::string formatValue(const Value& value);
// Shortest round-trip text for a double; "-0" is written "0".
std::string formatNumber(double value);

} // namespace rs
