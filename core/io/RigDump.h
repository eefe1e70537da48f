#pragma once
// A deterministic, readable YAML dump of a built rig (rigsmith-cli build --dump):
// nodes in build order with ids, names, kinds, physical and virtual parents, rest
// world transforms (6 decimals) and controller shapes. Used by golden tests.
#include "model/Rig.h"

#include <string>

namespace rs::io {

std::string writeRigDump(const model::Rig& rig);

} // namespace rs::io

namespace rs::model { struct Skeleton; }

namespace rs::io {

// The export skeleton as JSON: [{"name", "parent" (name or null), "head": [x,y,z]}]
// with world-space bind positions (metres, Y-up). For pipelines and consumer checks.
std::string writeSkeletonJson(const model::Skeleton& skeleton);

} // namespace rs::io
