#pragma once
// Undoable edits of the guide's mods (model/Mod.h): each pushes one command
// with a change event of kind Mods naming the mod's owner instance (none for
// a global mod). Mods are addressed by their index in GuideDocument::mods
// (the order they apply in). A refused edit changes nothing; an edit that
// changes nothing pushes no step.
#include "base/Status.h"
#include "edit/History.h"

#include <optional>
#include <string>

namespace rs::edit {

// Why a mod cannot be stored (a reference without a tag, a channel missing
// where the kind needs one, weights that are not one per target, keys not
// sorted or not finite, min above max...), or empty.
std::string modProblem(const model::Mod& mod);

// Inserts `mod` at `index` (nullopt: at the end). `what` names the undo step ("Add space mod" when empty).
Status addMod(History& history, model::Mod mod, std::optional<std::size_t> index = std::nullopt, const std::string& what = {});
// Replaces mod `index` by `mod` (its owner included).
Status setMod(History& history, std::size_t index, model::Mod mod, const std::string& what = {});
Status removeMod(History& history, std::size_t index, const std::string& what = {});

} // namespace rs::edit
