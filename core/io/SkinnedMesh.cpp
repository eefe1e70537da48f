#include "io/SkinnedMesh.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rs::io {

namespace {

constexpr int kTubeSides = 16;

struct Bone {
    int joint = 0;
    int child = 0;
};

// A bone from each joint to each child, once per place (blend joints share
// their place with the joint they blend).
std::vector<Bone> bonesOf(const model::Skeleton& skeleton)
{
    std::vector<Bone> bones;
    for (std::size_t c = 0; c < skeleton.joints.size(); ++c) {
        const int j = skeleton.joints[c].parent;
        if (j < 0)
            continue;
        const Vec3 a = translationOf(skeleton.joints[std::size_t(j)].bindWorld);
        const Vec3 b = translationOf(skeleton.joints[c].bindWorld);
        const bool seen = std::any_of(bones.begin(), bones.end(), [&](const Bone& other) {
            return other.joint == j && glm::length(translationOf(skeleton.joints[std::size_t(other.child)].bindWorld) - b) < 1e-6;
        });
        if (glm::length(b - a) > 1e-6 && !seen)
            bones.push_back({j, int(c)});
    }
    return bones;
}

glm::vec3 perpendicular(const glm::vec3& d)
{
    const glm::vec3 axis = std::abs(d.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    return glm::normalize(glm::cross(d, axis));
}

// Weights along a bone at parameter t in [0, 1] (see proxyMesh).
void appendBoneWeights(SkinnedMesh& mesh, const model::Skeleton& skeleton, const Bone& bone, float t)
{
    const int parent = skeleton.joints[std::size_t(bone.joint)].parent;
    auto add = [&](int joint, float weight) {
        if (weight > 0.f)
            mesh.influences.push_back({joint, weight});
    };
    if (t < 0.5f && parent >= 0) {
        add(bone.joint, 0.5f + t);
        add(parent, 0.5f - t);
    } else if (t < 0.5f) {
        add(bone.joint, 1.f);
    } else {
        add(bone.joint, 1.5f - t);
        add(bone.child, t - 0.5f);
    }
    mesh.influenceStart.push_back(std::uint32_t(mesh.influences.size()));
}

void appendTube(SkinnedMesh& mesh, const model::Skeleton& skeleton, const Bone& bone, int rings)
{
    const glm::vec3 a(translationOf(skeleton.joints[std::size_t(bone.joint)].bindWorld));
    const glm::vec3 b(translationOf(skeleton.joints[std::size_t(bone.child)].bindWorld));
    const float length = glm::length(b - a);
    const glm::vec3 d = (b - a) / length;
    const glm::vec3 u = perpendicular(d);
    const glm::vec3 v = glm::cross(d, u);
    const float radius = std::clamp(0.12f * length, 0.005f, 0.08f);
    const auto first = std::uint32_t(mesh.positions.size());
    for (int r = 0; r < rings; ++r) {
        const float t = float(r) / float(rings - 1);
        for (int s = 0; s < kTubeSides; ++s) {
            const float angle = 2.f * std::numbers::pi_v<float> * float(s) / kTubeSides;
            const glm::vec3 n = std::cos(angle) * u + std::sin(angle) * v;
            mesh.positions.push_back(a + d * (length * t) + radius * n);
            mesh.normals.push_back(n);
            appendBoneWeights(mesh, skeleton, bone, t);
        }
    }
    for (int r = 0; r + 1 < rings; ++r)
        for (int s = 0; s < kTubeSides; ++s) {
            const std::uint32_t i0 = first + std::uint32_t(r * kTubeSides + s);
            const std::uint32_t i1 = first + std::uint32_t(r * kTubeSides + (s + 1) % kTubeSides);
            const std::uint32_t j0 = i0 + kTubeSides, j1 = i1 + kTubeSides;
            mesh.indices.insert(mesh.indices.end(), {i0, i1, j1, i0, j1, j0});
        }
}

std::string vertexText(std::size_t count, std::size_t first, const std::string& what)
{
    return std::to_string(count) + (count == 1 ? " vertex " : " vertices ") + what + " (first: vertex " +
           std::to_string(first) + ")";
}

} // namespace

SkinnedMesh proxyMesh(const model::Skeleton& skeleton, std::size_t targetVertices)
{
    SkinnedMesh mesh;
    mesh.name = "proxy";
    mesh.influenceStart.push_back(0);
    const auto bones = bonesOf(skeleton);
    if (bones.empty())
        return mesh;
    const double perBone = std::min(double(targetVertices) / double(bones.size() * kTubeSides), 1e6); // int-safe
    const int rings = std::max(2, int(std::lround(perBone)));
    mesh.positions.reserve(bones.size() * std::size_t(rings * kTubeSides));
    for (const Bone& bone : bones)
        appendTube(mesh, skeleton, bone, rings);
    return mesh;
}

Diagnostics checkInfluences(const SkinnedMesh& mesh, const model::Skeleton& skeleton)
{
    auto error = [&](std::string message) {
        Diagnostic d = makeError({}, "mesh " + mesh.name + ": " + std::move(message));
        d.subject = Subject::ofMesh(mesh.name);
        return d;
    };
    const std::size_t n = mesh.vertexCount();
    if (mesh.influenceStart.size() != n + 1 || mesh.influenceStart.back() != mesh.influences.size() ||
        (!mesh.normals.empty() && mesh.normals.size() != n) || (!mesh.uvs.empty() && mesh.uvs.size() != n) ||
        mesh.indices.size() % 3 != 0)
        return {error("its vertex, normal, UV, triangle and influence arrays do not match")};
    for (std::uint32_t index : mesh.indices)
        if (index >= n)
            return {error("a triangle uses vertex " + std::to_string(index) + ", past its " + std::to_string(n) + " vertices")};

    struct Count {
        std::size_t count = 0, first = 0;
        void add(std::size_t vertex) { first = count++ ? first : vertex; }
    } badJoint, badWeight, unweighted, tooMany, unnormalised;
    const int joints = int(skeleton.joints.size());
    for (std::size_t v = 0; v < n; ++v) {
        double sum = 0.0;
        bool jointOk = true, weightOk = true;
        for (std::size_t k = 0; k < mesh.influenceCount(v); ++k) {
            const Influence& in = mesh.influencesOf(v)[k];
            jointOk = jointOk && in.joint >= 0 && in.joint < joints;
            weightOk = weightOk && std::isfinite(in.weight) && in.weight >= 0.f;
            sum += in.weight;
        }
        if (!jointOk) badJoint.add(v);
        if (!weightOk) badWeight.add(v);
        if (sum <= 0.0 && weightOk) unweighted.add(v);
        if (mesh.influenceCount(v) > kMaxInfluences) tooMany.add(v);
        if (weightOk && sum > 0.0 && std::abs(sum - 1.0) > kWeightTolerance) unnormalised.add(v);
    }
    Diagnostics out;
    auto report = [&](const Count& c, const std::string& what) {
        if (c.count)
            out.push_back(error(vertexText(c.count, c.first, what)));
    };
    report(badJoint, "bound to joints that are not in the export skeleton");
    report(badWeight, "with negative or non-finite weights");
    report(unweighted, "without any weight (they would stay behind)");
    report(tooMany, "with more than " + std::to_string(kMaxInfluences) + " influences (fix: keep the largest and renormalise)");
    report(unnormalised, "whose weights do not sum to 1 (fix: normalise)");
    return out;
}

SkinnedMesh limitInfluences(SkinnedMesh mesh, int maxInfluences)
{
    std::vector<Influence> kept;
    std::vector<std::uint32_t> start{0};
    kept.reserve(mesh.influences.size());
    std::vector<Influence> vertex;
    for (std::size_t v = 0; v + 1 < mesh.influenceStart.size(); ++v) {
        vertex.assign(mesh.influencesOf(v), mesh.influencesOf(v) + mesh.influenceCount(v));
        std::erase_if(vertex, [](const Influence& in) { return !(in.weight > 0.f) || !std::isfinite(in.weight); });
        std::stable_sort(vertex.begin(), vertex.end(), [](const Influence& a, const Influence& b) { return a.weight > b.weight; });
        if (vertex.size() > std::size_t(maxInfluences))
            vertex.resize(std::size_t(maxInfluences));
        double sum = 0.0;
        for (const Influence& in : vertex)
            sum += in.weight;
        for (Influence in : vertex) {
            in.weight = float(in.weight / sum);
            kept.push_back(in);
        }
        start.push_back(std::uint32_t(kept.size()));
    }
    mesh.influences = std::move(kept);
    mesh.influenceStart = std::move(start);
    return mesh;
}

} // namespace rs::io
