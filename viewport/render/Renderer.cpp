#include "Renderer.h"

#include "GlProgram.h"

#include "MeshRenderer.h"
#include "SceneLayers.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
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

std::vector<Vertex> gridVertices();

void push(std::vector<Vertex>& out, const glm::dvec3& p, const glm::dvec3& c)
{
    out.push_back({float(p.x), float(p.y), float(p.z), float(c.x), float(c.y), float(c.z)});
}

const glm::dvec3 kSelectedCvColor(1.0, 0.95, 0.2); // weight painting's selected vertices

} // namespace

// What is drawn, each in its own persistent vertex buffer: the grid is
// uploaded once, the reference model when the model changes, the scene's
// layers when the scene changes (not when only the camera moves; of a change
// that names its instances, Scene::delta, only their vertices), the gizmo (a
// few hundred vertices) every frame.
enum Layer { Grid, Lines, Curves, SkinPoints, MirrorPoints, GuidePoints, Hulls, CvPoints, Overlay, OverlayPoints, kLayerCount };
constexpr Layer layerOf(SceneLayer layer) { return Layer(int(Lines) + int(layer)); }
static_assert(int(CvPoints) - int(Lines) + 1 == kSceneLayerCount);

struct Renderer::GlState {
    GLuint program = 0;
    GLint viewProjection = -1, pointSize = -1, roundPoints = -1, alpha = -1;
    struct Buffer {
        GLuint vao = 0, vbo = 0;
        GLsizei count = 0;
    };
    Buffer buffers[kLayerCount];
    // What each scene layer's buffer holds: its vertices and each owner's range.
    struct Resident {
        std::vector<Vertex> vertices;
        std::vector<model::InstanceId> owners;
        std::vector<std::size_t> offsets, counts;
    };
    Resident resident[kSceneLayerCount];
    static constexpr std::uint64_t kNothing = ~std::uint64_t(0);
    std::uint64_t sceneRevision = kNothing;         // what the scene layers hold
    std::uint64_t uploads = 0;                      // vertex uploads so far (tests, measurements)
    std::uint64_t sceneUploads = 0;                 // of them, the scene layers'

    void makeResident(SceneLayer layer, LayerBlocks blocks)
    {
        Resident& r = resident[layer];
        r = {};
        for (std::size_t i = 0; i < blocks.owners.size(); ++i) {
            r.owners.push_back(blocks.owners[i]);
            r.offsets.push_back(r.vertices.size());
            r.counts.push_back(blocks.blocks[i].size());
            r.vertices.insert(r.vertices.end(), blocks.blocks[i].begin(), blocks.blocks[i].end());
        }
        upload(layerOf(layer), r.vertices);
        sceneUploads += r.vertices.size();
    }
    // The blocks of `changed` owners replace theirs: in place when every size
    // is kept (glBufferSubData of those ranges), else the layer is sent again.
    void update(SceneLayer layer, LayerBlocks blocks, const std::vector<model::InstanceId>& changed)
    {
        Resident& r = resident[layer];
        auto newBlock = [&](model::InstanceId owner) -> const std::vector<Vertex>* {
            const auto it = std::find(blocks.owners.begin(), blocks.owners.end(), owner);
            return it == blocks.owners.end() ? nullptr : &blocks.blocks[std::size_t(it - blocks.owners.begin())];
        };
        bool inPlace = true;
        for (model::InstanceId owner : changed) {
            const auto it = std::find(r.owners.begin(), r.owners.end(), owner);
            const std::size_t before = it == r.owners.end() ? 0 : r.counts[std::size_t(it - r.owners.begin())];
            const auto* now = newBlock(owner);
            inPlace = inPlace && before == (now ? now->size() : 0) && (before > 0 || !now);
        }
        if (!inPlace) {
            LayerBlocks merged; // the kept owners' blocks in their order, the changed ones replaced, new ones last
            for (std::size_t i = 0; i < r.owners.size(); ++i) {
                const model::InstanceId owner = r.owners[i];
                if (!std::binary_search(changed.begin(), changed.end(), owner)) {
                    merged.owners.push_back(owner);
                    merged.blocks.emplace_back(r.vertices.begin() + long(r.offsets[i]),
                                               r.vertices.begin() + long(r.offsets[i] + r.counts[i]));
                } else if (const auto* now = newBlock(owner)) {
                    merged.owners.push_back(owner);
                    merged.blocks.push_back(*now);
                }
            }
            for (std::size_t i = 0; i < blocks.owners.size(); ++i)
                if (std::find(r.owners.begin(), r.owners.end(), blocks.owners[i]) == r.owners.end()) {
                    merged.owners.push_back(blocks.owners[i]);
                    merged.blocks.push_back(std::move(blocks.blocks[i]));
                }
            makeResident(layer, std::move(merged));
            return;
        }
        glBindBuffer(GL_ARRAY_BUFFER, buffers[layerOf(layer)].vbo);
        for (std::size_t i = 0; i < blocks.owners.size(); ++i) {
            const auto it = std::find(r.owners.begin(), r.owners.end(), blocks.owners[i]);
            const std::size_t offset = r.offsets[std::size_t(it - r.owners.begin())];
            const std::vector<Vertex>& block = blocks.blocks[i];
            if (std::equal(block.begin(), block.end(), r.vertices.begin() + long(offset)))
                continue; // the change named it, yet it draws the same (a controller hung below a moved joint)
            std::memcpy(r.vertices.data() + offset, block.data(), block.size() * sizeof(Vertex));
            glBufferSubData(GL_ARRAY_BUFFER, GLintptr(offset * sizeof(Vertex)), GLsizeiptr(block.size() * sizeof(Vertex)),
                            block.data());
            uploads += block.size();
            sceneUploads += block.size();
        }
    }

