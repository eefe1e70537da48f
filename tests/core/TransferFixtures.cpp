// Synthetic meshes and weights for the skin chunk import tests (TransferFixtures.h).
#include "TransferFixtures.h"

#include "skin/Refit.h"

#include <algorithm>

namespace rs::test::transfer {

// A grid of nx by ny vertices, 1 cm apart, at height z, facing +z (or -z).
model::Mesh grid(const std::string& name, int nx, int ny, float z, bool up, float spacing)
{
    model::Mesh mesh;
    mesh.name = name;
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x)
            mesh.positions.push_back({x * spacing, y * spacing, z});
    for (int y = 0; y + 1 < ny; ++y)
        for (int x = 0; x + 1 < nx; ++x) {
            const std::uint32_t a = std::uint32_t(y * nx + x), b = a + 1, c = a + std::uint32_t(nx), d = c + 1;
            if (up)
                mesh.indices.insert(mesh.indices.end(), {a, b, c, b, d, c});
            else
                mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
        }
    return mesh;
}

// Three joints along x: the first fades into the second, the second into the third.
model::MeshWeights rampWeights(const model::Mesh& mesh, float width)
{
    model::MeshWeights w;
    w.joints = {{1, "", "skin.a"}, {1, "", "skin.b"}, {1, "", "skin.c"}};
    w.parents = {-1, 0, 1};
    w.offsets.push_back(0);
    for (const glm::vec3& p : mesh.positions) {
        const float t = std::clamp(p.x / width, 0.0f, 1.0f) * 2.0f;
        if (t < 1.0f)
            w.influences.insert(w.influences.end(), {{0, 1.0f - t}, {1, t}});
        else
            w.influences.insert(w.influences.end(), {{1, 2.0f - t}, {2, t - 1.0f}});
        w.offsets.push_back(std::uint32_t(w.influences.size()));
    }
    return w;
}

model::MeshWeights allOn(const model::Mesh& mesh, std::uint32_t joint)
{
    model::MeshWeights w;
    w.joints = {{1, "", "skin.a"}, {1, "", "skin.b"}, {1, "", "skin.c"}};
    w.parents = {-1, 0, 1};
    for (std::uint32_t v = 0; v <= mesh.vertexCount(); ++v)
        w.offsets.push_back(v);
    w.influences.assign(mesh.vertexCount(), {joint, 1.0f});
    return w;
}

// The chunk of a whole mesh in bind pose.
skin::SkinChunk chunkOf(const model::Mesh& mesh, const model::MeshWeights& weights, std::int64_t time)
{
    skin::SkinChunk c = skin::bindingChunk({"", mesh.name, mesh.vertexCount(), model::topologyFingerprint(mesh), weights}, mesh, nullptr);
    c.exportedAtMicroseconds = time; // the merge tests say which is newer
    return c;
}

std::uint32_t dominant(const model::MeshWeights& w, std::size_t v)
{
    return std::max_element(w.begin(v), w.end(v), [](const auto& a, const auto& b) { return a.weight < b.weight; })->joint;
}

} // namespace rs::test::transfer
