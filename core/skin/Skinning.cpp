#include "skin/Skinning.h"

#include <glm/gtc/quaternion.hpp>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace rs::skin {

namespace {

// Offsets that start at 0, never decrease and end at the influence count.
Status checkOffsets(std::span<const std::uint32_t> offsets, std::size_t influences)
{
    if (offsets.empty() || offsets.front() != 0 || offsets.back() != influences)
        return Status::refused("skinning: the influence offsets do not match the influences");
    for (std::size_t v = 0; v + 1 < offsets.size(); ++v)
        if (offsets[v + 1] < offsets[v])
            return Status::refused("skinning: the influence offsets of vertex " + std::to_string(v) + " decrease");
    return {};
}

} // namespace

Result<PreparedSkin> PreparedSkin::prepare(const model::MeshWeights& weights)
{
    if (Status status = checkOffsets(weights.offsets, weights.influences.size()); status.failed())
        return Result<PreparedSkin>::failure(status.takeDiagnostics());
    PreparedSkin skin;
    skin.m_vertexCount = weights.vertexCount();
    bool fixed = true;
    for (std::size_t v = 0; v < skin.m_vertexCount; ++v) {
        const std::size_t count = weights.offsets[v + 1] - weights.offsets[v];
        fixed = fixed && count >= 1 && count <= 4;
    }
    for (const model::Influence& influence : weights.influences) {
        skin.m_matrixCount = std::max<std::size_t>(skin.m_matrixCount, std::size_t(influence.joint) + 1);
        fixed = fixed && influence.joint <= std::numeric_limits<std::uint16_t>::max();
    }
    skin.m_fixed = fixed;
    if (!fixed) {
        skin.m_offsets = weights.offsets;
        skin.m_influences = weights.influences;
        return skin;
    }
    skin.m_joints.resize(skin.m_vertexCount);
    skin.m_weights.resize(skin.m_vertexCount);
    for (std::size_t v = 0; v < skin.m_vertexCount; ++v) {
        const model::Influence* first = weights.begin(v);
        const std::size_t count = std::size_t(weights.end(v) - first);
        for (std::size_t k = 0; k < 4; ++k) {
            // A missing influence: nothing from the vertex's own first joint,
            // so the dual-quaternion pivot and any NaN stay as in the general loops.
            const model::Influence& influence = k < count ? first[k] : first[0];
            skin.m_joints[v][k] = std::uint16_t(influence.joint);
            skin.m_weights[v][k] = k < count ? influence.weight : 0.0f;
        }
    }
    return skin;
}

Status SkinningJob::validate() const
{
    if (!prepared && !weights)
        return Status::refused("skinning: no weights");
    const std::size_t vertices = prepared ? prepared->vertexCount() : weights->vertexCount();
    if (vertices != positions.size())
        return Status::refused("skinning: " + std::to_string(vertices) + " weighted vertices for a mesh of " +
                               std::to_string(positions.size()));
    if (outPositions.size() != positions.size())
        return Status::refused("skinning: the output holds " + std::to_string(outPositions.size()) + " positions, not " +
                               std::to_string(positions.size()));
    if (!normals.empty() && (normals.size() != positions.size() || outNormals.size() != positions.size()))
        return Status::refused("skinning: normals and their output must have one entry per vertex");
    if (prepared) {
        if (skinMatrices.size() < prepared->matrixCount())
            return Status::refused("skinning: " + std::to_string(skinMatrices.size()) + " joint matrices; the weights name joint " +
                                   std::to_string(prepared->matrixCount() - 1));
        return {};
    }
    if (skinMatrices.size() < weights->joints.size())
        return Status::refused("skinning: " + std::to_string(skinMatrices.size()) + " joint matrices for " +
                               std::to_string(weights->joints.size()) + " joints");
    if (Status status = checkOffsets(weights->offsets, weights->influences.size()); status.failed())
        return status;
    for (const model::Influence& influence : weights->influences)
        if (influence.joint >= skinMatrices.size())
            return Status::refused("skinning: an influence names joint " + std::to_string(influence.joint) + " of " +
                                   std::to_string(skinMatrices.size()));
    return {};
}

namespace {

// The hot loops are compiled twice (x86-64-v3: AVX2 + FMA, where the CPU has
// them; plain x86-64 otherwise) and picked at load time, so the build stays
// portable. Not "arch=haswell": GCC picks that clone only on a CPU that *is* a
// Haswell (__builtin_cpu_is), so every later CPU ran the plain one.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
#define RS_SKIN_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define RS_SKIN_CLONES
#endif

// GCC/Clang vector types: one AVX register, or two SSE ones in the default clone.
typedef float Float8 __attribute__((vector_size(32)));
typedef float Float4 __attribute__((vector_size(16)));

// A skin matrix for the fast linear loop: its columns (x, y, z, 0) in two
// halves, so blending four of them is eight multiply-adds.
struct alignas(32) Columns {
    Float8 c01, c23;
};

Columns toColumns(const Mat4& m)
{
    float columns[16];
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 3; ++r)
            columns[c * 4 + r] = float(m[c][r]);
        columns[c * 4 + 3] = 0.0f;
    }
    Columns out;
    std::memcpy(&out, columns, sizeof columns);
    return out;
}