    void upload(Layer layer, const std::vector<Vertex>& vertices)
    {
        Buffer& b = buffers[layer];
        glBindBuffer(GL_ARRAY_BUFFER, b.vbo);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(),
                     layer == Overlay || layer == OverlayPoints ? GL_STREAM_DRAW : GL_DYNAMIC_DRAW);
        b.count = GLsizei(vertices.size());
        uploads += vertices.size();
    }
};

Renderer::Renderer() : m_meshes(std::make_unique<MeshRenderer>()) {}
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
    gl->program = linkProgram(kVertexShader, kFragmentShader, "scene", error);
    if (!gl->program)
        return false;
    gl->viewProjection = glGetUniformLocation(gl->program, "viewProjection");
    gl->pointSize = glGetUniformLocation(gl->program, "pointSize");
    gl->roundPoints = glGetUniformLocation(gl->program, "roundPoints");
    gl->alpha = glGetUniformLocation(gl->program, "alpha");
    for (auto& b : gl->buffers) {
        glGenVertexArrays(1, &b.vao);
        glGenBuffers(1, &b.vbo);
        glBindVertexArray(b.vao);
        glBindBuffer(GL_ARRAY_BUFFER, b.vbo);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(3 * sizeof(float)));
    }
    glBindVertexArray(0);
    gl->upload(Grid, gridVertices());
    if (!m_meshes->initialize(error))
        return false;
    m_gl = std::move(gl);
    return true;
}

void Renderer::release()
{
    if (!m_gl)
        return;
    for (auto& b : m_gl->buffers) {
        glDeleteBuffers(1, &b.vbo);
        glDeleteVertexArrays(1, &b.vao);
    }
    glDeleteProgram(m_gl->program);
    m_gl.reset();
    m_meshes->release();
}

std::uint64_t Renderer::verticesUploaded() const { return m_gl ? m_gl->uploads : 0; }
std::uint64_t Renderer::sceneVerticesUploaded() const { return m_gl ? m_gl->sceneUploads : 0; }
std::uint64_t Renderer::sceneRevision() const { return m_gl && m_gl->sceneRevision != GlState::kNothing ? m_gl->sceneRevision : 0; }
std::size_t Renderer::vertexSize() { return sizeof(Vertex); }
std::uint64_t Renderer::meshVerticesUploaded() const { return m_meshes->vertexUploads(); }
std::uint64_t Renderer::weightVerticesUploaded() const { return m_meshes->weightUploads(); }
std::vector<std::string> Renderer::takeWarnings() { return m_meshes->takeWarnings(); }

namespace {

std::vector<Vertex> gridVertices()
{
    std::vector<Vertex> grid;
    const int half = 10;
    for (int i = -half; i <= half; ++i) {
        const double v = i * 0.25;
        const glm::dvec3 c = i == 0 ? glm::dvec3(0.45) : glm::dvec3(0.27);
        push(grid, {v, 0, -half * 0.25}, i == 0 ? glm::dvec3(0.3, 0.3, 0.8) : c);
        push(grid, {v, 0, half * 0.25}, i == 0 ? glm::dvec3(0.3, 0.3, 0.8) : c);
        push(grid, {-half * 0.25, 0, v}, i == 0 ? glm::dvec3(0.8, 0.3, 0.3) : c);
        push(grid, {half * 0.25, 0, v}, i == 0 ? glm::dvec3(0.8, 0.3, 0.3) : c);
    }
    return grid;
}

void pushCurves(const std::vector<SceneCurve>& curves, std::vector<Vertex>& out)
{
    for (const auto& c : curves)
        for (std::size_t i = 1; i < c.points.size(); ++i) {
            push(out, c.points[i - 1], c.color);
            push(out, c.points[i], c.color);
        }
}

} // namespace

