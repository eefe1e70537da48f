#pragma once
// rigsmith --edit-latency GUIDE: `drags` guide-joint drags (four mouse moves
// and a release each) through the viewport's gizmo signals, as a mouse makes
// them, with the rig built (so every preview rebuilds it live). Prints JSON:
// the median and worst time from an edit to the repainted frame, in ms.
#include "MainWindow.h"

namespace rs::app {

int reportEditLatency(MainWindow& window, int drags = 100);

} // namespace rs::app
