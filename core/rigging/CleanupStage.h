#pragma once
// Cleanup: the build stage that turns a rigger's rig into the animators' one
// (seed 004's clean-up process, Mikan's release build), run when the guide's
// build settings ask for it (model::BuildSettings::cleanup) right after the
// overrides' channels and before the evaluation program compiles:
//  - every group (offsets, roots, hooks, spaces, helpers; not the rig root)
//    and every joint (skin and setup) is hidden;
//  - on every controller, each transform channel its builder did not declare
//    animatable (model::ChannelSettings::animatable), or locked, is locked,
//    made not keyable and hidden; custom attributes stay animatable;
//  - a rigger's lock record for a channel (model::Override::locks, while the
//    locks kind is restored) wins: that channel keeps the record's state;
//  - each controller's animatable channels (those left unlocked) record their
//    default values (model::RigNode::defaultValues), which exports write.
// Without cleanup nothing here runs and the rig is as before.
#include "model/GuideDocument.h"
#include "model/Rig.h"

namespace rs::rigging {

// Cleans `rig` up in place (a rig built from `guide`; `restore` is the build's).
void cleanUpRig(model::Rig& rig, const model::GuideDocument& guide, const model::RestoreToggles& restore);

} // namespace rs::rigging