// The scene's layers, uploaded again only when the scene changed; of a change
// that names its instances, only what those instances own.
void Renderer::uploadScene(const Scene& scene)
{
    const bool incremental = !scene.delta.all && scene.revision != 0 && m_gl->sceneRevision != GlState::kNothing &&
                             m_gl->sceneRevision >= scene.delta.since;
    auto layers = sceneLayers(scene, incremental ? &scene.delta.instances : nullptr);
    for (int layer = 0; layer < kSceneLayerCount; ++layer) {
        if (incremental)
            m_gl->update(SceneLayer(layer), std::move(layers[std::size_t(layer)]), scene.delta.instances);
        else
            m_gl->makeResident(SceneLayer(layer), std::move(layers[std::size_t(layer)]));
    }
    m_gl->sceneRevision = scene.revision;
}

void Renderer::render(const Scene& scene, const Camera& camera, int width, int height)
{
    glViewport(0, 0, width, height);
    glClearColor(0.16f, 0.17f, 0.19f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!isInitialized() || width <= 0 || height <= 0)
        return;
    if (scene.revision != m_gl->sceneRevision || scene.revision == 0) // 0: a scene nobody stamped
        uploadScene(scene);
    std::vector<Vertex> overlay;
    pushCurves(scene.overlay, overlay);
    m_gl->upload(Overlay, overlay);
    std::vector<Vertex> overlayPoints;
    for (const glm::dvec3& p : scene.overlayPoints)
        push(overlayPoints, p, kSelectedCvColor);
    m_gl->upload(OverlayPoints, overlayPoints);
    m_meshes->prepare(scene); // vertices once, weights when they change, the palette every frame

    glUseProgram(m_gl->program);
    const glm::mat4 viewProjection(camera.projectionMatrix(double(width) / height) * camera.viewMatrix());
    glUniformMatrix4fv(m_gl->viewProjection, 1, GL_FALSE, &viewProjection[0][0]);
    glEnable(GL_PROGRAM_POINT_SIZE);
    auto draw = [&](Layer layer, GLenum mode, float pointSize) {
        const GlState::Buffer& b = m_gl->buffers[layer];
        if (b.count == 0)
            return;
        glBindVertexArray(b.vao);
        glUniform1f(m_gl->pointSize, pointSize);
        glUniform1i(m_gl->roundPoints, mode == GL_POINTS);
        glDrawArrays(mode, 0, b.count);
    };
    glUniform1f(m_gl->alpha, 1.0f);
    glEnable(GL_DEPTH_TEST);
    draw(Grid, GL_LINES, 1.0f);
    const glm::mat4 meshViewProjection(viewProjection);
    const glm::vec3 viewDirection(glm::normalize(camera.target - camera.position()));
    m_meshes->draw(scene, meshViewProjection, viewDirection, false); // skinned: opaque
    glUseProgram(m_gl->program);
    const bool seeThroughMeshes = m_meshes->hasSeeThrough(scene);
    if (seeThroughMeshes) { // see-through: guides stay visible inside the model
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
        m_meshes->draw(scene, meshViewProjection, viewDirection, true);
        glUseProgram(m_gl->program);
        glBindVertexArray(0);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }
    glDisable(GL_DEPTH_TEST); // rig elements stay visible through each other, as in a DCC's X-ray mode
    draw(Lines, GL_LINES, 1.0f);
    draw(Curves, GL_LINES, 1.0f);
    draw(SkinPoints, GL_POINTS, 6.0f);
    draw(MirrorPoints, GL_POINTS, 7.0f);
    draw(GuidePoints, GL_POINTS, 10.0f);
    draw(Hulls, GL_LINES, 1.0f);
    draw(CvPoints, GL_POINTS, 8.0f);
    glLineWidth(2.0f); // core profiles may clamp this to 1; the gizmo colours still stand out
    draw(Overlay, GL_LINES, 1.0f);
    glLineWidth(1.0f);
    draw(OverlayPoints, GL_POINTS, 5.0f);
    glBindVertexArray(0);
    glUseProgram(0);
}

} // namespace rs::viewport
