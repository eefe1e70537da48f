#pragma once
// Undoable edits of the guide's build settings (model/BuildSettings.h): the
// restore toggles and cleanup, saved with the guide. Each is one command with
// the change event ChangeKind::Build (a built rig is built again).
#include "base/Status.h"
#include "edit/History.h"

#include <string>

namespace rs::edit {

// Replaces the build settings, one undo step named `what`. Refused when
// nothing changes, so no empty step lands on the stack.
Status setBuildSettings(History& history, const model::BuildSettings& settings, const std::string& what);

} // namespace rs::edit
