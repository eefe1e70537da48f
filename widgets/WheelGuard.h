#pragma once
// Only a focused field takes the mouse wheel. The spin boxes, combo boxes and
// sliders under `root` take focus by click or Tab only (never by the wheel),
// and a wheel turned over one without focus goes to the panel around it (its
// scroll area scrolls) instead of changing the value. Call again after adding
// fields; installing twice is harmless.
class QWidget;

namespace rs::widgets {

void guardWheel(QWidget* root);

} // namespace rs::widgets
