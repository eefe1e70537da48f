#pragma once
// A deterministic, readable YAML dump of a built rig (rigsmith-cli build --dump):
// nodes in build order with ids, names, kinds, physical and virtual parents, rest
// world transforms (6 decimals) and controller shapes, then the constraints
// with every typed setting by name (attribute references as {node, attribute}).
// Used by golden tests.
#include "model/Rig.h"

#include <string>

namespace rs::io {

std::string writeRigDump(const model::Rig& rig);

} // namespace rs::io
