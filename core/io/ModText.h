#pragma once
// One mod (model/Mod.h) as YAML text: what the guide file's `mods:` section
// holds per mod and what the editor's Mods panel edits. A mod is a map with one
// key, its kind, e.g.
//   space:
//     node: ctrls.ik
//     target: spine::ctrls.chest
//     label: chest
// Nodes are named by rig id, `instance[.branch]::tag[@channel]` (the instance's
// current name; `::rig` is the rig root); in an instance's mod a bare tag
// (`ctrls.ik`) is that instance's node, on each branch copy. The text is parsed
// here only: reading resolves every instance name to its id (a name no instance
// has is kept, and reported when the rig is built). templates/README.md
// documents every kind's keys.
#include "base/Result.h"
#include "model/GuideDocument.h"

#include <string>

namespace rs::io {

// The mod's text (its kind's key and body, block style, no owner), ending in a newline.
std::string writeModText(const model::GuideDocument& document, const model::Mod& mod);
// Reads one mod's text as a mod of `owner` (none: global; its id when the instance exists).
// Errors at line:col of `displayName` for malformed text, an unknown kind or
// key of the wrong type, a bare tag in a global mod, a channel where a node is
// expected and the reverse; unknown keys warn.
Result<model::Mod> readModText(const model::GuideDocument& document, const model::ModInstance& owner, const std::string& text,
                               const std::string& displayName = "mod");
// A sample of each kind (the panel's Add), for a mod of an instance or a global one.
std::string modSample(model::ModKind kind, bool ofInstance);
// A reference as its rig id text, relative to a mod of `owner` (bare tag when it is the owner's own node).
std::string formatModRef(const model::GuideDocument& document, const model::ModRef& ref, const model::ModInstance& owner);
// An instance's name as a mod names it: its current name, else the name it was read with.
std::string modInstanceName(const model::GuideDocument& document, const model::ModInstance& instance);

} // namespace rs::io
