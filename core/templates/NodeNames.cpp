#include "templates/NodeNames.h"

#include <algorithm>
#include <iterator>

namespace rs::templates {

namespace {

bool isIdentifier(const std::string& name)
{
    auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
    if (name.empty() || !letter(name.front()))
        return false;
    return std::all_of(name.begin(), name.end(), [&](char c) { return letter(c) || (c >= '0' && c <= '9'); });
}

// Names the stack gives its own nodes (and Mikan's marks for them): a group
// named so would be mistaken for one of them.
constexpr const char* kReserved[] = {"root", "roots", "ctrl", "ctrls", "skin", "sk", "hooks", "cns", "nodes"};

} // namespace

std::vector<std::string> addNodesProblems(const std::vector<std::string>& names)
{
    std::vector<std::string> problems, seen;
    bool controller = false;
    for (const std::string& name : names) {
        if (name == "c") {
            if (controller)
                problems.push_back("names the controller 'c' twice");
            controller = true;
        } else if (!isIdentifier(name)) {
            problems.push_back("'" + name + "' is no node name (letters, digits and '_', not starting with a digit)");
        } else if (std::find(std::begin(kReserved), std::end(kReserved), name) != std::end(kReserved)) {
            problems.push_back("'" + name + "' is a name the control already uses; pick another");
        } else if (std::find(seen.begin(), seen.end(), name) != seen.end()) {
            problems.push_back("names '" + name + "' twice");
        }
        seen.push_back(name);
    }
    return problems;
}

std::vector<std::string> addChainsProblems(const std::vector<std::string>& names)
{
    std::vector<std::string> problems, seen;
    for (const std::string& name : names) {
        if (!isIdentifier(name))
            problems.push_back("'" + name + "' is no chain name (letters, digits and '_', not starting with a digit)");
        else if (std::find(seen.begin(), seen.end(), name) != seen.end())
            problems.push_back("names '" + name + "' twice");
        seen.push_back(name);
    }
    return problems;
}

} // namespace rs::templates
