#pragma once
// The guide file's `pose:` section of schema 2 (internal to io/GuideFile): the
// rigger's test pose, one record per node keyed by instance id, branch and tag
// (read into overrides since schema 3):
//   - {instance: 4, branch: L, node: ctrls.fk.0, values: {rz: 30}}  # arm
// Guides of schema 1 keyed it by the instance's name ("arm.L::ctrls.fk.0"):
// such records are read as legacy records and migrated once every instance is
// read; those that name no instance stay as `legacy_pose:` and are reported.
#include "io/YamlSupport.h"
#include "model/GuideDocument.h"

#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace rs::io {

// A schema-1 record, with where it was in the file (for messages).
struct LegacyPoseRecord {
    std::string text;
    std::map<std::string, double> channels;
    SourceLocation where;
};

// `pose:` (a list: keyed records; a map: legacy records) or `legacy_pose:`.
void readPose(YamlReader& r, const YAML::Node& node, model::PoseValues& pose, std::vector<LegacyPoseRecord>& legacy);
// The one place the schema-1 text form of a node is parsed; a note says how many migrated.
void migrateLegacyPose(YamlReader& r, std::vector<LegacyPoseRecord>& legacy, model::GuideDocument& doc);
// `legacy_pose:` as the guide file writes it (nothing when empty); the keyed
// test pose is written with the other overrides (io/OverrideFile.h).
void writeLegacyPose(std::ostream& out, const model::GuideDocument& doc);

} // namespace rs::io
