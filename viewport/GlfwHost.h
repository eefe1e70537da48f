#pragma once
// Hosts the Renderer in a GLFW window with an OpenGL 3.3 core context: the
// non-Qt way to show a rig (rigsmith-glview) and to render images in tests.
#include "Camera.h"
#include "Scene.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace rs::viewport {

class Renderer;

class GlfwHost {
public:
    // nullptr with `error` set when GLFW, the window or the context fails.
    static std::unique_ptr<GlfwHost> create(int width, int height, const std::string& title, bool visible,
                                            std::string& error);
    ~GlfwHost();

    void render(const Scene& scene, const Camera& camera);
    // The last rendered frame as tightly packed RGB rows, top row first.
    std::vector<std::uint8_t> readPixels() const;
    int width() const { return m_width; }
    // The renderer (its upload counters, for tests).
    const Renderer& renderer() const { return *m_renderer; }
    int height() const { return m_height; }
    // Interactive loop until the window closes: left drag orbits, middle drag
    // pans, wheel zooms, F frames everything.
    void run(const Scene& scene, Camera camera);

private:
    GlfwHost() = default;
    GLFWwindow* m_window = nullptr;
    std::unique_ptr<Renderer> m_renderer;
    int m_width = 0, m_height = 0;
};

} // namespace rs::viewport
