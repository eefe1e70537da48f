#include "Renderer.h"

#include <epoxy/gl.h>

#include <vector>

namespace rs::viewport {

namespace {

const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 color;
uniform mat4 viewProjection;
uniform float pointSize;
out vec3 vertexColor;
void main() {
    gl_Position = viewProjection * vec4(position, 1.0);
    gl_PointSize = pointSize;
    vertexColor = color;
}
)";

const char* kFragmentShader = R"(#version 330 core
in vec3 vertexColor;
uniform bool roundPoints;
uniform float alpha;
out vec4 fragmentColor;
void main() {
    if (roundPoints && length(gl_PointCoord - vec2(0.5)) > 0.5)
        discard;
    fragmentColor = vec4(vertexColor, alpha);
}
)";

struct Vertex {
    float x, y, z, r, g, b;
};

void push(std::vector<Vertex>& out, const glm::dvec3& p, const glm::dvec3& c)
{
    out.push_back({float(p.x), float(p.y), float(p.z), float(c.x), float(c.y), float(c.z)});
}

GLuint compile(GLenum type, const char* source, std::string& error)
{
    GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024];
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        error = std::string("shader compilation failed: ") + log;
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

const glm::dvec3 kGuideColor(0.95, 0.55, 0.2);
const glm::dvec3 kSelectedColor(1.0, 1.0, 1.0);
const glm::dvec3 kCvColor(0.85, 0.45, 1.0);         // CV mode, as Maya's violet CVs
const glm::dvec3 kSelectedCvColor(1.0, 0.95, 0.2);
const glm::dvec3 kSkinColor(0.3, 0.9, 0.9);
const glm::dvec3 kReferenceColor(0.55, 0.6, 0.7);

} // namespace

struct Renderer::GlState {
    GLuint program = 0, vao = 0, vbo = 0;
    GLint viewProjection = -1, pointSize = -1, roundPoints = -1, alpha = -1;
};

Renderer::Renderer() = default;
Renderer::~Renderer() = default; // GL objects need a context: call release() first

bool Renderer::isInitialized() const { return m_gl && m_gl->program; }

bool Renderer::initialize(std::string& error)
{
    if (epoxy_gl_version() < 33) {
        error = "OpenGL 3.3 core is required, the context offers " + std::to_string(epoxy_gl_version() / 10) + "." +
                std::to_string(epoxy_gl_version() % 10);
        return false;
    }
    auto gl = std::make_unique<GlState>();
    const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader, error);
    const GLuint fs = vs ? compile(GL_FRAGMENT_SHADER, kFragmentShader, error) : 0;
    if (!vs || !fs)
        return false;
    gl->program = glCreateProgram();
    glAttachShader(gl->program, vs);
    glAttachShader(gl->program, fs);
    glLinkProgram(gl->program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(gl->program, GL_LINK_STATUS, &ok);
    if (!ok) {
        error = "shader link failed";
        glDeleteProgram(gl->program);
        return false;
    }
    gl->viewProjection = glGetUniformLocation(gl->program, "viewProjection");
    gl->pointSize = glGetUniformLocation(gl->program, "pointSize");
    gl->roundPoints = glGetUniformLocation(gl->program, "roundPoints");
    gl->alpha = glGetUniformLocation(gl->program, "alpha");
    glGenVertexArrays(1, &gl->vao);
    glGenBuffers(1, &gl->vbo);
    glBindVertexArray(gl->vao);
    glBindBuffer(GL_ARRAY_BUFFER, gl->vbo);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(3 * sizeof(float)));
    glBindVertexArray(0);
    m_gl = std::move(gl);
    return true;
}

void Renderer::release()
{
    if (!m_gl)
        return;
    glDeleteBuffers(1, &m_gl->vbo);
    glDeleteVertexArrays(1, &m_gl->vao);
    glDeleteProgram(m_gl->program);
    m_gl.reset();
}

