#include "templates/TemplateRegistry.h"

#include <cctype>
#include <filesystem>

namespace rs::templates {

namespace fs = std::filesystem;

namespace {

const char* kFallbackIcon = "template";

} // namespace

bool isIconName(const std::string& name)
{
    if (name.empty() || name.size() > 64 || name.front() == '.')
        return false;
    for (const char c : name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
            return false;
    return true;
}

void TemplateRegistry::reset(const std::string& iconsDirectory)
{
    m_manifests.clear();
    m_shapes.clear();
    m_iconsDirectory = iconsDirectory;
}

void TemplateRegistry::add(TemplateManifest manifest)
{
    const std::string id = manifest.id;
    m_manifests[id] = std::move(manifest);
}

Diagnostics TemplateRegistry::crossCheck() const
{
    Diagnostics diagnostics;
    std::error_code ec;
    for (const auto& [id, m] : m_manifests) {
        for (const ShapeSpec& s : m.shapes)
            if (!s.shape.empty() && !m_shapes.find(s.shape))
                diagnostics.push_back(makeWarning(s.where, "unknown shape '" + s.shape + "' in shapes." + s.key +
                                                               " (a circle is used)"));
        if (!m.icon.empty() && isIconName(m.icon) && !fs::exists(fs::path(m_iconsDirectory) / (m.icon + ".svg"), ec))
            diagnostics.push_back(makeWarning(m.iconWhere, "icon '" + m.icon + "' not found in " + m_iconsDirectory +
                                                                  " (the default icon is used)"));
    }
    return diagnostics;
}

const TemplateManifest* TemplateRegistry::find(const std::string& id) const
{
    auto it = m_manifests.find(id);
    return it == m_manifests.end() ? nullptr : &it->second;
}

std::vector<const TemplateManifest*> TemplateRegistry::all() const
{
    std::vector<const TemplateManifest*> out;
    for (const auto& [id, m] : m_manifests)
        out.push_back(&m);
    return out;
}

std::vector<std::string> TemplateRegistry::categories() const
{
    std::vector<std::string> out;
    for (const auto& [id, m] : m_manifests)
        if (out.empty() || out.back() != m.category)
            out.push_back(m.category);
    return out;
}

std::string TemplateRegistry::iconPath(const TemplateManifest& manifest) const
{
    std::error_code ec;
    const fs::path icon = fs::path(m_iconsDirectory) / (manifest.icon + ".svg");
    if (isIconName(manifest.icon) && fs::exists(icon, ec))
        return icon.string();
    return (fs::path(m_iconsDirectory) / (std::string(kFallbackIcon) + ".svg")).string();
}

} // namespace rs::templates
