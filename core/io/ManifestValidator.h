// Checks between a template manifest's keys, made once the whole file is read
// (structure addresses, their cycles, shape placement targets, hierarchy rules
// and their option conditions, ui hooks), so a mistake is reported at its line
// when the library loads and not at build time. Internal to io.
#pragma once

#include "io/YamlSupport.h"
#include "templates/Manifest.h"

namespace rs::io {

// Reports through `reader` (errors and warnings at the offending node's line).
void validateManifest(YamlReader& reader, const templates::TemplateManifest& manifest, const YAML::Node& root);

} // namespace rs::io
