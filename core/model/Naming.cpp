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

std::string mirroredName(const std::string& name)
{
    static const std::pair<const char*, const char*> pairs[] = {{"L", "R"}, {"l", "r"}, {"Left", "Right"}, {"left", "right"}};
    for (const auto& [a, b] : pairs)
        for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
            const std::string token(from);
            if (name.size() > token.size() + 1 && name.compare(name.size() - token.size(), token.size(), token) == 0) {
                const char separator = name[name.size() - token.size() - 1];
                if (separator == '_' || separator == '.')
                    return name.substr(0, name.size() - token.size()) + to;
            }
        }
    return {};
}

} // namespace rs::model
