#include "model/Naming.h"

#include <cctype>

namespace rs::model {

std::string NamingRules::make(NameRole role, const std::string& core, const std::string& branch) const
{
    const std::string& mark = role == NameRole::Offset ? offset : role == NameRole::Controller ? controller
                            : role == NameRole::Skin ? skin : group;
    std::string name = core;
    if (!branch.empty())
        name += side + branch;
    name = suffixes ? name + mark : mark + name;
    if (lowercase)
        for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return name;
}

std::optional<NamingRules> namingPreset(const std::string& name)
{
    NamingRules rules;
    if (name == "mikan")
        return rules;
    if (name == "suffix") {
        rules.preset = name;
        rules.offset = "_gp";
        rules.controller = "_ctrl";
        rules.skin = "_jnt";
        rules.group = "_gp";
        rules.suffixes = true;
        return rules;
    }
    return std::nullopt;
}

} // namespace rs::model
