#pragma once
// Draws the character's meshes (Scene::meshes) for the Renderer: skinned on
// the GPU with the scene's palette (linear blend or dual quaternions),
// normals too; shaded with the material's base colour and texture, or with
// the weight display's colours. Private to the viewport's render folder.
//
// What goes to the GPU when: a mesh's vertices (positions, normals, UVs) once
// per (model, mesh); its joint indices and weights (the 4 largest influences
// per vertex, renormalised) once per weights object; a texture once per path;
// the palette (a mat4 per bone, or two quaternions per bone for dual
// quaternions, made on the CPU) every frame, into a texture buffer, so any
// number of bones fits. Nothing is skinned on the CPU.
#include "../Scene.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace rs::viewport {

class MeshRenderer {
public:
    MeshRenderer();
    ~MeshRenderer();
    bool initialize(std::string& error);
    void release();
    // Uploads what changed (see above), then draws. `seeThrough` picks the
    // pass: the opaque (skinned) meshes, or the see-through ones (bind pose)
    // blended over them. `viewDirection`: the camera's, world space.
    void prepare(const Scene& scene);
    void draw(const Scene& scene, const glm::mat4& viewProjection, const glm::vec3& viewDirection, bool seeThrough);
    bool hasSeeThrough(const Scene& scene) const;

    std::uint64_t vertexUploads() const;  // mesh vertices sent so far
    std::uint64_t weightUploads() const;  // vertices whose weights were sent so far
    // Problems met since the last call (a texture that cannot be read), each once.
    std::vector<std::string> takeWarnings();

    // The 4 largest influences of each vertex, renormalised, as the shader
    // takes them (joint indices, weights); vertices without influences get
    // joint 0 with weight 0.
    static void packInfluences(const model::MeshWeights& weights, std::size_t vertexCount,
                               std::vector<std::uint16_t>& joints, std::vector<float>& shares);
    // A rigid transform as a unit dual quaternion (real xyzw, dual xyzw);
    // scale and shear in `m` are dropped.
    static void toDualQuaternion(const glm::mat4& m, glm::vec4& real, glm::vec4& dual);

private:
    struct Gl;
    std::unique_ptr<Gl> m_gl;
};

} // namespace rs::viewport
