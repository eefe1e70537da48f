// The rig id text of a mod's references, parsed (ModRefReader.h).
#include "io/ModRefReader.h"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace rs::io {

using model::ModRef;

// The reference `node` holds (or `word` of it).
std::optional<ModRef> ModRefReader::ref(const YAML::Node& node, const std::string& what, Want want, const std::string& word)
{
    const auto text = word.empty() ? m_r.string(node, what) : std::optional<std::string>(word);
    if (!text)
        return std::nullopt;
    ModRef ref;
    std::string tagPart = *text;
    if (const auto sep = text->find("::"); sep == std::string::npos) {
        if (m_owner.isNone()) {
            m_r.error(node, what + " '" + *text + "': a global mod names a node as instance::tag (e.g. arm.L::ctrls.ik)");
            return std::nullopt;
        }
        ref.instance = m_owner;
    } else {
        instancePart(text->substr(0, sep), ref);
        tagPart = text->substr(sep + 2);
    }
    const auto at = tagPart.find('@');
    ref.tag = tagPart.substr(0, at);
    ref.channel = at == std::string::npos ? std::string() : tagPart.substr(at + 1);
    const auto bad = [](const std::string& s) {
        return s.find("::") != std::string::npos || s.find('@') != std::string::npos ||
               std::any_of(s.begin(), s.end(), [](unsigned char c) { return std::isspace(c); });
    };
    if (ref.tag.empty() || bad(ref.tag) || bad(ref.channel) || (at != std::string::npos && ref.channel.empty())) {
        m_r.error(node, what + " '" + *text + "' is not a rig id (instance[.branch]::tag[@channel], e.g. arm.L::ctrls.ik@ik_blend)");
        return std::nullopt;
    }
    if (ref.instance.isNone() && ref.tag != "rig") {
        m_r.error(node, what + " '" + *text + "': only the rig root (::rig) has no instance");
        return std::nullopt;
    }
    if (want == Want::Channel && ref.channel.empty()) {
        m_r.error(node, what + " '" + *text + "' needs a channel (node@channel, e.g. ctrls.ik@ik_blend or ctrls.fk.0@rz)");
        return std::nullopt;
    }
    if (want == Want::Node && !ref.channel.empty()) {
        m_r.error(node, what + " '" + *text + "' names a channel; it takes a node (drop '@" + ref.channel + "')");
        return std::nullopt;
    }
    return ref;
}

// "arm", "arm.L", "arm.A.L": an instance's name, else name and branch.
void ModRefReader::instancePart(const std::string& text, ModRef& ref)
{
    if (text.empty())
        return; // the rig root
    if (const model::TemplateInstance* i = m_doc.instanceNamed(text)) {
        ref.instance = {i->id, i->name};
        return;
    }
    const auto dot = text.find('.');
    const std::string name = text.substr(0, dot);
    const model::TemplateInstance* i = m_doc.instanceNamed(name);
    ref.instance = {i ? i->id : kNoId, name}; // unknown: kept by name, reported by a build
    if (dot != std::string::npos)
        ref.branch = text.substr(dot + 1);
}

std::vector<ModRef> ModRefReader::refs(const YAML::Node& node, const std::string& what, Want want, bool& ok)
{
    std::vector<ModRef> out;
    if (node.IsSequence()) {
        for (const auto& item : node)
            if (auto r = ref(item, what, want)) out.push_back(*r);
            else ok = false;
    } else if (node.IsScalar() && node.Scalar().find_first_of(" \t") != std::string::npos) {
        // Mikan's one-line form: `hide: a::ctrls.0 b::ctrls.0`.
        std::istringstream words(node.Scalar());
        for (std::string word; words >> word;)
            if (auto r = ref(node, what, want, word)) out.push_back(*r);
            else ok = false;
    } else if (auto r = ref(node, what, want)) {
        out.push_back(*r);
    } else {
        ok = false;
    }
    if (ok && out.empty()) {
        m_r.error(node, what + " is empty");
        ok = false;
    }
    return out;
}

} // namespace rs::io
