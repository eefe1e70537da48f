#include "GlfwHost.h"

#include "render/Renderer.h"

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>

#include <algorithm>

namespace rs::viewport {

std::unique_ptr<GlfwHost> GlfwHost::create(int width, int height, const std::string& title, bool visible,
                                           std::string& error)
{
    if (!glfwInit()) {
        const char* description = nullptr;
        glfwGetError(&description);
        error = std::string("GLFW could not start: ") + (description ? description : "no display?");
        return nullptr;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
    std::unique_ptr<GlfwHost> host(new GlfwHost);
    host->m_window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!host->m_window) {
        const char* description = nullptr;
        glfwGetError(&description);
        error = std::string("no OpenGL 3.3 core window: ") + (description ? description : "unknown error");
        return nullptr;
    }
    glfwMakeContextCurrent(host->m_window);
    glfwGetFramebufferSize(host->m_window, &host->m_width, &host->m_height);
    host->m_renderer = std::make_unique<Renderer>();
    if (!host->m_renderer->initialize(error))
        return nullptr;
    return host;
}

GlfwHost::~GlfwHost()
{
    if (m_window) {
        glfwMakeContextCurrent(m_window);
        if (m_renderer)
            m_renderer->release();
        glfwDestroyWindow(m_window);
    }
}

void GlfwHost::render(const Scene& scene, const Camera& camera)
{
    glfwMakeContextCurrent(m_window);
    glfwGetFramebufferSize(m_window, &m_width, &m_height);
    m_renderer->render(scene, camera, m_width, m_height);
    glFinish();
}

std::vector<std::uint8_t> GlfwHost::readPixels() const
{
    std::vector<std::uint8_t> rows(std::size_t(m_width) * std::size_t(m_height) * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, m_width, m_height, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
    std::vector<std::uint8_t> flipped(rows.size());
    const std::size_t stride = std::size_t(m_width) * 3;
    for (int y = 0; y < m_height; ++y)
        std::copy_n(rows.begin() + std::ptrdiff_t(std::size_t(y) * stride), stride,
                    flipped.begin() + std::ptrdiff_t(std::size_t(m_height - 1 - y) * stride));
    return flipped;
}

void GlfwHost::run(const Scene& scene, Camera camera)
{
    glfwShowWindow(m_window);
    double lastX = 0, lastY = 0;
    glfwGetCursorPos(m_window, &lastX, &lastY);
    struct Scroll { double steps = 0; } scroll;
    glfwSetWindowUserPointer(m_window, &scroll);
    glfwSetScrollCallback(m_window, [](GLFWwindow* w, double, double dy) {
        static_cast<Scroll*>(glfwGetWindowUserPointer(w))->steps += dy;
    });
    while (!glfwWindowShouldClose(m_window)) {
        glfwWaitEvents();
        double x = 0, y = 0;
        glfwGetCursorPos(m_window, &x, &y);
        if (glfwGetMouseButton(m_window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS)
            camera.orbit(x - lastX, y - lastY);
        if (glfwGetMouseButton(m_window, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS)
            camera.pan(x - lastX, y - lastY, m_height);
        if (glfwGetKey(m_window, GLFW_KEY_F) == GLFW_PRESS) {
            glm::dvec3 lo, hi;
            if (scene.bounds(lo, hi))
                camera.frame(lo, hi, double(m_width) / std::max(1, m_height));
        }
        camera.dolly(scroll.steps);
        scroll.steps = 0;
        lastX = x;
        lastY = y;
        render(scene, camera);
        glfwSwapBuffers(m_window);
    }
}

} // namespace rs::viewport
