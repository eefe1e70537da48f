#pragma once
// Edits of the character: its models and the skin weights bound to the rig.
// Each is one undo step (a paint stroke is a transaction of weight edits, one
// step when it ends); a refused edit changes nothing and says why.
#include "base/Status.h"
#include "edit/History.h"

#include <string>
#include <vector>

namespace rs::edit {

// Adds a model file (an absolute path; the file is not read here). Refused
// when it is already one of the guide's models.
Status addModel(History& history, const std::string& path);
// Removes a model and the weights of its meshes (undo brings both back).
Status removeModel(History& history, const std::string& path);

// Puts `bindings` in place: each replaces the record of the same model and
// mesh (the n-th record of a name pairs with the n-th new one), or is added.
// One undo step named `what` ("Bind skin"). Refused when a record names a
// model the guide does not have or its weights do not fit its vertex count.
Status setBindings(History& history, std::vector<model::MeshBinding> bindings, const std::string& what);

// New influences of some vertices of one binding (a paint dab, a smooth...).
struct VertexWeights {
    std::uint32_t vertex = 0;
    std::vector<model::Influence> influences; // into the binding's joints (after the edit)
};
struct WeightEdit {
    std::size_t binding = 0;                 // into GuideDocument::bindings
    // The binding's joints after the edit: the current ones, possibly with
    // more appended (painting a joint that had no weight yet); empty: unchanged.
    std::vector<NodeKey> joints;
    std::vector<std::int32_t> parents;       // per joint, as MeshWeights::parents (with `joints`)
    std::vector<VertexWeights> vertices;     // ascending vertex order, each at most once
};
// Refused when the binding, a vertex or a joint index is out of range, a
// weight is not finite or negative, a vertex's weights do not sum to 1
// (within 1e-3) or nothing changes.
Status setVertexWeights(History& history, WeightEdit edit, const std::string& what);

} // namespace rs::edit
