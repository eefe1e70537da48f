#pragma once
// All known templates and shapes. A templates folder holds
// <category>/<module>/template.yml plus a shapes/ library; folders scanned later
// override earlier ones (user folders over built-ins). Broken manifests are left
// out and reported; the rest stay usable.
#include "base/Diagnostic.h"
#include "templates/Manifest.h"
#include "templates/ShapeLibrary.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rs::templates {

class TemplateRegistry {
public:
    // Replaces the content with what the folders hold; returns every diagnostic.
    Diagnostics scan(const std::vector<std::string>& folders, const std::string& iconsDirectory);

    const TemplateManifest* find(const std::string& id) const;
    std::vector<const TemplateManifest*> all() const; // sorted by id
    std::vector<std::string> categories() const;
    const ShapeLibrary& shapes() const { return m_shapes; }
    // The icon's SVG path, or the fallback icon when the manifest's is missing.
    std::string iconPath(const TemplateManifest& manifest) const;

    // Convenience: scans templateSearchPath() and iconsDirectory().
    static std::shared_ptr<TemplateRegistry> loadDefault(Diagnostics& diagnostics);

private:
    std::map<std::string, TemplateManifest> m_manifests;
    ShapeLibrary m_shapes;
    std::string m_iconsDirectory;
};

} // namespace rs::templates
