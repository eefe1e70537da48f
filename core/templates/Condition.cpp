#include "templates/Condition.h"

#include "base/TextScalars.h"

#include <cctype>
#include <vector>

namespace rs::templates {

namespace {

class Parser {
public:
    Parser(const std::string& text, const std::map<std::string, Value>& options) : m_options(options)
    {
        for (std::size_t i = 0; i < text.size();) {
            const char c = text[i];
            if (std::isspace(static_cast<unsigned char>(c))) { ++i; continue; }
            if (c == '(' || c == ')') { m_tokens.emplace_back(1, c); ++i; continue; }
            if ((c == '=' || c == '!') && i + 1 < text.size() && text[i + 1] == '=') { m_tokens.push_back(text.substr(i, 2)); i += 2; continue; }
            if (c == '\'' || c == '"') {
                const auto end = text.find(c, i + 1);
                if (end == std::string::npos) { m_error = "unterminated quote"; return; }
                m_tokens.push_back(text.substr(i, end - i + 1));
                i = end + 1;
                continue;
            }
            std::size_t j = i;
            while (j < text.size() && !std::isspace(static_cast<unsigned char>(text[j])) && text[j] != '(' && text[j] != ')' && text[j] != '=' && text[j] != '!')
                ++j;
            if (j == i) { m_error = std::string("unexpected '") + c + "'"; return; }
            m_tokens.push_back(text.substr(i, j - i));
            i = j;
        }
    }

    std::optional<bool> parse(std::string& error)
    {
        std::optional<bool> result;
        if (m_error.empty()) {
            result = orExpr();
            if (m_error.empty() && m_pos != m_tokens.size())
                m_error = "unexpected '" + m_tokens[m_pos] + "'";
        }
        if (!m_error.empty()) { error = m_error; return std::nullopt; }
        return result;
    }

private:
    bool peek(const char* t) const { return m_pos < m_tokens.size() && m_tokens[m_pos] == t; }
    bool orExpr() { bool v = andExpr(); while (m_error.empty() && peek("or")) { ++m_pos; v = andExpr() || v; } return v; }
    bool andExpr() { bool v = unary(); while (m_error.empty() && peek("and")) { ++m_pos; v = unary() && v; } return v; }
    bool unary()
    {
        // Each 'not' and '(' recurses; a hostile manifest could nest them deep
        // enough to overflow the stack, so the depth is capped.
        if (peek("not") || peek("(")) {
            if (m_depth >= kMaxConditionDepth) {
                fail("expression nested too deeply (more than " + std::to_string(kMaxConditionDepth) + " levels of 'not' and '(')");
                return false;
            }
            ++m_depth;
            const bool v = peek("not") ? (++m_pos, !unary()) : group();
            --m_depth;
            return v;
        }
        std::string left = operand();
        if (peek("==") || peek("!=")) {
            const bool equal = m_tokens[m_pos++] == "==";
            std::string right = operand(true);
            return (left == right) == equal;
        }
        return truthy(left);
    }
    // '(' expr ')'
    bool group()
    {
        ++m_pos;
        const bool v = orExpr();
        if (!peek(")")) { fail("missing ')'"); return false; }
        ++m_pos;
        return v;
    }
    // The operand's value as text: options give their value, literals themselves.
    std::string operand(bool bareWordIsText = false)
    {
        if (m_pos >= m_tokens.size()) { fail("expression ends too early"); return {}; }
        std::string t = m_tokens[m_pos++];
        if (t == "(" || t == ")" || t == "==" || t == "!=" || t == "and" || t == "or" || t == "not") { fail("unexpected '" + t + "'"); return {}; }
        if (t.front() == '\'' || t.front() == '"') return t.substr(1, t.size() - 2);
        if (auto it = m_options.find(t); it != m_options.end()) return formatValue(it->second);
        if (parseNumber(t)) return t;
        if (auto b = parseBool(t)) return *b ? "on" : "off";
        if (!bareWordIsText && (std::isalpha(static_cast<unsigned char>(t.front())) || t.front() == '_')) { fail("unknown option '" + t + "'"); return {}; }
        return t;
    }
    static bool truthy(const std::string& v) { return !(v.empty() || v == "off" || v == "0" || v == "0.0" || v == "[]"); }
    void fail(const std::string& message) { if (m_error.empty()) m_error = message; }

    const std::map<std::string, Value>& m_options;
    std::vector<std::string> m_tokens;
    std::size_t m_pos = 0;
    int m_depth = 0;
    std::string m_error;
};

} // namespace

Result<bool> evaluateCondition(const std::string& expression, const std::map<std::string, Value>& options)
{
    std::string error;
    const std::optional<bool> holds = Parser(expression, options).parse(error);
    if (!holds)
        return Result<bool>::refused(error);
    return *holds;
}

} // namespace rs::templates