void Renderer::render(const Scene& scene, const Camera& camera, int width, int height)
{
    glViewport(0, 0, width, height);
    glClearColor(0.16f, 0.17f, 0.19f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!isInitialized() || width <= 0 || height <= 0)
        return;

    // Batches: lines drawn with depth, then points and curves on top.
    std::vector<Vertex> grid, lines, guidePoints, skinPoints;
    const int half = 10;
    for (int i = -half; i <= half; ++i) {
        const double v = i * 0.25;
        const glm::dvec3 c = i == 0 ? glm::dvec3(0.45) : glm::dvec3(0.27);
        push(grid, {v, 0, -half * 0.25}, i == 0 ? glm::dvec3(0.3, 0.3, 0.8) : c);
        push(grid, {v, 0, half * 0.25}, i == 0 ? glm::dvec3(0.3, 0.3, 0.8) : c);
        push(grid, {-half * 0.25, 0, v}, i == 0 ? glm::dvec3(0.8, 0.3, 0.3) : c);
        push(grid, {half * 0.25, 0, v}, i == 0 ? glm::dvec3(0.8, 0.3, 0.3) : c);
    }
    if (scene.showGuides)
        for (const auto& j : scene.guideJoints) {
            const glm::dvec3 c = j.selected ? kSelectedColor : kGuideColor;
            if (j.hasParent) {
                push(lines, j.parentPosition, c * 0.8);
                push(lines, j.position, c * 0.8);
            }
            push(guidePoints, j.position, c);
        }
    std::vector<Vertex> mirrorPoints;
    if (scene.showGuides)
        for (const auto& j : scene.mirrorJoints) {
            if (j.hasParent) {
                push(lines, j.parentPosition, kGuideColor * 0.4);
                push(lines, j.position, kGuideColor * 0.4);
            }
            push(mirrorPoints, j.position, kGuideColor * 0.5);
        }
    std::vector<Vertex> reference;
    for (const glm::vec3& p : scene.reference)
        push(reference, glm::dvec3(p), kReferenceColor);
    for (const auto& j : scene.skinJoints) {
        if (j.hasParent) {
            push(lines, j.parentPosition, kSkinColor * 0.6);
            push(lines, j.position, kSkinColor * 0.6);
        }
        push(skinPoints, j.position, kSkinColor);
    }
    std::vector<Vertex> curves;
    for (const auto& c : scene.curves)
        for (std::size_t i = 1; i < c.points.size(); ++i) {
            const glm::dvec3 color = c.selected ? kSelectedColor : c.color;
            push(curves, c.points[i - 1], color);
            push(curves, c.points[i], color);
        }

    std::vector<Vertex> hulls, cvPoints;
    for (const auto& h : scene.hulls)
        for (std::size_t i = 1; i < h.points.size(); ++i) {
            push(hulls, h.points[i - 1], h.color);
            push(hulls, h.points[i], h.color);
        }
    for (bool selected : {false, true}) // selected on top of unselected CVs at the same place
        for (const auto& cv : scene.cvs)
            if (cv.selected == selected) push(cvPoints, cv.position, selected ? kSelectedCvColor : kCvColor);

    glUseProgram(m_gl->program);
    const glm::mat4 viewProjection(camera.projectionMatrix(double(width) / height) * camera.viewMatrix());
    glUniformMatrix4fv(m_gl->viewProjection, 1, GL_FALSE, &viewProjection[0][0]);
    glBindVertexArray(m_gl->vao);
    glBindBuffer(GL_ARRAY_BUFFER, m_gl->vbo);
    glEnable(GL_PROGRAM_POINT_SIZE);
    auto draw = [&](const std::vector<Vertex>& v, GLenum mode, float pointSize) {
        if (v.empty())
            return;
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(Vertex)), v.data(), GL_STREAM_DRAW);
        glUniform1f(m_gl->pointSize, pointSize);
        glUniform1i(m_gl->roundPoints, mode == GL_POINTS);
        glDrawArrays(mode, 0, GLsizei(v.size()));
    };
    glUniform1f(m_gl->alpha, 1.0f);
    glEnable(GL_DEPTH_TEST);
    draw(grid, GL_LINES, 1.0f);
    if (!reference.empty()) { // see-through: guides stay visible inside the model
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
        glUniform1f(m_gl->alpha, 0.12f);
        draw(reference, GL_TRIANGLES, 1.0f);
        glUniform1f(m_gl->alpha, 1.0f);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }
    glDisable(GL_DEPTH_TEST); // rig elements stay visible through each other, as in a DCC's X-ray mode
    draw(lines, GL_LINES, 1.0f);
    draw(curves, GL_LINES, 1.0f);
    draw(skinPoints, GL_POINTS, 6.0f);
    draw(mirrorPoints, GL_POINTS, 7.0f);
    draw(guidePoints, GL_POINTS, 10.0f);
    draw(hulls, GL_LINES, 1.0f);
    draw(cvPoints, GL_POINTS, 8.0f);
    std::vector<Vertex> overlay;
    for (const auto& c : scene.overlay)
        for (std::size_t i = 1; i < c.points.size(); ++i) {
            push(overlay, c.points[i - 1], c.color);
            push(overlay, c.points[i], c.color);
        }
    glLineWidth(2.0f); // core profiles may clamp this to 1; the gizmo colours still stand out
    draw(overlay, GL_LINES, 1.0f);
    glLineWidth(1.0f);
    glBindVertexArray(0);
    glUseProgram(0);
}

} // namespace rs::viewport
