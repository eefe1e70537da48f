#pragma once
// A triangle mesh bound to an export skeleton (linear blend skinning), as the
// exporters write it: positions and normals in bind pose, world space, metres
// Y-up; each vertex has any number of (joint, weight) influences, stored
// compressed (vertex v's are influences[influenceStart[v] .. influenceStart[v+1])).
// Engines want at most four per vertex summing to one: checkInfluences reports
// what breaks that, limitInfluences is the safe fix (keeps the largest four,
// renormalises).
//
// A character's bound meshes come from io/CharacterExport.h (with UVs and a
// material); proxyMesh binds a generated mesh, a tube along every bone, so a
// rig without a character still has real skinning to carry (tests, bench).
#include "base/Diagnostic.h"
#include "model/Skeleton.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace rs::io {

struct Influence {
    int joint = 0;      // index into the skeleton's joints
    float weight = 0.f;
};

struct SkinnedMesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;            // empty or one per position, unit length
    std::vector<glm::vec2> uvs;                // empty or one per position; as imported (OpenGL: v up from the bottom)
    int material = -1;                         // into ExportScene::materials; -1: none
    std::vector<std::uint32_t> indices;        // triangles
    std::vector<std::uint32_t> influenceStart; // positions.size() + 1 entries
    std::vector<Influence> influences;

    std::size_t vertexCount() const { return positions.size(); }
    std::size_t influenceCount(std::size_t vertex) const { return influenceStart[vertex + 1] - influenceStart[vertex]; }
    const Influence* influencesOf(std::size_t vertex) const { return influences.data() + influenceStart[vertex]; }
};

constexpr int kMaxInfluences = 4;
constexpr double kWeightTolerance = 1e-4;

// Tubes (16 sides) along every bone from a joint to each child, about
// `targetVertices` vertices in all. Weights: the bone's joint, blending into the
// parent joint over the first half and into the child over the second (at most
// two influences, normalised).
SkinnedMesh proxyMesh(const model::Skeleton& skeleton, std::size_t targetVertices);

// Errors, one per kind of problem and mesh (counting the vertices, naming the
// first), subject = the mesh name: broken layout (index or influence arrays out
// of range), joints that are not in the skeleton, negative or non-finite
// weights, vertices without weight, more than kMaxInfluences influences,
// weights that do not sum to 1 within kWeightTolerance.
Diagnostics checkInfluences(const SkinnedMesh& mesh, const model::Skeleton& skeleton);
// Keeps each vertex's `maxInfluences` largest positive weights and normalises
// them. Vertices without any weight keep none (checkInfluences still reports them).
SkinnedMesh limitInfluences(SkinnedMesh mesh, int maxInfluences = kMaxInfluences);

} // namespace rs::io
