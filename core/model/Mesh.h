#pragma once
// A character's meshes as Rigsmith keeps them: triangles in the guide's world
// space (metres, Y-up), in the file's vertex order (stable: weights are stored
// per vertex index), and the skin weights bound to a rig's skin joints.
#include "base/Identity.h"
#include "base/Math.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rs::model {

// One skin joint's share of a vertex.
struct Influence {
    std::uint32_t joint = 0; // into MeshWeights::joints (FileWeights: into Model::joints)
    float weight = 0.0f;
    bool operator==(const Influence&) const = default;
};

// The skin weights a model file brings with a mesh (a skinned glTF, FBX,
// Collada, X...), as io::importModel reads them. Per vertex of the mesh (its
// vertex order), shares of the file's joints, Influence::joint an index into
// Model::joints, largest first, normalised to sum to 1 (files often store sums
// a little off 1); a vertex the file weights on no joint has none. `bones`
// are the joints the file binds this mesh to (including bones that weight no
// vertex), each with its world matrix at this mesh's bind, from the bone's
// offset (inverse bind) matrix, in the guide's space as FileJoint::world.
struct FileWeights {
    struct Bone {
        std::uint32_t joint = 0; // into Model::joints
        Mat4 bindWorld{1.0};
    };
    std::vector<Bone> bones;
    std::vector<std::uint32_t> offsets; // vertex v's influences: [offsets[v], offsets[v + 1]); vertex count + 1 entries
    std::vector<Influence> influences;

    std::size_t vertexCount() const { return offsets.empty() ? 0 : offsets.size() - 1; }
    const Influence* begin(std::size_t vertex) const { return influences.data() + offsets[vertex]; }
    const Influence* end(std::size_t vertex) const { return influences.data() + offsets[vertex + 1]; }
};

struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;  // metres, world space
    std::vector<glm::vec3> normals;    // one per position, or none
    std::vector<glm::vec2> uvs;        // one per position, or none
    std::vector<std::uint32_t> indices; // three per triangle, into positions
    int material = -1;                  // into the model's materials; -1: none
    std::optional<FileWeights> fileWeights; // the file's skin weights (io::importModel); none for a mesh without bones

    std::size_t vertexCount() const { return positions.size(); }
    std::size_t triangleCount() const { return indices.size() / 3; }
};

// Identifies a mesh's vertex count and triangles (not its positions): weights
// stored for a mesh apply 1:1 only while this is unchanged.
std::uint64_t topologyFingerprint(const Mesh& mesh);

// Area-weighted unit vertex normals of `mesh`'s triangles over `positions`
// (its own, or a posed copy of them, one per vertex); a vertex on no triangle
// of positive area gets `fallback`. Triangles with an index out of range are skipped.
std::vector<glm::vec3> vertexNormals(const Mesh& mesh, const std::vector<glm::vec3>& positions, glm::vec3 fallback = {0.0f, 1.0f, 0.0f});
inline std::vector<glm::vec3> vertexNormals(const Mesh& mesh) { return vertexNormals(mesh, mesh.positions); }

// Skin weights of one mesh: per vertex, its influences (at most the bind's
// limit, summing to 1), keyed by skin joint identity so a rebuild keeps them.
struct MeshWeights {
    std::vector<NodeKey> joints;          // the skin joints that may influence
    std::vector<std::int32_t> parents;    // per joint: its skin parent (an index into joints), -1 for a root
    std::vector<std::uint32_t> offsets;   // vertex v's influences: [offsets[v], offsets[v + 1])
    std::vector<Influence> influences;

    std::size_t vertexCount() const { return offsets.empty() ? 0 : offsets.size() - 1; }
    const Influence* begin(std::size_t vertex) const { return influences.data() + offsets[vertex]; }
    const Influence* end(std::size_t vertex) const { return influences.data() + offsets[vertex + 1]; }
    bool operator==(const MeshWeights&) const = default;
};

// The skin weights of one mesh of one of the guide's models. The record keeps
// what it was bound to (the mesh's vertex count and topology fingerprint): when
// the mesh changes, the weights are kept but no longer applied 1:1.
struct MeshBinding {
    std::string model;             // the model file (absolute in memory), as in GuideDocument::models
    std::string mesh;              // the mesh's name in it; same-named meshes pair up in file order
    std::size_t vertexCount = 0;
    std::uint64_t fingerprint = 0; // topologyFingerprint of the mesh as bound
    MeshWeights weights;
    bool operator==(const MeshBinding&) const = default;
};

// True when `binding` applies 1:1 to `mesh` (same vertex count and triangles).
bool bindingFits(const MeshBinding& binding, const Mesh& mesh);

} // namespace rs::model

namespace rs::model {

struct Material {
    std::string name;
    Vec3 baseColor{0.8};
    std::string texture; // base colour texture: a path relative to the model file, "*N" (embedded), or "" (none)
    // The texture's encoded bytes (PNG, JPEG...) when the model file embeds it
    // (GLB, FBX, .zae); null when it is a file beside the model.
    std::shared_ptr<const std::string> image;
};

// A joint of a skeleton the model file brings (a skinned character's own rig):
// parents first, bind pose in the guide's world space.
struct FileJoint {
    std::string name;
    int parent = -1;
    Mat4 world{1.0};
};

// A character model as imported: its meshes (names and vertex order as the file
// has them, transforms applied, metres, Y-up) and materials.
struct Model {
    std::string path;                 // as given
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<FileJoint> joints;    // the file's own skeleton, if it has one
    double metresPerUnit = 1.0;       // the file's unit
    bool zUp = false;                 // the file's up axis was +Z (turned to +Y)
};

// Pairs the meshes of a guide's models with its weight records: the n-th mesh
// of a name in a model with the n-th record of that model (path) and name.
// Per model (null: not read, no meshes), per mesh: a record index or -1.
std::vector<std::vector<int>> pairBindings(const std::vector<std::string>& modelPaths, const std::vector<const Model*>& models,
                                           const std::vector<MeshBinding>& bindings);

} // namespace rs::model
