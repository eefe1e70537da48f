#pragma once
// Reading a mod's references (internal to io/ModFile.cpp): the one place the
// rig id text `instance[.branch]::tag[@channel]` is parsed, from a YAML
// scalar, a list of them or Mikan's one-line form (`a::ctrls.0 b::ctrls.0`).
// An instance's own mod may leave the instance out (`ctrls.ik`); only the rig
// root (`::rig`) has none. An instance name the guide does not have is kept
// by name (a build reports it). Every problem is an error at the line and
// column of the value, and the reference is not read.
#include "io/YamlSupport.h"
#include "model/GuideDocument.h"

#include <optional>
#include <string>
#include <vector>

namespace rs::io {

class ModRefReader {
public:
    // What a reference may be: a node, or a node's channel.
    enum class Want { Node, Channel };

    ModRefReader(YamlReader& r, const model::GuideDocument& doc, model::ModInstance owner)
        : m_r(r), m_doc(doc), m_owner(std::move(owner)) {}

    // The reference `node` holds (or `word` of it); `what` names it in errors.
    std::optional<model::ModRef> ref(const YAML::Node& node, const std::string& what, Want want, const std::string& word = {});
    // One or more references (a list, or words on one line); `ok` cleared by a bad one or an empty list.
    std::vector<model::ModRef> refs(const YAML::Node& node, const std::string& what, Want want, bool& ok);

protected:
    YamlReader& m_r;
    const model::GuideDocument& m_doc;
    model::ModInstance m_owner;

private:
    // "arm", "arm.L", "arm.A.L": an instance's name, else name and branch.
    void instancePart(const std::string& text, model::ModRef& ref);
};

} // namespace rs::io
