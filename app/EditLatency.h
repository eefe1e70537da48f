#pragma once
// rigsmith --edit-latency GUIDE: `drags` guide-joint drags (four mouse moves
// and a release each) through the viewport's gizmo signals, as a mouse makes
// them, with the rig built (so every preview rebuilds it live). Prints JSON:
// the median and worst time from an edit to the repainted frame, in ms.
#include "MainWindow.h"

#include <string>

namespace rs::app {

int reportEditLatency(MainWindow& window, int drags = 100);
// The same in Rig mode: `drags` drags rotating the controller at `path` (a rig
// display path) back and forth, four moves each; the character's meshes are
// skinned on the GPU every frame. Also reports the mesh vertices and weights
// sent during the drags (0 expected: posing sends the palette only).
int reportRigEditLatency(MainWindow& window, const std::string& path, int drags = 100);

} // namespace rs::app
