#pragma once
// A canonical, line-per-fact text of a parsed manifest: what Rigsmith understood
// of each key. Used by `rigsmith-cli describe-template` and the golden tests.
#include "templates/Manifest.h"

#include <string>

namespace rs::templates {

std::string describeManifest(const TemplateManifest& manifest);

} // namespace rs::templates
