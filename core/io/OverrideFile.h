#pragma once
// The guide file's `overrides:` section (internal to io/GuideFile): one record
// per rig node, sorted by key, each kind on its own line so a diff shows what
// changed:
//   overrides:
//     - instance: 4            # arm
//       branch: L
//       node: ctrls.fk.0
//       shape: {t: [0, 0.1, 0], s: [2, 2, 2], color: [1, 0, 0], line_width: 2, visible: on}
//       cvs:
//         - {curve: 0, cv: 3, offset: [0, 0.05, 0]}
//       defaults: {rx: 10}
//       limits: {rx: [-45, 90]}
//       locks: {tx: {locked: on, keyable: off}}
//       name: upperarm_fk_L
//       pose: {rz: 30}
//     - node: rig                # the rig root: the post transform
//       post: {t: [0, 0, 1], s: [2, 2, 2]}
// A guide of schema 2 kept shape edits in each instance (`shapes:`) and the
// test pose in `pose:`; both are read into overrides with a note.
#include "io/YamlSupport.h"
#include "model/GuideDocument.h"

#include <map>
#include <ostream>
#include <string>

namespace rs::io {

// `overrides:`: errors (file:line) for a bad record, a second record of one node, an unknown channel value.
void readOverrides(YamlReader& r, const YAML::Node& node, model::Overrides& overrides);
// An older guide's instance `shapes:` ({ctrls.ik: {t, r, s, cvs}}): tag -> edit.
bool readLegacyShapes(YamlReader& r, const YAML::Node& node, std::map<std::string, model::ShapeEdit>& shapes);
// `overrides:` as the guide file writes it (nothing when empty).
void writeOverrides(std::ostream& out, const model::GuideDocument& doc);

} // namespace rs::io
