#include "io/YamlSupport.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

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

// One walk over the loaded document, before any reader sees it. yaml-cpp
// shares the node of an anchor among its aliases, so a few lines of nested
// aliases ("billion laughs") make a tree of billions of nodes: the walk counts
// every node it visits and stops at a budget no alias-free text can reach.
class DocumentCheck {
public:
    DocumentCheck(const std::string& file, std::size_t textBytes, Diagnostics& out)
        : m_file(file), m_budget(2 * textBytes + 64), m_out(out) {}

    // False when the document expands past the budget (the walk stopped).
    bool run(const YAML::Node& root) { return walk(root); }

private:
    bool walk(const YAML::Node& node)
    {
        if (++m_visited > m_budget) {
            m_out.push_back(makeError(locationOf(node, m_file),
                                      "the YAML expands to more than " + std::to_string(m_budget) +
                                          " values (aliases of aliases?); refused"));
            return false;
        }
        if (node.IsScalar()) {
            scalar(node);
        } else if (node.IsMap()) {
            // yaml-cpp keeps both entries of a repeated key and lookups see only the
            // first, so a repeated key would silently lose the rigger's second value.
            std::map<std::string, int> seen;
            for (const auto& kv : node) {
                if (kv.first.IsScalar()) {
                    const int line = kv.first.Mark().line + 1;
                    auto [it, fresh] = seen.emplace(kv.first.Scalar(), line);
                    if (!fresh)
                        m_out.push_back(makeError(locationOf(kv.first, m_file),
                                                  "duplicate key '" + kv.first.Scalar() + "' (first at line " +
                                                      std::to_string(it->second) + ")"));
                }
                if (!walk(kv.first) || !walk(kv.second))
                    return false;
            }
        } else if (node.IsSequence()) {
            for (const auto& item : node)
                if (!walk(item))
                    return false;
        }
        return true;
    }

    // Names become JSON strings in glTF, which refuses ill-formed UTF-8: say so
    // here, at the value's line, rather than fail (or throw) at export.
    void scalar(const YAML::Node& node)
    {
        const std::string& text = node.Scalar();
        if (const std::size_t at = invalidUtf8Offset(text); at != std::string::npos) {
            char byte[8];
            std::snprintf(byte, sizeof byte, "0x%02x", static_cast<unsigned char>(text[at]));
            m_out.push_back(makeError(locationOf(node, m_file), std::string("text is not valid UTF-8 (byte ") + byte +
                                                                    " at offset " + std::to_string(at) + " of the value)"));
        }
    }

    const std::string& m_file;
    std::size_t m_budget;
    std::size_t m_visited = 0;
    Diagnostics& m_out;
};

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
        Diagnostics problems;
        DocumentCheck(displayName, text.size(), problems).run(root);
        if (!problems.empty())
            return Result<YAML::Node>::failure(problems);
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

Result<std::string> readTextFile(const std::string& path)
{
    auto refuse = [&](const std::string& message) { return Result<std::string>::failure(makeError({path, 0, 0}, message)); };
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0)
        return refuse(std::string("cannot open file: ") + std::strerror(errno));
    struct Closer { int fd; ~Closer() { ::close(fd); } } closer{fd};
    struct stat info {};
    if (::fstat(fd, &info) != 0)
        return refuse(std::string("cannot read file: ") + std::strerror(errno));
    if (!S_ISREG(info.st_mode))
        return refuse(S_ISDIR(info.st_mode) ? "is a folder, not a file" : "not a regular file (a FIFO, socket or device); refused");
    if (std::uint64_t(info.st_size) > kMaxTextFileBytes)
        return refuse("file is " + std::to_string(info.st_size >> 20) + " MB, larger than the " +
                      std::to_string(kMaxTextFileBytes >> 20) + " MB limit");
    std::string text;
    text.reserve(std::size_t(info.st_size));
    char buffer[1 << 16];
    for (;;) { // read to the end (the file may have grown), never past the limit
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            return refuse(std::string("cannot read file: ") + std::strerror(errno));
        if (n == 0)
            break;
        if (text.size() + std::size_t(n) > kMaxTextFileBytes)
            return refuse("file is larger than the " + std::to_string(kMaxTextFileBytes >> 20) + " MB limit");
        text.append(buffer, std::size_t(n));
    }
    return text;
}

