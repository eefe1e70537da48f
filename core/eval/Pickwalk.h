#pragma once
// Pickwalk, as animators know it from Maya: arrow keys move the selection over
// the controller hierarchy (the `ctrls` virtual hierarchy, which crosses
// templates through their hooks). Up: the virtual parent; Down: the first
// virtual child; Left/Right: the previous/next sibling, wrapping; Mirror: the
// L/R twin. Where there is nowhere to go, the node itself comes back.
// The same walk over template instances serves the outliner.
#include "model/GuideDocument.h"
#include "model/Rig.h"

#include <cstdint>
#include <vector>

namespace rs::eval {

enum class WalkDirection { Up, Down, Left, Right, Mirror };

// `shown` (EvalState::visible of the pose the animator sees; null: all)
// skips controllers a visibility constraint hides, as if they were not there.
model::RigNodeIndex pickwalk(const model::Rig& rig, model::RigNodeIndex from, WalkDirection direction,
                             const std::vector<std::uint8_t>* shown = nullptr);
// Instances: parent, first child, siblings; Mirror swaps a trailing L/R (l/r,
// Left/Right) token of the name ("arm_L" <-> "arm_R") when that instance exists.
model::InstanceId pickwalk(const model::GuideDocument& guide, model::InstanceId from, WalkDirection direction);

} // namespace rs::eval
