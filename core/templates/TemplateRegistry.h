#pragma once
// All known templates and shapes, keyed by id and name. The data only: the
// folders (<category>/<module>/template.yml plus a shapes/ library) are read by
// io/TemplateFolders, which fills a registry; folders read later override
// earlier ones (user folders over built-ins).
#include "base/Diagnostic.h"
#include "templates/Manifest.h"
#include "templates/ShapeLibrary.h"

#include <map>
#include <string>
#include <vector>

namespace rs::templates {

// A manifest's `ui.icon` names a file in the icons folder and nothing else: a
// plain name of letters, digits, '_', '-' and '.' (not first), at most 64
// bytes. No '/', "..", absolute path or NUL byte can lead it out of the folder.
bool isIconName(const std::string& name);

class TemplateRegistry {
public:
    // Empties the registry; icons are then looked up in `iconsDirectory`.
    void reset(const std::string& iconsDirectory);
    // Adds a manifest, replacing one with the same id.
    void add(TemplateManifest manifest);
    // Problems only the whole library shows: unknown shapes, missing icons (warnings).
    Diagnostics crossCheck() const;

    const TemplateManifest* find(const std::string& id) const;
    std::vector<const TemplateManifest*> all() const; // sorted by id
    std::vector<std::string> categories() const;
    const ShapeLibrary& shapes() const { return m_shapes; }
    ShapeLibrary& shapes() { return m_shapes; }
    const std::string& iconsDirectory() const { return m_iconsDirectory; }
    // The icon's SVG path in iconsDirectory(), or the fallback icon when the
    // manifest's is missing or not an isIconName (never a path outside the folder).
    std::string iconPath(const TemplateManifest& manifest) const;

private:
    std::map<std::string, TemplateManifest> m_manifests;
    ShapeLibrary m_shapes;
    std::string m_iconsDirectory;
};

} // namespace rs::templates
