#pragma once
// Reads template.yml files into TemplateManifest. Collects every problem with its
// file:line:col; unknown keys are warnings, wrong types errors. A manifest with
// errors yields no value, so a broken template is never half-used.
#include "base/Result.h"
#include "templates/Manifest.h"

#include <string>

namespace rs::templates {

Result<TemplateManifest> readManifest(const std::string& file, const std::string& category,
                                      const std::string& module);
Result<TemplateManifest> readManifestText(const std::string& text, const std::string& displayName,
                                          const std::string& category, const std::string& module);

// The options every template has (Mikan's common_data), layered under its own opts.
const std::vector<Parameter>& commonOptions();

} // namespace rs::templates
