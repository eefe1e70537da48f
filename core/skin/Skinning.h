#pragma once
// CPU skinning (export, tests, the CLI; the viewport skins on the GPU): a job
// that is validated once and run per pose, as in ozz-animation. Linear blend
// skinning, or dual-quaternion skinning (no candy-wrapper collapse when a
// joint twists). Vertices are skinned in parallel.
//
// For speed, prepare the weights once per bind (PreparedSkin::prepare) and
// name them in every job; a job may also read a MeshWeights in place (slower:
// the general layout, and validate() scans every influence).
#include "base/Result.h"
#include "base/Status.h"
#include "model/Mesh.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace rs::skin {

enum class SkinningMethod { Linear, DualQuaternion };

// One mesh's weights laid out for skinning, once per bind rather than per pose.
// When every vertex has one to four influences and no joint index reaches
// 65,536, each vertex gets exactly four joint indices (uint16) and four weights
// (float) in two flat arrays, a missing influence being weight 0 on the
// vertex's first joint: the fixed layout, skinned by the fast loops. Otherwise
// the offsets and influences are kept as they are (the general loops).
// Holds copies: the MeshWeights may change or go afterwards.
class PreparedSkin {
public:
    // Refused when the offsets do not describe the influences (not starting
    // at 0, decreasing, or not ending at the influence count).
    static Result<PreparedSkin> prepare(const model::MeshWeights& weights);

    PreparedSkin() = default; // no vertex
    std::size_t vertexCount() const { return m_vertexCount; }
    // The skin matrices a job needs: one more than the largest joint named.
    std::size_t matrixCount() const { return m_matrixCount; }
    bool hasFixedLayout() const { return m_fixed; }

    // The fixed layout (empty otherwise): per vertex, four joints and weights.
    std::span<const std::array<std::uint16_t, 4>> fixedJoints() const { return m_joints; }
    std::span<const std::array<float, 4>> fixedWeights() const { return m_weights; }
    // The general layout (empty when fixed), as in model::MeshWeights.
    std::span<const std::uint32_t> offsets() const { return m_offsets; }
    std::span<const model::Influence> influences() const { return m_influences; }

private:
    std::size_t m_vertexCount = 0, m_matrixCount = 0;
    bool m_fixed = false;
    std::vector<std::array<std::uint16_t, 4>> m_joints;
    std::vector<std::array<float, 4>> m_weights;
    std::vector<std::uint32_t> m_offsets;
    std::vector<model::Influence> m_influences;
};

struct SkinningJob {
    SkinningMethod method = SkinningMethod::Linear;
    std::span<const glm::vec3> positions;   // bind pose
    std::span<const glm::vec3> normals;     // bind pose; may be empty
    // The weights: prepared ones when set (fast), else `weights` read in place.
    const PreparedSkin* prepared = nullptr;
    const model::MeshWeights* weights = nullptr;
    // Per weights joint: its posed world matrix times its inverse bind matrix.
    std::span<const Mat4> skinMatrices;
    std::span<glm::vec3> outPositions;
    std::span<glm::vec3> outNormals;        // empty when normals are

    // Sizes agree, every influence names a joint the matrices cover. With
    // prepared weights this costs nothing per vertex.
    Status validate() const;
    // Skins every vertex; validate() first (run() checks nothing). Normals
    // are turned by the blended transform and normalised (linear blend), or
    // rotated by the blended rotation (dual quaternion).
    void run() const;
};

} // namespace rs::skin
