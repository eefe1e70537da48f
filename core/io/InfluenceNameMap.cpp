#include "io/InfluenceNameMap.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

namespace rs::io {

namespace {

std::string trimmed(std::string s)
{
    const auto space = [](unsigned char c) { return std::isspace(c) != 0; };
    s.erase(s.begin(), std::find_if_not(s.begin(), s.end(), space));
    s.erase(std::find_if_not(s.rbegin(), s.rend(), space).base(), s.end());
    if (s.size() >= 2 && (s[0] == '"' || s[0] == '\'') && s.back() == s[0])
        s = s.substr(1, s.size() - 2);
    return s;
}

} // namespace

bool parseInfluenceMapEntry(const std::string& text, InfluenceNameMap& names)
{
    const std::size_t equals = text.find('=');
    if (equals == std::string::npos)
        return false;
    const std::string from = trimmed(text.substr(0, equals)), to = trimmed(text.substr(equals + 1));
    if (from.empty() || to.empty())
        return false;
    names[from] = to;
    return true;
}

Result<InfluenceNameMap> readInfluenceNameMapText(const std::string& text, const std::string& displayName)
{
    std::istringstream in(text);
    InfluenceNameMap names;
    Diagnostics problems;
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        if (const std::size_t hash = line.find('#'); hash != std::string::npos)
            line.erase(hash);
        if (trimmed(line).empty())
            continue;
        const std::size_t colon = line.find(": ") != std::string::npos ? line.find(": ") : line.find(':');
        if (line.find('=') == std::string::npos && colon != std::string::npos)
            line[colon] = '=';
        if (!parseInfluenceMapEntry(line, names))
            problems.push_back(
                makeError({displayName, number, 1}, "expected 'OLD=NEW' or 'OLD: NEW' (an influence name and a rig joint name)"));
    }
    if (!problems.empty())
        return Result<InfluenceNameMap>::failure(std::move(problems));
    return names;
}

Result<InfluenceNameMap> readInfluenceNameMap(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return Result<InfluenceNameMap>::failure(makeError({path, 0, 0}, "cannot read the name map"));
    std::ostringstream text;
    text << in.rdbuf();
    return readInfluenceNameMapText(text.str(), path);
}

} // namespace rs::io
