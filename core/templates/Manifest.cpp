#include "templates/Manifest.h"

#include <algorithm>

namespace rs::templates {

namespace {
template <class List>
auto findByName(const List& list, const std::string& name) -> decltype(&list.front())
{
    auto it = std::find_if(list.begin(), list.end(), [&](const auto& p) { return p.name == name; });
    return it == list.end() ? nullptr : &*it;
}
} // namespace

const Parameter* TemplateManifest::findOpt(const std::string& n) const { return findByName(opts, n); }
const Parameter* TemplateManifest::findGuide(const std::string& n) const { return findByName(guides, n); }

const Parameter* TemplateManifest::findByOtherName(const std::string& n) const
{
    for (const auto* list : {&guides, &opts})
        for (const Parameter& p : *list)
            if (!p.legacy.empty() && p.legacy == n)
                return &p;
    return nullptr;
}

const ShapeSpec* TemplateManifest::findShape(const std::string& key) const
{
    auto it = std::find_if(shapes.begin(), shapes.end(), [&](const ShapeSpec& s) { return s.key == key; });
    return it == shapes.end() ? nullptr : &*it;
}

std::string TemplateManifest::defaultName(const std::string& token) const
{
    for (const auto& [t, n] : names)
        if (t == token)
            return n;
    return token;
}

std::optional<std::string> TemplateManifest::structureAddress(const std::string& tag) const
{
    for (const auto& [t, address] : structure)
        if (t == tag)
            return address;
    return std::nullopt;
}

std::optional<Vec3> parseAxis(const std::string& text)
{
    if (text.empty() || text.size() > 2)
        return std::nullopt;
    double sign = 1.0;
    char letter = text[0];
    if (text.size() == 2) {
        if (text[0] != '+' && text[0] != '-')
            return std::nullopt;
        sign = text[0] == '-' ? -1.0 : 1.0;
        letter = text[1];
    }
    switch (letter) {
    case 'x': return Vec3(sign, 0, 0);
    case 'y': return Vec3(0, sign, 0);
    case 'z': return Vec3(0, 0, sign);
    default: return std::nullopt;
    }
}

} // namespace rs::templates
