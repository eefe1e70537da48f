#pragma once
// CPU skinning (export, tests, the CLI; the viewport skins on the GPU): a job
// that is validated once and run per pose, as in ozz-animation. Linear blend
// skinning, or dual-quaternion skinning (no candy-wrapper collapse when a
// joint twists). Vertices are skinned in parallel.
#include "base/Status.h"
#include "model/Mesh.h"

#include <span>
#include <vector>

namespace rs::skin {

enum class SkinningMethod { Linear, DualQuaternion };

struct SkinningJob {
    SkinningMethod method = SkinningMethod::Linear;
    std::span<const glm::vec3> positions;   // bind pose
    std::span<const glm::vec3> normals;     // bind pose; may be empty
    const model::MeshWeights* weights = nullptr;
    // Per weights joint: its posed world matrix times its inverse bind matrix.
    std::span<const Mat4> skinMatrices;
    std::span<glm::vec3> outPositions;
    std::span<glm::vec3> outNormals;        // empty when normals are

    // Sizes agree, every influence names a joint the matrices cover.
    Status validate() const;
    // Skins every vertex; validate() first (run() checks nothing).
    void run() const;
};

} // namespace rs::skin
