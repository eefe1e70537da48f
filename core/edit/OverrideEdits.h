#pragma once
// Undoable edits of the guide's overrides (model/Override.h): each pushes one
// command that replaces the records it touches, with a change event naming
// what changed (Shapes for shapes, Pose for the test pose, Overrides for
// defaults, limits, locks, the post transform and display names) and the
// instances concerned. A refused edit changes nothing; an edit that changes
// nothing pushes no step.
#include "base/Status.h"
#include "edit/History.h"

#include <map>
#include <optional>
#include <string>

namespace rs::edit {

// Sets one node's record (an empty record removes it). Refused for a bad
// record: a limit with min above max, a line width not above 0, a colour
// outside [0, 1], a number that is not finite, a post transform off the rig
// root, an empty display name or channel name. `what` names the undo step.
Status setOverride(History& history, const NodeKey& key, const model::Override& record, const std::string& what);
// Sets or clears one kind of one node's record, keeping its other kinds.
Status setOverrideKind(History& history, const NodeKey& key, model::OverrideKind kind, const model::Override& from,
                       const std::string& what);
Status removeOverride(History& history, const NodeKey& key, const std::string& what = {});
// Sets many nodes' records as one undo step named `what` (an empty record
// removes its node's). Refused, changing nothing, when any record is bad (as
// setOverride) or when nothing changes.
Status setOverrides(History& history, const std::map<NodeKey, model::Override>& records, const std::string& what);

// A controller shape's edit (`tag` as "ctrls.ik") in the controller's space,
// kept in the shape override of the instance's authored side (branch "");
// the identity clears the edit. One undo step named `what` ("Edit shape <tag>" when empty).
Status setShapeEdit(History& history, model::InstanceId id, const std::string& tag, const model::ShapeEdit& edit,
                    const std::string& what = {});

// Replaces the document's test pose (one undo step per pose tool or gizmo drag);
// `what` names the step ("Rotate c_arm1_L", "Mirror pose"). Refused when
// nothing changes, so no empty step lands on the stack.
Status setPose(History& history, const model::PoseValues& pose, const std::string& what);

} // namespace rs::edit
