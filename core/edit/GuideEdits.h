#pragma once
// The edits a rigger makes to a guide, each validated and then pushed as one
// undoable command ("AddInstance", "RenameInstance"...). A refused edit returns
// a failed Status and changes nothing; its error names what it is about (the
// instance for an instance edit, the guide joint for a joint edit, the shape
// for a shape edit), so the log can select it. An edit that changes nothing
// and is not refused succeeds without pushing a step.
#include "base/Status.h"
#include "edit/History.h"
#include "edit/OverrideEdits.h"

#include <string>

namespace rs::edit {

// Adds a fully formed instance (ids and joints prepared by rs::rigging::makeInstance).
Status addInstance(History& history, model::TemplateInstance instance);
// Removes the instance and everything hanging below it.
Status removeInstance(History& history, model::InstanceId id);
// Removes several instances (each with everything below it) as one undo step.
Status removeInstances(History& history, const std::vector<model::InstanceId>& ids);
Status renameInstance(History& history, model::InstanceId id, const std::string& newName);
// Copies the instances (each with everything hanging below it) in place, with
// new ids and free names ("arm" -> "arm1"), as one undo step. `copies` gets the
// ids of the new top instances, in order.
Status duplicateInstances(History& history, const std::vector<model::InstanceId>& ids,
                          std::vector<model::InstanceId>* copies = nullptr);
// Re-hangs an instance (and what hangs below it) under another joint (kNoId:
// top level), keeping its guide where it is in the world. Refused under its own
// subtree.
Status reparentInstance(History& history, model::InstanceId id, model::JointId hookJoint);
Status setJointTransform(History& history, model::JointId joint, const Transform& local);
// `value` equal to `defaultValue` removes the stored option (instances keep only
// values that differ from the defaults).
Status setOption(History& history, model::InstanceId id, const std::string& option, const Value& value,
                 const Value& defaultValue);

// A per-instance name override of a manifest name token; an empty name (or the
// template's default) removes the override. Names are letters, digits and _.
Status setNameOverride(History& history, model::InstanceId id, const std::string& token, const std::string& name,
                       const std::string& defaultName);

// Replaces an instance (same id) as one undo step named `what`: used when its
// guide joints are regenerated. Refused when a child instance hangs under a
// joint the new one no longer has, or a joint id belongs to another instance.
Status replaceInstance(History& history, model::TemplateInstance instance, const std::string& what);

bool isValidInstanceName(const std::string& name);

} // namespace rs::edit
