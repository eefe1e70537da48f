#pragma once
// A keyed clip file (io::KeyedClip, exported with cubic keys): poses a rigger
// keys at times, each pose in the guide's `pose:` record form (node by
// instance id, branch and node path; channel values as in the test pose):
//   rigsmith_clip: 1
//   name: wave
//   keys:
//     - time: 0
//       pose: []
//     - time: 0.4
//       pose:
//         - {instance: 4, branch: L, node: ctrls.fk.0, values: {rz: 50}}
// Keys need increasing times from 0 s, at least two; a channel a key does not
// name is at its default there. Problems are reported at their file:line.
#include "base/Result.h"
#include "io/ExportScene.h"

#include <string>

namespace rs::io {

Result<KeyedClip> readClipText(const std::string& text, const std::string& displayName);
Result<KeyedClip> readClipFile(const std::string& path);

} // namespace rs::io
