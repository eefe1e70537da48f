#pragma once
// A character's meshes as Rigsmith keeps them: triangles in the guide's world
// space (metres, Y-up), in the file's vertex order (stable: weights are stored
// per vertex index), and the skin weights bound to a rig's skin joints.
#include "base/Identity.h"
#include "base/Math.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rs::model {

struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;  // metres, world space
    std::vector<glm::vec3> normals;    // one per position, or none
    std::vector<glm::vec2> uvs;        // one per position, or none
    std::vector<std::uint32_t> indices; // three per triangle, into positions
    int material = -1;                  // into the model's materials; -1: none

    std::size_t vertexCount() const { return positions.size(); }
    std::size_t triangleCount() const { return indices.size() / 3; }
};

// One skin joint's share of a vertex.
struct Influence {
    std::uint32_t joint = 0; // into MeshWeights::joints
    float weight = 0.0f;
};

// Skin weights of one mesh: per vertex, its influences (at most the bind's
// limit, summing to 1), keyed by skin joint identity so a rebuild keeps them.
struct MeshWeights {
    std::vector<NodeKey> joints;          // the skin joints that may influence
    std::vector<std::uint32_t> offsets;   // vertex v's influences: [offsets[v], offsets[v + 1])
    std::vector<Influence> influences;

    std::size_t vertexCount() const { return offsets.empty() ? 0 : offsets.size() - 1; }
    const Influence* begin(std::size_t vertex) const { return influences.data() + offsets[vertex]; }
    const Influence* end(std::size_t vertex) const { return influences.data() + offsets[vertex + 1]; }
};

} // namespace rs::model