// Linear blend skinning of vertices [first, last) in the fixed layout.
RS_SKIN_CLONES
void skinLinearFixed(std::size_t first, std::size_t last, const Columns* matrices, const std::array<std::uint16_t, 4>* joints,
                     const std::array<float, 4>* weights, const glm::vec3* in, const glm::vec3* inNormals, glm::vec3* out,
                     glm::vec3* outN)
{
    for (std::size_t v = first; v != last; ++v) {
        const std::array<std::uint16_t, 4> j = joints[v];
        const std::array<float, 4> w = weights[v];
        Float8 lo = matrices[j[0]].c01 * w[0], hi = matrices[j[0]].c23 * w[0];
        lo += matrices[j[1]].c01 * w[1];
        hi += matrices[j[1]].c23 * w[1];
        lo += matrices[j[2]].c01 * w[2];
        hi += matrices[j[2]].c23 * w[2];
        lo += matrices[j[3]].c01 * w[3];
        hi += matrices[j[3]].c23 * w[3];
        const glm::vec3 p = in[v];
        const Float8 s = lo * Float8{p.x, p.x, p.x, p.x, p.y, p.y, p.y, p.y} + hi * Float8{p.z, p.z, p.z, p.z, 1, 1, 1, 1};
        const Float4 moved = __builtin_shufflevector(s, s, 0, 1, 2, 3) + __builtin_shufflevector(s, s, 4, 5, 6, 7);
        out[v] = glm::vec3(moved[0], moved[1], moved[2]);
        if (inNormals) {
            const glm::vec3 q = inNormals[v];
            const Float8 t = lo * Float8{q.x, q.x, q.x, q.x, q.y, q.y, q.y, q.y} + hi * Float8{q.z, q.z, q.z, q.z, 0, 0, 0, 0};
            const Float4 turned = __builtin_shufflevector(t, t, 0, 1, 2, 3) + __builtin_shufflevector(t, t, 4, 5, 6, 7);
            const float squared = turned[0] * turned[0] + turned[1] * turned[1] + turned[2] * turned[2];
            outN[v] = squared > 0.0f ? glm::vec3(turned[0], turned[1], turned[2]) * (1.0f / std::sqrt(squared)) : q;
        }
    }
}

// 3x4 float matrices (rows), the form the general linear loop reads.
using Affine = std::array<float, 12>;

Affine toAffine(const Mat4& m)
{
    Affine a;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c)
            a[std::size_t(r * 4 + c)] = float(m[c][r]);
    return a;
}

// Linear blend skinning of vertices [first, last), any number of influences.
RS_SKIN_CLONES
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

// A unit dual quaternion: real (x, y, z, w) then dual (x, y, z, w).
struct alignas(32) DualQuat {
    Float8 q;
};

DualQuat toDualQuat(const Mat4& m)
{
    const glm::dmat3 r(m);
    // Scale is not part of a dual quaternion: orthonormalise the rotation.
    const glm::dquat q = glm::normalize(glm::quat_cast(glm::dmat3(glm::normalize(r[0]), glm::normalize(r[1]), glm::normalize(r[2]))));
    const glm::dvec3 t(m[3]);
    const glm::dquat d = 0.5 * glm::dquat(0.0, t.x, t.y, t.z) * q;
    return {Float8{float(q.x), float(q.y), float(q.z), float(q.w), float(d.x), float(d.y), float(d.z), float(d.w)}};
}

float dot4(const Float8& a, const Float8& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]; }

// A blended dual quaternion `b` applied to vertex v: it rotates then
// translates the position and rotates the normal. Normalising it would divide
// both parts by its length; every term below is a product of two parts, so
// dividing once by the squared length does the same without a square root.
inline void applyDualQuat(const Float8& b, std::size_t v, const glm::vec3* in, const glm::vec3* inNormals, glm::vec3* out,
                          glm::vec3* outN)
{
    const float squared = dot4(b, b);
    if (!(squared > 1e-24f)) {
        out[v] = in[v];
        if (inNormals)
            outN[v] = inNormals[v];
        return;
    }
    const float twice = 2.0f / squared;
    const glm::vec3 real(b[0], b[1], b[2]), dual(b[4], b[5], b[6]);
    const float realW = b[3], dualW = b[7];
    // The translation: the vector part of 2 dual conj(real).
    const glm::vec3 t = twice * (realW * dual - dualW * real + glm::cross(real, dual));
    auto rotate = [&](const glm::vec3& p) {
        const glm::vec3 uv = glm::cross(real, p);
        return p + twice * (realW * uv + glm::cross(real, uv));
    };
    out[v] = rotate(in[v]) + t;
    if (inNormals)
        outN[v] = rotate(inNormals[v]);
}

