#include "model/Value.h"

#include <charconv>
#include <optional>

namespace rs {

ValueType typeOf(const Value& value)
{
    return static_cast<ValueType>(value.index());
}

const char* typeName(ValueType type)
{
    switch (type) {
    case ValueType::Bool: return "bool";
    case ValueType::Int: return "int";
    case ValueType::Float: return "float";
    case ValueType::String: return "string";
    case ValueType::Vec3: return "vec3";
    }
    return "?";
}

bool sameValue(const Value& a, const Value& b)
{
    auto number = [](const Value& v) -> std::optional<double> {
        if (const auto* i = std::get_if<long long>(&v))
            return double(*i);
        if (const auto* d = std::get_if<double>(&v))
            return *d;
        return std::nullopt;
    };
    const auto x = number(a), y = number(b);
    return x && y ? *x == *y : a == b;
}

std::string formatNumber(double value)
{
    if (value == 0.0)
        value = 0.0; // folds -0 into 0 so dumps are stable
    char buffer[64];
    auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    std::string text(buffer, ptr);
    return text;
}

std::string formatValue(const Value& value)
{
    struct Visitor {
        std::string operator()(bool b) const { return b ? "on" : "off"; }
        std::string operator()(long long i) const { return std::to_string(i); }
        std::string operator()(double d) const
        {
            std::string text = formatNumber(d);
            // keep floats recognisable as floats when read back
            if (text.find_first_of(".eEn") == std::string::npos)
                text += ".0";
            return text;
        }
        std::string operator()(const std::string& s) const { return s; }
        std::string operator()(const Vec3& v) const
        {
            std::string text("[");
            text.append(formatNumber(v.x)).append(", ").append(formatNumber(v.y)).append(", ").append(formatNumber(v.z));
            return text.append("]");
        }
    };
    return std::visit(Visitor{}, value);
}

} // namespace rs
