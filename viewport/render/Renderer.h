#pragma once
// OpenGL 3.3 core renderer for a Scene: ground grid, the character's meshes
// (skinned on the GPU, MeshRenderer.h), guide joints and bones, controller
// curves, skin joints. Host-agnostic: the caller (a Qt widget or a
// GLFW window) makes its context current before every call. GL functions come
// from libepoxy, so no GL header leaks out of this library's .cpp files.
#include "../Camera.h"
#include "../Scene.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace rs::viewport {

class MeshRenderer;

class Renderer {
public:
    Renderer();
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Compiles shaders and creates buffers; false with `error` set on failure
    // (for example a context older than 3.3 core).
    bool initialize(std::string& error);
    bool isInitialized() const;
    // Draws into the currently bound framebuffer, `width` x `height` device pixels.
    void render(const Scene& scene, const Camera& camera, int width, int height);
    // Frees GL objects; needs the same context current.
    void release();
    // Vertices sent to the GPU so far: a frame that only moves the camera sends
    // the gizmo's alone (Scene::revision unchanged).
    std::uint64_t verticesUploaded() const;
    // Of them, the scene layers' (joints, bones, curves, CVs): a change naming
    // one instance (Scene::delta) sends only that instance's vertices.
    std::uint64_t sceneVerticesUploaded() const;
    static std::size_t vertexSize(); // bytes per scene vertex (position and colour)
    // The revision of the scene the layers hold (0: none yet).
    std::uint64_t sceneRevision() const;
    // Mesh vertices (positions, normals, UVs) and vertex weights sent so far:
    // a posed frame sends neither, only the palette.
    std::uint64_t meshVerticesUploaded() const;
    std::uint64_t weightVerticesUploaded() const;
    // Problems met while drawing (an unreadable texture), each reported once.
    std::vector<std::string> takeWarnings();

private:
    void uploadScene(const Scene& scene);
    struct GlState;
    std::unique_ptr<GlState> m_gl;
    std::unique_ptr<MeshRenderer> m_meshes;
};

} // namespace rs::viewport
