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

// Whether two values are the same value: numbers compare by value whatever
// their kind, since a float option's 0.0 is written "0" and reads back as an
// int (the build coerces it to the manifest's type).
bool sameValue(const Value& a, const Value& b);

// Shortest text that reads back to the same value ("0.1", "on", "[0, 1, 0]").
std::string formatValue(const Value& value);
// Shortest round-trip text for a double; "-0" is written "0".
std::string formatNumber(double value);

} // namespace rs
