#include "model/Mesh.h"

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

} // namespace rs::model
