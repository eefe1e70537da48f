#include "io/YamlSupport.h"

#include <cctype>
#include <fstream>
#include <map>
#include <sstream>

namespace rs::io {

namespace {

std::string describeType(const YAML::Node& node)
{
    switch (node.Type()) {
    case YAML::NodeType::Map: return "a map";
    case YAML::NodeType::Sequence: return "a list of " + std::to_string(node.size()) + (node.size() == 1 ? " item" : " items");
    case YAML::NodeType::Null: return "nothing";
    case YAML::NodeType::Scalar: return "'" + node.Scalar() + "'";
    default: return "an undefined value";
    }
}

// yaml-cpp keeps both entries of a repeated key and lookups see only the first,
// so a repeated key would silently lose the rigger's second value.
void reportDuplicateKeys(const YAML::Node& node, const std::string& file, Diagnostics& out)
{
    if (node.IsMap()) {
        std::map<std::string, int> seen;
        for (const auto& kv : node) {
            if (kv.first.IsScalar()) {
                const int line = kv.first.Mark().line + 1;
                auto [it, fresh] = seen.emplace(kv.first.Scalar(), line);
                if (!fresh)
                    out.push_back(makeError(locationOf(kv.first, file), "duplicate key '" + kv.first.Scalar() +
                                                                            "' (first at line " + std::to_string(it->second) + ")"));
            }
            reportDuplicateKeys(kv.second, file, out);
        }
    } else if (node.IsSequence()) {
        for (const auto& item : node)
            reportDuplicateKeys(item, file, out);
    }
}

} // namespace

SourceLocation locationOf(const YAML::Node& node, const std::string& file)
{
    SourceLocation where{file, 0, 0};
    if (node.IsDefined()) {
        const YAML::Mark mark = node.Mark();
        if (!mark.is_null()) {
            where.line = mark.line + 1;
            where.column = mark.column + 1;
        }
    }
    return where;
}

Result<YAML::Node> loadYamlText(const std::string& text, const std::string& displayName)
{
    try {
        YAML::Node root = YAML::Load(text);
        Diagnostics duplicates;
        reportDuplicateKeys(root, displayName, duplicates);
        if (!duplicates.empty())
            return Result<YAML::Node>::failure(duplicates);
        return root;
    } catch (const YAML::ParserException& e) {
        SourceLocation where{displayName, e.mark.line + 1, e.mark.column + 1};
        if (e.mark.is_null())
            where.line = where.column = 0;
        return Result<YAML::Node>::failure(makeError(where, "malformed YAML: " + e.msg));
    } catch (const YAML::Exception& e) {
        return Result<YAML::Node>::failure(makeError({displayName, 0, 0}, std::string("malformed YAML: ") + e.what()));
    }
}

std::optional<std::string> readTextFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return std::nullopt;
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

Result<YAML::Node> loadYamlFile(const std::string& path)
{
    auto text = readTextFile(path);
    if (!text)
        return Result<YAML::Node>::failure(makeError({path, 0, 0}, "cannot open file"));
    return loadYamlText(*text, path);
}

void YamlReader::error(const YAML::Node& node, const std::string& message)
{
    m_diagnostics.push_back(makeError(locationOf(node, m_file), message));
}

void YamlReader::warning(const YAML::Node& node, const std::string& message)
{
    m_diagnostics.push_back(makeWarning(locationOf(node, m_file), message));
}

std::optional<std::string> YamlReader::string(const YAML::Node& node, const std::string& what)
{
    if (node.IsScalar())
        return node.Scalar();
    error(node, what + " must be a text value, got " + describeType(node));
    return std::nullopt;
}

std::optional<bool> YamlReader::boolean(const YAML::Node& node, const std::string& what)
{
    if (node.IsScalar())
        if (auto b = parseBool(node.Scalar()))
            return b;
    error(node, what + " must be on/off, got " + describeType(node));
    return std::nullopt;
}

std::optional<long long> YamlReader::integer(const YAML::Node& node, const std::string& what)
{
    if (node.IsScalar())
        if (auto i = parseInteger(node.Scalar()))
            return i;
    error(node, what + " must be an integer, got " + describeType(node));
    return std::nullopt;
}

std::optional<double> YamlReader::number(const YAML::Node& node, const std::string& what)
{
    if (node.IsScalar())
        if (auto d = parseNumber(node.Scalar()))
            return d;
    error(node, what + " must be a number, got " + describeType(node));
    return std::nullopt;
}

std::optional<Vec3> YamlReader::vec3(const YAML::Node& node, const std::string& what)
{
    if (node.IsSequence() && node.size() == 3) {
        Vec3 v;
        for (int i = 0; i < 3; ++i) {
            const YAML::Node item = node[i];
            auto d = item.IsScalar() ? parseNumber(item.Scalar()) : std::nullopt;
            if (!d) {
                error(item, what + " must be a list of 3 numbers, got " + describeType(item) + " at index " + std::to_string(i));
                return std::nullopt;
            }
            v[i] = *d;
        }
        return v;
    }
    error(node, what + " must be a list of 3 numbers, got " + describeType(node));
    return std::nullopt;
}

bool YamlReader::expectMap(const YAML::Node& node, const std::string& what)
{
    if (node.IsMap())
        return true;
    error(node, what + " must be a map, got " + describeType(node));
    return false;
}

bool YamlReader::expectSequence(const YAML::Node& node, const std::string& what)
{
    if (node.IsSequence())
        return true;
    error(node, what + " must be a list, got " + describeType(node));
    return false;
}

std::optional<Value> readValue(YamlReader& r, const YAML::Node& node, const std::string& what)
{
    if (node.IsSequence()) {
        if (auto v = r.vec3(node, what))
            return Value(*v);
        return std::nullopt;
    }
    if (!node.IsScalar()) {
        r.error(node, what + " must be a scalar or a list of 3 numbers");
        return std::nullopt;
    }
    const std::string& text = node.Scalar();
    if (node.Tag() != "!") { // plain (unquoted) scalars are typed by their text
        if (auto b = parseBool(text)) return Value(*b);
        if (auto i = parseInteger(text)) return Value(*i);
        if (auto d = parseNumber(text)) return Value(*d);
    }
    return Value(text);
}

bool isValidYaml(const std::string& text)
{
    try {
        YAML::Load(text);
        return true;
    } catch (const YAML::Exception&) {
        return false;
    }
}

std::string quoteIfNeeded(const std::string& text)
{
    bool plain = !text.empty() && !parseBool(text) && !parseNumber(text) && text != "null" && text != "~" &&
                 text.front() != ' ' && text.back() != ' ';
    for (char c : text)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-' || c == ' ' || c == '/'))
            plain = false;
    if (plain && (text.front() == '-' || text.front() == '.'))
        plain = false;
    if (plain)
        return text;
    std::string quoted = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') quoted += '\\';
        if (c == '\n') { quoted += "\\n"; continue; }
        quoted += c;
    }
    return quoted + "\"";
}

} // namespace rs::io
