#include "templates/Structure.h"

#include "base/TextScalars.h"

#include <algorithm>
#include <cctype>
#include <unordered_map>
#include <unordered_set>

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
        auto index = parseInteger(trim(selector));
        if (!index) { error = "bad index '[" + selector + "]'"; return std::nullopt; }
        long long i = *index < 0 ? n + *index : *index;
        if (i < 0 || i >= n) { error = "index [" + selector + "] is out of range (" + std::to_string(n) + " joints)"; return std::nullopt; }
        return std::vector<JointId>{list[std::size_t(i)]};
    }
    auto bound = [&](const std::string& text, long long fallback) -> std::optional<long long> {
        if (trim(text).empty()) return fallback;
        auto v = parseInteger(trim(text));
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

bool isInteger(const std::string& text) { return parseInteger(text).has_value(); }

std::optional<std::string> checkSelector(const std::string& selector)
{
    if (selector == "*")
        return std::nullopt;
    const auto colon = selector.find(':');
    if (colon == std::string::npos)
        return isInteger(trim(selector)) ? std::nullopt : std::optional<std::string>("bad index '[" + selector + "]'");
    const std::string a = trim(selector.substr(0, colon)), b = trim(selector.substr(colon + 1));
    if ((!a.empty() && !isInteger(a)) || (!b.empty() && !isInteger(b)))
        return "bad slice '[" + selector + "]'";
    return std::nullopt;
}

std::optional<std::vector<AddressTerm>> parseTerms(const std::string& expression, std::string& error)
{
    std::vector<AddressTerm> terms;
    if (trim(expression).empty())
        return terms;
    std::size_t start = 0;
    while (true) {
        auto plus = expression.find('+', start);
        if (plus == std::string::npos) plus = expression.size();
        AddressTerm term;
        term.text = trim(expression.substr(start, plus - start));
        if (term.text.empty()) { error = "empty term in '" + expression + "'"; return std::nullopt; }
        term.base = term.text;
        if (auto open = term.text.find('['); open != std::string::npos) {
            if (term.text.back() != ']') { error = "missing ']' in '" + term.text + "'"; return std::nullopt; }
            term.base = trim(term.text.substr(0, open));
            term.selector = term.text.substr(open + 1, term.text.size() - open - 2);
            if (term.selector.find_first_of("[]") != std::string::npos) { error = "nested brackets in '" + term.text + "'"; return std::nullopt; }
            if (auto bad = checkSelector(term.selector)) { error = "'" + term.text + "': " + *bad; return std::nullopt; }
            if (term.base.empty()) { error = "missing tag before '[' in '" + term.text + "'"; return std::nullopt; }
        }
        if (term.base[0] == '/') {
            const std::string depth = term.base.substr(1);
            if (depth != "*" && !isInteger(depth)) { error = "bad depth address '" + term.base + "' (use /N, /-N or /*)"; return std::nullopt; }
        } else if (term.base != ".") {
            for (char c : term.base)
                if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.')) {
                    error = "bad tag name '" + term.base + "'";
                    return std::nullopt;
                }
        }
        terms.push_back(std::move(term));
        if (plus == expression.size()) break;
        start = plus + 1;
    }
    return terms;
}

} // namespace

Result<std::vector<AddressTerm>> parseAddress(const std::string& expression)
{
    std::string error;
    auto terms = parseTerms(expression, error);
    if (!terms)
        return Result<std::vector<AddressTerm>>::refused(error);
    return std::move(*terms);
}

const std::vector<JointId>& StructureResolver::chain() const
{
    if (m_chain)
        return *m_chain;
    m_chain.emplace();
    std::vector<JointId>& out = *m_chain;
    if (m_instance.joints.empty())
        return out;
    // Per joint: how many chain candidates (untagged, non-helper, not the root) hang under it, and the first.
    const JointId root = m_instance.joints.front().id;
    std::unordered_map<JointId, std::pair<std::size_t, JointId>> candidates;
    for (const model::GuideJoint& j : m_instance.joints)
        if (j.parent != model::kNoId && j.id != root && j.tags.empty() && !j.isHelper()) {
            auto& [count, first] = candidates[j.parent];
            if (count++ == 0)
                first = j.id;
        }
    std::unordered_set<JointId> visited;
    JointId current = root;
    while (true) {
        out.push_back(current);
        visited.insert(current);
        auto next = candidates.find(current);
        if (next == candidates.end() || next->second.first != 1 || visited.count(next->second.second))
            return out;
        current = next->second.second;
    }
}

std::optional<std::vector<JointId>> StructureResolver::evaluate(const std::string& expression, const std::string& ownTag,
                                                                std::string& error) const
{
    auto terms = parseTerms(expression, error);
    if (!terms)
        return std::nullopt;
    if (terms->empty()) { // explicit tag: the joints tagged with the tag itself
        if (ownTag.empty()) { error = "empty address"; return std::nullopt; }
        std::vector<JointId> joints;
        for (const auto& j : m_instance.joints)
            if (j.hasTag(ownTag)) joints.push_back(j.id);
        if (joints.empty()) { error = "no guide joint is tagged '" + ownTag + "'"; return std::nullopt; }
        return joints;
    }
    std::vector<JointId> result;
    for (const AddressTerm& term : *terms) {
        std::vector<JointId> joints;
        if (term.base == ".") {
            joints.push_back(m_instance.joints.front().id);
        } else if (term.base[0] == '/') {
            const std::vector<JointId>& c = chain();
            if (term.base == "/*") joints = c;
            else if (auto sel = applySelector(c, term.base.substr(1), error)) joints = *sel;
            else { error = "address '" + term.base + "': " + error; return std::nullopt; }
        } else {
            const std::vector<JointId>* sub = lookup(term.base, error);
            if (!sub) return std::nullopt;
            if (term.selector.empty()) { // selected from the memoised list, never copied whole
                result.insert(result.end(), sub->begin(), sub->end());
                continue;
            }
            auto sel = applySelector(*sub, term.selector, error);
            if (!sel) { error = "'" + term.text + "': " + error; return std::nullopt; }
            result.insert(result.end(), sel->begin(), sel->end());
            continue;
        }
        if (!term.selector.empty()) {
            auto sel = applySelector(joints, term.selector, error);
            if (!sel) { error = "'" + term.text + "': " + error; return std::nullopt; }
            joints = *sel;
        }
        result.insert(result.end(), joints.begin(), joints.end());
    }
    return result;
}

const std::vector<JointId>* StructureResolver::lookup(const std::string& tagName, std::string& message) const
{
    if (auto known = m_tags.find(tagName); known != m_tags.end())
        return &known->second;
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
    if (!out)
        return nullptr;
    return &m_tags.emplace(tagName, std::move(*out)).first->second;
}

Result<std::vector<JointId>> StructureResolver::tag(const std::string& tagName) const
{
    std::string error;
    const std::vector<JointId>* joints = lookup(tagName, error);
    if (!joints)
        return Result<std::vector<JointId>>::refused(error);
    return *joints;
}

Result<std::vector<JointId>> StructureResolver::address(const std::string& expression) const
{
    std::string error;
    auto joints = evaluate(expression, "", error);
    if (!joints)
        return Result<std::vector<JointId>>::refused(error);
    return std::move(*joints);
}

} // namespace rs::templates