Result<YAML::Node> loadYamlFile(const std::string& path)
{
    auto text = readTextFile(path);
    if (!text)
        return Result<YAML::Node>::failure(text.takeDiagnostics());
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
        if (auto d = parseNumber(node.Scalar())) {
            if (std::isfinite(*d))
                return d;
            error(node, what + " must be a finite number, got '" + node.Scalar() + "'");
            return std::nullopt;
        }
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
            if (d && !std::isfinite(*d)) {
                error(item, what + " must be a list of 3 finite numbers, got '" + item.Scalar() + "' at index " + std::to_string(i));
                return std::nullopt;
            }
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
        // A list of names (branches: [L, R], add_nodes: [inf, pose]) is the
        // text its quoted form gives ("[L, R]"); three numbers are a vector.
        bool names = node.size() > 0;
        for (const auto& e : node) { // `inf` and `nan` are names here (a node called inf), not numbers
            const auto number = e.IsScalar() ? parseNumber(e.Scalar()) : std::nullopt;
            names = names && e.IsScalar() && !e.Scalar().empty() && !(number && std::isfinite(*number));
        }
        if (names) {
            std::string text = "[";
            for (std::size_t i = 0; i < node.size(); ++i)
                text += (i ? ", " : "") + node[i].Scalar();
            return Value(text + "]");
        }
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
        if (auto d = parseNumber(text)) {
            if (std::isfinite(*d)) return Value(*d);
            r.error(node, what + " must be a finite number, got '" + text + "' (quote it for text)");
            return std::nullopt;
        }
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

namespace {

// Words a YAML 1.1 or 1.2 reader (or our own typed readers: parseBool, and
// parseNumber, which takes nan and inf) types as null, a bool or a number,
// compared lower-cased.
bool isReservedWord(std::string lower)
{
    for (char& c : lower)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    for (const char* word : {"null", "y", "n", "yes", "no", "true", "false", "on", "off", "nan", "inf", "infinity"})
        if (lower == word)
            return true;
    return false;
}

// A scalar starting with a digit that some YAML reader may type as a number, a
// time or a date (1e3, 0x1F, 0o17, 0b11, 1_000, 1:30, 2001-12-14): only digits,
// hex letters, x/o/b and the separators _ . : + - appear in it.
bool looksNumeric(const std::string& text)
{
    if (!std::isdigit(static_cast<unsigned char>(text.front())))
        return false;
    for (char c : text)
        if (!std::isxdigit(static_cast<unsigned char>(c)) && !std::strchr("xXoObB_.:+-", c))
            return false;
    return true;
}

// Plain only when every YAML reader returns the same string: a letter, a digit,
// '_' or '/' first, then letters, digits, '_', '.', '/', '-' and inner spaces;
// no reserved word, nothing numeric. Anything else is double-quoted.
bool canBePlain(const std::string& text)
{
    if (text.empty() || text.back() == ' ')
        return false;
    const unsigned char first = static_cast<unsigned char>(text.front());
    if (!std::isalnum(first) && first != '_' && first != '/')
        return false;
    for (char c : text)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-' || c == ' ' || c == '/'))
            return false;
    if (text.find("  ") != std::string::npos) // folded by some readers
        return false;
    return !isReservedWord(text) && !looksNumeric(text) && !parseBool(text) && !parseNumber(text);
}

} // namespace

std::string quoteIfNeeded(const std::string& text)
{
    if (canBePlain(text))
        return text;
    std::string quoted = "\"";
    for (char c : text) {
        switch (c) {
        case '"': quoted += "\\\""; break;
        case '\\': quoted += "\\\\"; break;
        case '\n': quoted += "\\n"; break;
        case '\t': quoted += "\\t"; break;
        case '\r': quoted += "\\r"; break;
        default:
            if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
                char escape[5];
                std::snprintf(escape, sizeof escape, "\\x%02x", static_cast<unsigned char>(c));
                quoted += escape;
            } else {
                quoted += c; // UTF-8 bytes as they are
            }
        }
    }
    return quoted + "\"";
}

} // namespace rs::io