// Dual-quaternion skinning of vertices [first, last) in the fixed layout.
// Antipodality: every rotation is blended in the same hemisphere as the first.
RS_SKIN_CLONES
void skinDualFixed(std::size_t first, std::size_t last, const DualQuat* quats, const std::array<std::uint16_t, 4>* joints,
                   const std::array<float, 4>* weights, const glm::vec3* in, const glm::vec3* inNormals, glm::vec3* out,
                   glm::vec3* outN)
{
    for (std::size_t v = first; v != last; ++v) {
        const std::array<std::uint16_t, 4> j = joints[v];
        const std::array<float, 4> w = weights[v];
        const Float8 pivot = quats[j[0]].q;
        Float8 b = pivot * w[0];
        for (int k = 1; k < 4; ++k) {
            const Float8 q = quats[j[k]].q;
            b += q * (dot4(pivot, q) < 0.0f ? -w[k] : w[k]);
        }
        applyDualQuat(b, v, in, inNormals, out, outN);
    }
}

// Dual-quaternion skinning of vertices [first, last), any number of influences.
RS_SKIN_CLONES
void skinDual(std::size_t first, std::size_t last, const DualQuat* quats, const std::uint32_t* offsets,
              const model::Influence* influences, const glm::vec3* in, const glm::vec3* inNormals, glm::vec3* out,
              glm::vec3* outN)
{
    for (std::size_t v = first; v != last; ++v) {
        Float8 b = {};
        const Float8* pivot = nullptr;
        for (std::uint32_t i = offsets[v]; i < offsets[v + 1]; ++i) {
            const Float8& q = quats[influences[i].joint].q;
            if (!pivot)
                pivot = &q;
            const float s = influences[i].weight;
            b += q * (dot4(*pivot, q) < 0.0f ? -s : s);
        }
        applyDualQuat(b, v, in, inNormals, out, outN);
    }
}

// Vertices per task: a few tasks per core, so a busy core does not hold the rest.
constexpr std::size_t kGrain = 4096;

} // namespace

void SkinningJob::run() const
{
    const std::size_t n = positions.size();
    const glm::vec3* const in = positions.data();
    const glm::vec3* const inNormals = normals.empty() ? nullptr : normals.data();
    glm::vec3* const out = outPositions.data();
    glm::vec3* const outN = outNormals.data();
    const bool fixed = prepared && prepared->hasFixedLayout();
    const auto* const joints = fixed ? prepared->fixedJoints().data() : nullptr;
    const auto* const shares = fixed ? prepared->fixedWeights().data() : nullptr;
    const std::uint32_t* const offsets = fixed ? nullptr : prepared ? prepared->offsets().data() : weights->offsets.data();
    const model::Influence* const influences = fixed ? nullptr : prepared ? prepared->influences().data() : weights->influences.data();
    const tbb::blocked_range<std::size_t> all(0, n, kGrain);
    if (method == SkinningMethod::Linear) {
        if (fixed) {
            std::vector<Columns> matrices(skinMatrices.size());
            for (std::size_t j = 0; j < skinMatrices.size(); ++j)
                matrices[j] = toColumns(skinMatrices[j]);
            const Columns* const m = matrices.data();
            tbb::parallel_for(all, [=](const tbb::blocked_range<std::size_t>& r) {
                skinLinearFixed(r.begin(), r.end(), m, joints, shares, in, inNormals, out, outN);
            });
            return;
        }
        std::vector<Affine> matrices(skinMatrices.size());
        for (std::size_t j = 0; j < skinMatrices.size(); ++j)
            matrices[j] = toAffine(skinMatrices[j]);
        const Affine* const m = matrices.data();
        tbb::parallel_for(all, [=](const tbb::blocked_range<std::size_t>& r) {
            skinLinear(r.begin(), r.end(), m, offsets, influences, in, inNormals, out, outN);
        });
        return;
    }
    std::vector<DualQuat> quats(skinMatrices.size());
    for (std::size_t j = 0; j < skinMatrices.size(); ++j)
        quats[j] = toDualQuat(skinMatrices[j]);
    const DualQuat* const q = quats.data();
    if (fixed)
        tbb::parallel_for(all, [=](const tbb::blocked_range<std::size_t>& r) {
            skinDualFixed(r.begin(), r.end(), q, joints, shares, in, inNormals, out, outN);
        });
    else
        tbb::parallel_for(all, [=](const tbb::blocked_range<std::size_t>& r) {
            skinDual(r.begin(), r.end(), q, offsets, influences, in, inNormals, out, outN);
        });
}

} // namespace rs::skin
