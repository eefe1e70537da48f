#include "base/TextScalars.h"

#include <charconv>

namespace rs {

std::optional<bool> parseBool(const std::string& t)
{
    if (t == "on" || t == "true" || t == "yes" || t == "True" || t == "TRUE" || t == "On" || t == "Yes")
        return true;
    if (t == "off" || t == "false" || t == "no" || t == "False" || t == "FALSE" || t == "Off" || t == "No")
        return false;
    return std::nullopt;
}

namespace {

// The whole text as a number of type T (an optional leading '+'), else nullopt.
template <class T>
std::optional<T> parseWhole(const std::string& t)
{
    T value{};
    const char* begin = t.data();
    const char* end = t.data() + t.size();
    if (begin != end && *begin == '+')
        ++begin;
    auto [ptr, ec] = std::from_chars(begin, end, value);
    if (ec != std::errc() || ptr != end || begin == end)
        return std::nullopt;
    return value;
}

} // namespace

std::optional<long long> parseInteger(const std::string& t) { return parseWhole<long long>(t); }

std::size_t invalidUtf8Offset(const std::string& text)
{
    // Table 3-7 of the Unicode standard: the second byte's range depends on the first.
    const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
    const std::size_t size = text.size();
    for (std::size_t i = 0; i < size;) {
        const unsigned char c = bytes[i];
        if (c < 0x80) { ++i; continue; }
        int length = 0;
        unsigned char low = 0x80, high = 0xBF;
        if (c >= 0xC2 && c <= 0xDF) length = 2;
        else if (c >= 0xE0 && c <= 0xEF) { length = 3; if (c == 0xE0) low = 0xA0; if (c == 0xED) high = 0x9F; }
        else if (c >= 0xF0 && c <= 0xF4) { length = 4; if (c == 0xF0) low = 0x90; if (c == 0xF4) high = 0x8F; }
        else return i;
        if (i + std::size_t(length) > size || bytes[i + 1] < low || bytes[i + 1] > high)
            return i;
        for (int k = 2; k < length; ++k)
            if (bytes[i + std::size_t(k)] < 0x80 || bytes[i + std::size_t(k)] > 0xBF)
                return i;
        i += std::size_t(length);
    }
    return std::string::npos;
}

std::optional<double> parseNumber(const std::string& t) { return parseWhole<double>(t); }

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

bool isNull(const std::string& plain) { return plain == "~" || plain == "null" || plain == "Null" || plain == "NULL"; }

// A small reader of the YAML flow-list subset. Positions are byte offsets; a
// failure leaves its message in `error` and makes every later step fail too.
class FlowReader {
public:
    FlowReader(const std::string& text, std::string& error) : m_text(text), m_error(error) {}

    std::optional<std::vector<std::string>> read()
    {
        skipSpace();
        std::vector<std::string> items;
        if (atEnd())
            return items;
        const char c = m_text[m_pos];
        if (c == '{')
            return fail("expected a list");
        if (c == '[') {
            ++m_pos;
            if (!readItems(items))
                return std::nullopt;
        } else {
            auto item = readScalar(false);
            if (!item)
                return std::nullopt;
            if (m_mapKey)
                return fail("expected a list");
            if (!item->quoted && isNull(item->text))
                return finish(std::move(items));
            items.push_back(std::move(item->text));
        }
        return finish(std::move(items));
    }

private:
    struct Scalar {
        std::string text;
        bool quoted = false;
    };

    bool atEnd() const { return m_pos >= m_text.size(); }
    char peek(std::size_t ahead = 0) const { return m_pos + ahead < m_text.size() ? m_text[m_pos + ahead] : '\0'; }

    // Whitespace and a comment ('#' at the start or after whitespace) up to the line's end.
    void skipSpace()
    {
        while (!atEnd()) {
            if (isSpace(m_text[m_pos])) {
                ++m_pos;
            } else if (m_text[m_pos] == '#' && (m_pos == 0 || isSpace(m_text[m_pos - 1]))) {
                while (!atEnd() && m_text[m_pos] != '\n') ++m_pos;
            } else {
                break;
            }
        }
    }

    std::nullopt_t fail(const std::string& message)
    {
        if (m_error.empty()) m_error = message;
        return std::nullopt;
    }

