#include "model/Mesh.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace rs::model {

std::uint64_t topologyFingerprint(const Mesh& mesh)
{
    std::uint64_t h = 1469598103934665603ull; // FNV-1a over the vertex count and the triangles
    auto mix = [&](std::uint32_t value) {
        for (int k = 0; k < 4; ++k) {
            h ^= (value >> (8 * k)) & 0xffu;
            h *= 1099511628211ull;
        }
    };
    mix(std::uint32_t(mesh.positions.size()));
    for (std::uint32_t index : mesh.indices)
        mix(index);
    return h;
}

bool bindingFits(const MeshBinding& binding, const Mesh& mesh)
{
    return binding.vertexCount == mesh.vertexCount() && binding.weights.vertexCount() == mesh.vertexCount() &&
           binding.fingerprint == topologyFingerprint(mesh);
}

std::vector<glm::vec3> vertexNormals(const Mesh& mesh, const std::vector<glm::vec3>& positions, glm::vec3 fallback)
{
    std::vector<glm::vec3> normals(positions.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        if (a >= normals.size() || b >= normals.size() || c >= normals.size())
            continue;
        // The cross product's length is twice the area: larger faces count more.
        const glm::vec3 n = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
        normals[a] += n;
        normals[b] += n;
        normals[c] += n;
    }
    for (glm::vec3& n : normals) {
        const float length = glm::length(n);
        n = length > 0.0f && std::isfinite(length) ? n / length : fallback;
    }
    return normals;
}

std::vector<std::vector<int>> pairBindings(const std::vector<std::string>& modelPaths, const std::vector<const Model*>& models,
                                           const std::vector<MeshBinding>& bindings)
{
    std::vector<std::vector<int>> out(models.size());
    std::vector<bool> used(bindings.size(), false);
    for (std::size_t m = 0; m < models.size() && m < modelPaths.size(); ++m) {
        if (!models[m])
            continue;
        for (const Mesh& mesh : models[m]->meshes) {
            int paired = -1;
            for (std::size_t b = 0; b < bindings.size() && paired < 0; ++b)
                if (!used[b] && bindings[b].model == modelPaths[m] && bindings[b].mesh == mesh.name) {
                    used[b] = true;
                    paired = int(b);
                }
            out[m].push_back(paired);
        }
    }
    return out;
}

} // namespace rs::model
