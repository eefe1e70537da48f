#include "templates/Structure.h"

#include "io/YamlSupport.h"

#include <algorithm>

namespace rs::templates {

using model::JointId;

namespace {

std::string trim(const std::string& s)
{
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

// Python-style index/slice on a list; returns nullopt on bad syntax or range.
std::optional<std::vector<JointId>> applySelector(const std::vector<JointId>& list, const std::string& selector,
                                                  std::string& error)
{
    const long long n = static_cast<long long>(list.size());
    if (selector == "*")
        return list;
    const auto colon = selector.find(':');
    if (colon == std::string::npos) {
        auto index = io::parseInteger(trim(selector));
        if (!index) { error = "bad index '[" + selector + "]'"; return std::nullopt; }
        long long i = *index < 0 ? n + *index : *index;
        if (i < 0 || i >= n) { error = "index [" + selector + "] is out of range (" + std::to_string(n) + " joints)"; return std::nullopt; }
        return std::vector<JointId>{list[std::size_t(i)]};
    }
    auto bound = [&](const std::string& text, long long fallback) -> std::optional<long long> {
        if (trim(text).empty()) return fallback;
        auto v = io::parseInteger(trim(text));
        if (!v) return std::nullopt;
        long long i = *v < 0 ? n + *v : *v;
        return std::clamp(i, 0LL, n);
    };
    auto a = bound(selector.substr(0, colon), 0);
    auto b = bound(selector.substr(colon + 1), n);
    if (!a || !b) { error = "bad slice '[" + selector + "]'"; return std::nullopt; }
    std::vector<JointId> out;
    for (long long i = *a; i < *b; ++i)
        out.push_back(list[std::size_t(i)]);
    return out;
}

} // namespace

std::vector<JointId> StructureResolver::chain() const
{
    std::vector<JointId> out;
    if (m_instance.joints.empty())
        return out;
    JointId current = m_instance.joints.front().id;
    while (true) {
        out.push_back(current);
        std::vector<JointId> next;
        for (JointId child : m_instance.childJoints(current))
            if (const auto* j = m_instance.joint(child); j->tags.empty() && !j->isHelper())
                next.push_back(child);
        if (next.size() != 1 || std::find(out.begin(), out.end(), next.front()) != out.end())
            return out;
        current = next.front();
    }
}

std::optional<std::vector<JointId>> StructureResolver::evaluate(const std::string& expression, const std::string& ownTag,
                                                                std::string& error) const
{
    std::vector<JointId> result;
    std::size_t start = 0;
    while (start <= expression.size()) {
        auto plus = expression.find('+', start);
        if (plus == std::string::npos) plus = expression.size();
        const std::string term = trim(expression.substr(start, plus - start));
        start = plus + 1;

        std::string base = term, selector;
        if (auto open = term.find('['); open != std::string::npos) {
            if (term.back() != ']') { error = "missing ']' in '" + term + "'"; return std::nullopt; }
            base = trim(term.substr(0, open));
            selector = term.substr(open + 1, term.size() - open - 2);
        }
        std::vector<JointId> joints;
        if (base.empty() && term.empty()) {
            if (ownTag.empty()) { error = "empty address"; return std::nullopt; }
            for (const auto& j : m_instance.joints)
                if (j.hasTag(ownTag)) joints.push_back(j.id);
            if (joints.empty()) { error = "no guide joint is tagged '" + ownTag + "'"; return std::nullopt; }
        } else if (base == ".") {
            joints.push_back(m_instance.joints.front().id);
        } else if (!base.empty() && base[0] == '/') {
            const std::vector<JointId> c = chain();
            if (base == "/*") joints = c;
            else if (auto sel = applySelector(c, base.substr(1), error)) joints = *sel;
            else { error = "address '" + base + "': " + error; return std::nullopt; }
        } else {
            auto sub = tag(base, &error);
            if (!sub) return std::nullopt;
            joints = *sub;
        }
        if (!selector.empty()) {
            auto sel = applySelector(joints, selector, error);
            if (!sel) { error = "'" + term + "': " + error; return std::nullopt; }
            joints = *sel;
        }
        result.insert(result.end(), joints.begin(), joints.end());
        if (plus == expression.size()) break;
    }
    return result;
}

std::optional<std::vector<JointId>> StructureResolver::tag(const std::string& tagName, std::string* error) const
{
    std::string message;
    std::optional<std::vector<JointId>> out;
    std::optional<std::string> address;
    if (auto it = m_instance.structure.find(tagName); it != m_instance.structure.end())
        address = it->second; // per-instance override
    else
        address = m_manifest.structureAddress(tagName);
    if (address) {
        // Tags may refer to tags; a chain deeper than the tag count is a cycle.
        if (m_depth > m_manifest.structure.size() + m_instance.structure.size()) {
            message = "structure tag '" + tagName + "' refers to itself";
        } else {
            ++m_depth;
            out = evaluate(*address, tagName, message);
            --m_depth;
        }
    } else {
        // Not declared: an explicit tag on the guide still resolves (Mikan's set_template_id).
        std::vector<JointId> tagged;
        for (const auto& j : m_instance.joints)
            if (j.hasTag(tagName)) tagged.push_back(j.id);
        if (!tagged.empty()) out = tagged;
        else message = "unknown structure tag '" + tagName + "'";
    }
    if (!out && error) *error = message;
    return out;
}

std::optional<std::vector<JointId>> StructureResolver::address(const std::string& expression, std::string* error) const
{
    std::string message;
    auto out = evaluate(expression, "", message);
    if (!out && error) *error = message;
    return out;
}

} // namespace rs::templates