    bool refuse(const std::string& message)
    {
        fail(message);
        return false;
    }

    std::optional<std::vector<std::string>> finish(std::vector<std::string> items)
    {
        skipSpace();
        if (!atEnd())
            return fail("unexpected '" + std::string(1, m_text[m_pos]) + "' after the list");
        return items;
    }

    bool readItems(std::vector<std::string>& items)
    {
        for (;;) {
            skipSpace();
            if (atEnd()) return refuse("missing ']' at the end of the list");
            if (peek() == ']') { ++m_pos; return true; }
            if (peek() == ',') return refuse("empty list item");
            if (peek() == '[' || peek() == '{') return refuse("list items must be plain values");
            auto item = readScalar(true);
            if (!item) return false;
            if (m_mapKey || (!item->quoted && isNull(item->text))) return refuse("list items must be plain values");
            items.push_back(std::move(item->text));
            skipSpace();
            if (atEnd()) return refuse("missing ']' at the end of the list");
            if (peek() == ',') { ++m_pos; continue; }
            if (peek() != ']') return refuse("expected ',' or ']' after a list item");
        }
    }

    // A mapping indicator: ':' followed by whitespace, the end or (in a list) a flow indicator.
    bool isMapIndicator(bool inList) const
    {
        const char next = peek(1);
        return peek() == ':' && (next == '\0' || isSpace(next) || (inList && (next == ',' || next == ']' || next == '}')));
    }

    std::optional<Scalar> readScalar(bool inList)
    {
        m_mapKey = false;
        const char c = peek();
        std::optional<Scalar> out;
        if (c == '\'' || c == '"') {
            out = c == '\'' ? readSingleQuoted() : readDoubleQuoted();
            if (!out) return std::nullopt;
            skipSpace();
            m_mapKey = peek() == ':';
            return out;
        }
        if (std::string("&*!|>%@`").find(c) != std::string::npos || ((c == '-' || c == '?') && isSpace(peek(1))))
            return fail(std::string("unsupported YAML syntax '") + c + "'");
        Scalar plain;
        const std::size_t begin = m_pos;
        std::size_t end = m_pos;
        while (!atEnd()) {
            const char d = peek();
            if (inList && (d == ',' || d == ']' || d == '[' || d == '{' || d == '}')) break;
            if (d == '#' && m_pos > 0 && isSpace(m_text[m_pos - 1])) break;
            if (isMapIndicator(inList)) { m_mapKey = true; break; }
            ++m_pos;
            if (!isSpace(d)) end = m_pos;
        }
        plain.text = m_text.substr(begin, end - begin);
        return plain;
    }

    std::optional<Scalar> readSingleQuoted()
    {
        Scalar s{{}, true};
        ++m_pos;
        for (;;) {
            if (atEnd()) return fail("missing closing quote");
            const char d = m_text[m_pos++];
            if (d == '\'') {
                if (peek() == '\'') { s.text += '\''; ++m_pos; continue; }
                return s;
            }
            s.text += d;
        }
    }

    std::optional<Scalar> readDoubleQuoted()
    {
        Scalar s{{}, true};
        ++m_pos;
        for (;;) {
            if (atEnd()) return fail("missing closing quote");
            const char d = m_text[m_pos++];
            if (d == '"') return s;
            if (d != '\\') { s.text += d; continue; }
            if (atEnd()) return fail("missing closing quote");
            const char e = m_text[m_pos++];
            switch (e) {
            case '\\': case '"': case '/': case '\'': case ' ': s.text += e; break;
            case 'n': s.text += '\n'; break;
            case 't': s.text += '\t'; break;
            case 'r': s.text += '\r'; break;
            case '0': s.text += '\0'; break;
            default: return fail(std::string("unknown escape '\\") + e + "' in a quoted item");
            }
        }
    }

    const std::string& m_text;
    std::string& m_error;
    std::size_t m_pos = 0;
    bool m_mapKey = false; // the scalar just read is followed by ':' (a map key)
};

} // namespace

Result<std::vector<std::string>> parseFlowList(const std::string& text)
{
    std::string error;
    auto items = FlowReader(text, error).read();
    if (!items)
        return Result<std::vector<std::string>>::refused(error);
    return std::move(*items);
}

} // namespace rs
