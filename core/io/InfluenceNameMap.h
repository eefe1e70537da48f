#pragma once
// Influence name maps for skin chunk imports (issue 20 item 4): which skin
// joint of the rig an influence of imported chunks lands on when the rig has
// no joint of its identity or name (skin/InfluenceMap.h applies the map).
// The CLI's --name-map and the editor's Skin Chunks dock read the same file:
//
//   # old influence name = rig skin joint name
//   elbow_old=arm_L_elbow_jnt
//   "hand old": arm_L_hand_jnt      (a flat YAML mapping reads too)
//
// One `OLD=NEW` or `OLD: NEW` per line, '#' comments, quotes around names
// optional. Errors carry file:line and every bad line is listed.
#include "base/Result.h"

#include <map>
#include <string>

namespace rs::io {

using InfluenceNameMap = std::map<std::string, std::string>; // influence name -> rig skin joint export name

Result<InfluenceNameMap> readInfluenceNameMap(const std::string& path);
Result<InfluenceNameMap> readInfluenceNameMapText(const std::string& text, const std::string& displayName);
// One `OLD=NEW` entry (--map) into `names`; false when either side is empty.
bool parseInfluenceMapEntry(const std::string& text, InfluenceNameMap& names);

} // namespace rs::io
