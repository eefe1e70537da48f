#pragma once
// Reads template.yml files into templates::TemplateManifest (the data class
// lives in templates/, the YAML reading here in io/). Collects every problem with its
// file:line:col; unknown keys are warnings, wrong types errors. A manifest with
// errors yields no value, so a broken template is never half-used.
#include "base/Result.h"
#include "templates/Manifest.h"

#include <string>

namespace rs::io {

Result<templates::TemplateManifest> readManifest(const std::string& file, const std::string& category,
                                                 const std::string& module);
Result<templates::TemplateManifest> readManifestText(const std::string& text, const std::string& displayName,
                                                     const std::string& category, const std::string& module);

// The options every template has (Mikan's common_data), layered under its own opts.
const std::vector<templates::Parameter>& commonOptions();

} // namespace rs::io
