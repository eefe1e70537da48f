#include "skin/Skinning.h"

#include <glm/gtc/quaternion.hpp>
#include <tbb/parallel_for.h>

#include <array>
#include <cmath>

namespace rs::skin {

Status SkinningJob::validate() const
{
    if (!weights)
        return Status::refused("skinning: no weights");
    if (weights->vertexCount() != positions.size())
        return Status::refused("skinning: " + std::to_string(weights->vertexCount()) + " weighted vertices for a mesh of " +
                               std::to_string(positions.size()));
    if (outPositions.size() != positions.size())
        return Status::refused("skinning: the output holds " + std::to_string(outPositions.size()) + " positions, not " +
                               std::to_string(positions.size()));
    if (!normals.empty() && (normals.size() != positions.size() || outNormals.size() != positions.size()))
        return Status::refused("skinning: normals and their output must have one entry per vertex");
    if (skinMatrices.size() < weights->joints.size())
        return Status::refused("skinning: " + std::to_string(skinMatrices.size()) + " joint matrices for " +
                               std::to_string(weights->joints.size()) + " joints");
    if (weights->offsets.back() != weights->influences.size())
        return Status::refused("skinning: the influence offsets do not match the influences");
    for (const model::Influence& influence : weights->influences)
        if (influence.joint >= skinMatrices.size())
            return Status::refused("skinning: an influence names joint " + std::to_string(influence.joint) + " of " +
                                   std::to_string(skinMatrices.size()));
    return {};
}

namespace {

// 3x4 float matrices (rows), the form the inner loop reads.
using Affine = std::array<float, 12>;

Affine toAffine(const Mat4& m)
{
    Affine a;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c)
            a[std::size_t(r * 4 + c)] = float(m[c][r]);
    return a;
}

struct DualQuat {
    glm::quat real, dual;
};

DualQuat toDualQuat(const Mat4& m)
{
    const glm::dmat3 r(m);
    // Scale is not part of a dual quaternion: orthonormalise the rotation.
    const glm::dquat q = glm::normalize(glm::quat_cast(glm::dmat3(glm::normalize(r[0]), glm::normalize(r[1]), glm::normalize(r[2]))));
    const glm::dvec3 t(m[3]);
    const glm::dquat d = 0.5 * glm::dquat(0.0, t.x, t.y, t.z) * q;
    return {glm::quat(q), glm::quat(d)};
}

// Linear blend skinning of vertices [first, last): the hot loop, compiled
// twice (AVX2 + FMA where the CPU has them, plain x86-64 otherwise) and picked
// at load time, so the build stays portable.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("arch=haswell", "default")))
#endif
void skinLinear(std::size_t first, std::size_t last, const Affine* joints, const std::uint32_t* offsets,
                const model::Influence* influences, const glm::vec3* in, const glm::vec3* inNormals, glm::vec3* out,
                glm::vec3* outN)
{
    for (std::size_t v = first; v != last; ++v) {
        float m[12] = {};
        const std::uint32_t end = offsets[v + 1];
        for (std::uint32_t i = offsets[v]; i < end; ++i) {
            const float* a = joints[influences[i].joint].data();
            const float s = influences[i].weight;
            for (int k = 0; k < 12; ++k)
                m[k] += s * a[k];
        }
        const glm::vec3 p = in[v];
        out[v] = {m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3], m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
                  m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]};
        if (inNormals) {
            const glm::vec3 q = inNormals[v];
            const glm::vec3 turned{m[0] * q.x + m[1] * q.y + m[2] * q.z, m[4] * q.x + m[5] * q.y + m[6] * q.z,
                                   m[8] * q.x + m[9] * q.y + m[10] * q.z};
            const float squared = turned.x * turned.x + turned.y * turned.y + turned.z * turned.z;
            outN[v] = squared > 0.0f ? turned * (1.0f / std::sqrt(squared)) : q;
        }
    }
}

} // namespace

void SkinningJob::run() const
{
    const std::size_t n = positions.size();
    const auto& w = *weights;
    if (method == SkinningMethod::Linear) {
        std::vector<Affine> matrices(skinMatrices.size());
        for (std::size_t j = 0; j < skinMatrices.size(); ++j)
            matrices[j] = toAffine(skinMatrices[j]);
        const Affine* const joints = matrices.data();
        const std::uint32_t* const offsets = w.offsets.data();
        const model::Influence* const influences = w.influences.data();
        const glm::vec3* const in = positions.data();
        const glm::vec3* const inNormals = normals.empty() ? nullptr : normals.data();
        glm::vec3* const out = outPositions.data();
        glm::vec3* const outN = outNormals.data();
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 8192), [=](const tbb::blocked_range<std::size_t>& range) {
            skinLinear(range.begin(), range.end(), joints, offsets, influences, in, inNormals, out, outN);
        });
        return;
    }
    std::vector<DualQuat> quats(skinMatrices.size());
    for (std::size_t j = 0; j < skinMatrices.size(); ++j)
        quats[j] = toDualQuat(skinMatrices[j]);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 2048), [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t v = range.begin(); v != range.end(); ++v) {
            glm::quat real(0, 0, 0, 0), dual(0, 0, 0, 0);
            const glm::quat* pivot = nullptr;
            for (std::uint32_t i = w.offsets[v]; i < w.offsets[v + 1]; ++i) {
                const DualQuat& dq = quats[w.influences[i].joint];
                if (!pivot)
                    pivot = &dq.real;
                // Antipodality: blend every rotation in the same hemisphere as the first.
                const float s = w.influences[i].weight * (glm::dot(*pivot, dq.real) < 0.0f ? -1.0f : 1.0f);
                real = real + s * dq.real;
                dual = dual + s * dq.dual;
            }
            const float length = glm::length(real);
            if (!(length > 1e-12f)) {
                outPositions[v] = positions[v];
                if (!normals.empty())
                    outNormals[v] = normals[v];
                continue;
            }
            real = real / length;
            dual = dual / length;
            const glm::quat t = 2.0f * dual * glm::conjugate(real);
            outPositions[v] = real * positions[v] + glm::vec3(t.x, t.y, t.z);
            if (!normals.empty())
                outNormals[v] = real * normals[v];
        }
    });
}

} // namespace rs::skin
