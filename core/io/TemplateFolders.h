#pragma once
// Reads template folders into a templates::TemplateRegistry. A folder holds
// <category>/<module>/template.yml plus a shapes/ library; folders read later
// override earlier ones (user folders over built-ins). Broken manifests and
// shapes are left out and reported; the rest stay usable.
#include "base/Diagnostic.h"
#include "templates/TemplateRegistry.h"

#include <memory>
#include <string>
#include <vector>

namespace rs::io {

// Replaces the registry's content with what the folders hold; returns every
// diagnostic, in scan order (the files are parsed in parallel).
Diagnostics scanTemplates(templates::TemplateRegistry& registry, const std::vector<std::string>& folders,
                          const std::string& iconsDirectory);

// Convenience: a registry of templateSearchPath() with iconsDirectory().
std::shared_ptr<templates::TemplateRegistry> loadDefaultTemplates(Diagnostics& diagnostics);

} // namespace rs::io
