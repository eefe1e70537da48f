#pragma once
// The guide file's `mods:` section (internal to io/GuideFile): the mods in
// document order, each one map with its kind's key (io/ModText.h) and, for an
// instance's mod, `instance: <name>`:
//   mods:
//     - instance: arm
//       space:
//         node: ctrls.ik
//         target: spine::ctrls.chest
//     - hide: [arm.L::ctrls.pv]
#include "io/YamlSupport.h"
#include "model/GuideDocument.h"

#include <ostream>

namespace rs::io {

// Reads `mods:` into document.mods once the instances are read (names resolve
// to ids); errors at file:line:col for a malformed mod, each mod's location kept.
void readMods(YamlReader& r, const YAML::Node& node, model::GuideDocument& document);
// One mod's map (the kind's key; `instance:` allowed when `allowOwner`).
std::optional<model::Mod> readMod(YamlReader& r, const YAML::Node& node, const model::GuideDocument& document,
                                  const model::ModInstance& owner, bool allowOwner);
// `mods:` as the guide file writes it (nothing when there is none).
void writeMods(std::ostream& out, const model::GuideDocument& document);

} // namespace rs::io
