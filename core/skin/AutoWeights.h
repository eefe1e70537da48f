#pragma once
// Automatic weights: binds a mesh to a rig's skin joints.
//  - heat (default; Baran & Popovic 2007): each bone's weight is the
//    steady-state heat over the welded surface when the bone is held at 1 and
//    the others at 0, each vertex heated by its nearest *visible* bone with
//    strength 1/d^2. One sparse Cholesky factorisation, one solve per bone,
//    bones solved in parallel. A part the heat cannot reach (no vertex sees a
//    bone: an eye inside a closed head) takes its closest bone, and says so.
//  - envelope: the nearest bones by inverse square distance.
//  - closest: the nearest bone takes all.
// No vertex is ever left unweighted: weights are normalised, limited to
// `maxInfluences` and pruned below `pruneBelow` (then normalised again).
#include "base/Result.h"
#include "model/Mesh.h"
#include "skin/SkinBones.h"

#include <functional>

namespace rs::skin {

enum class BindMethod { Heat, Envelope, Closest };
const char* bindMethodName(BindMethod method); // "heat", "envelope", "closest"
std::optional<BindMethod> parseBindMethod(const std::string& text);

struct BindOptions {
    BindMethod method = BindMethod::Heat;
    int maxInfluences = 4;    // 1 to 8
    double pruneBelow = 0.01; // a share below this goes to the others
    // The model's other meshes: they hide bones too (a closed head hides the
    // eyes inside it from every bone, so the eyes take their closest bone).
    std::vector<const model::Mesh*> occluders;
    // Told the fraction done (0 to 1); returning false cancels the bind.
    std::function<bool(double)> progress;
};

struct BindStats {
    std::size_t vertices = 0, surfaceVertices = 0, parts = 0;
    std::size_t partsByClosestBone = 0;   // parts the heat could not reach
    std::size_t verticesByClosestBone = 0;
    std::size_t bonesSolved = 0;
};

// Fails when there is no bone, the options are out of range, or the bind was
// cancelled (nothing is changed then). Notes say which parts fell back.
Result<model::MeshWeights> bindMesh(const model::Mesh& mesh, const std::vector<SkinBone>& bones, const BindOptions& options,
                                    BindStats* stats = nullptr);

} // namespace rs::skin
