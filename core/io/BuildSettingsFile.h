#pragma once
// The guide file's `build:` section (internal to io/GuideFile): the guide's
// build settings (model/BuildSettings.h), written only when they differ from
// the defaults, so a guide that never changed them has no such section:
//   build:
//     cleanup: on                  # lock and hide what animators should not touch
//     no_restore: [shapes, pose]   # override kinds a build leaves out
// `no_restore` names kinds as `rigsmith-cli build --no-restore KIND` does.
#include "io/YamlSupport.h"
#include "model/BuildSettings.h"

#include <ostream>

namespace rs::io {

// `build:`: errors (file:line) for a value of the wrong type and an unknown
// override kind; an unknown key warns.
void readBuildSettings(YamlReader& r, const YAML::Node& node, model::BuildSettings& settings);
// `build:` as the guide file writes it (nothing for the defaults).
void writeBuildSettings(std::ostream& out, const model::BuildSettings& settings);

} // namespace rs::io
