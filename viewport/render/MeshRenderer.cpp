#include "MeshRenderer.h"

#include "GlProgram.h"
#include "MeshShaders.h"

#include <QImage>

#include <epoxy/gl.h>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <map>

namespace rs::viewport {

namespace {

struct MeshVertex {
    float position[3], normal[3], uv[2];
};
struct MeshInfluence {
    std::uint16_t joints[4];
    float weights[4];
};

} // namespace

struct MeshRenderer::Gl {
    GLuint program = 0;
    GLint viewProjection = -1, palette = -1, skinning = -1, weightDisplay = -1, weightBone = -1, baseColor = -1,
          baseTexture = -1, hasTexture = -1, viewDirection = -1, alpha = -1, weightDisplayFragment = -1;
    GLuint paletteBuffer = 0, paletteTexture = 0;
    struct GpuMesh {
        std::shared_ptr<const model::Model> model; // held: the key's address stays this model's
        std::size_t mesh = 0;
        std::shared_ptr<const model::MeshWeights> weights; // what the influence buffer holds
        bool hasInfluences = false;
        std::shared_ptr<const std::vector<glm::vec3>> colors; // what the colour buffer holds
        bool hasColors = false;
        GLuint vao = 0, vertices = 0, influences = 0, indices = 0, colorBuffer = 0;
        GLsizei indexCount = 0;
        bool used = false;
    };
    std::vector<GpuMesh> meshes;
    std::map<std::string, GLuint> textures; // by absolute path; 0: could not be read (warned once)
    std::vector<std::string> warnings;
    std::uint64_t vertexUploads = 0, weightUploads = 0;

    GpuMesh& meshFor(const SceneMesh& m);
    void uploadWeights(GpuMesh& gpu, const SceneMesh& m);
    void uploadColors(GpuMesh& gpu, const SceneMesh& m);
    GLuint texture(const std::string& path, const std::string* image);
    void free(GpuMesh& gpu)
    {
        glDeleteBuffers(1, &gpu.vertices);
        glDeleteBuffers(1, &gpu.influences);
        glDeleteBuffers(1, &gpu.indices);
        glDeleteBuffers(1, &gpu.colorBuffer);
        glDeleteVertexArrays(1, &gpu.vao);
    }
};

MeshRenderer::MeshRenderer() = default;
MeshRenderer::~MeshRenderer() = default;

bool MeshRenderer::initialize(std::string& error)
{
    auto gl = std::make_unique<Gl>();
    gl->program = linkProgram(kMeshVertexShader, kMeshFragmentShader, "mesh", error);
    if (!gl->program)
        return false;
    const GLuint p = gl->program;
    gl->viewProjection = glGetUniformLocation(p, "viewProjection");
    gl->palette = glGetUniformLocation(p, "palette");
    gl->skinning = glGetUniformLocation(p, "skinning");
    gl->weightDisplay = glGetUniformLocation(p, "weightDisplay");
    gl->weightBone = glGetUniformLocation(p, "weightBone");
    gl->baseColor = glGetUniformLocation(p, "baseColor");
    gl->baseTexture = glGetUniformLocation(p, "baseTexture");
    gl->hasTexture = glGetUniformLocation(p, "hasTexture");
    gl->viewDirection = glGetUniformLocation(p, "viewDirection");
    gl->alpha = glGetUniformLocation(p, "alpha");
    glGenBuffers(1, &gl->paletteBuffer);
    glGenTextures(1, &gl->paletteTexture);
    glBindBuffer(GL_TEXTURE_BUFFER, gl->paletteBuffer);
    glBufferData(GL_TEXTURE_BUFFER, 16 * sizeof(float), nullptr, GL_STREAM_DRAW);
    glBindTexture(GL_TEXTURE_BUFFER, gl->paletteTexture);
    glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, gl->paletteBuffer);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    m_gl = std::move(gl);
    return true;
}

void MeshRenderer::release()
{
    if (!m_gl)
        return;
    for (auto& mesh : m_gl->meshes)
        m_gl->free(mesh);
    for (auto& [path, texture] : m_gl->textures)
        if (texture)
            glDeleteTextures(1, &texture);
    glDeleteTextures(1, &m_gl->paletteTexture);
    glDeleteBuffers(1, &m_gl->paletteBuffer);
    glDeleteProgram(m_gl->program);
    m_gl.reset();
}

std::uint64_t MeshRenderer::vertexUploads() const { return m_gl ? m_gl->vertexUploads : 0; }
std::uint64_t MeshRenderer::weightUploads() const { return m_gl ? m_gl->weightUploads : 0; }

std::vector<std::string> MeshRenderer::takeWarnings()
{
    std::vector<std::string> out;
    if (m_gl)
        out.swap(m_gl->warnings);
    return out;
}

void MeshRenderer::packInfluences(const model::MeshWeights& weights, std::size_t vertexCount,
                                  std::vector<std::uint16_t>& joints, std::vector<float>& shares)
{
    joints.assign(vertexCount * 4, 0);
    shares.assign(vertexCount * 4, 0.0f);
    const std::size_t weighted = std::min(vertexCount, weights.vertexCount());
    std::vector<model::Influence> top;
    for (std::size_t v = 0; v < weighted; ++v) {
        top.assign(weights.begin(v), weights.end(v));
        const std::size_t keep = std::min<std::size_t>(4, top.size());
        std::partial_sort(top.begin(), top.begin() + std::ptrdiff_t(keep), top.end(),
                          [](const model::Influence& a, const model::Influence& b) { return a.weight > b.weight; });
        float total = 0.0f;
        for (std::size_t k = 0; k < keep; ++k)
            total += std::max(0.0f, top[k].weight);
        if (total <= 0.0f)
            continue;
        for (std::size_t k = 0; k < keep; ++k) {
            joints[v * 4 + k] = std::uint16_t(std::min<std::uint32_t>(top[k].joint, 0xffff));
            shares[v * 4 + k] = std::max(0.0f, top[k].weight) / total;
        }
    }
}

void MeshRenderer::toDualQuaternion(const glm::mat4& m, glm::vec4& real, glm::vec4& dual)
{
    glm::mat3 rotation(m);
    for (int c = 0; c < 3; ++c) { // drop scale: dual quaternions are rigid
        const float length = glm::length(rotation[c]);
        if (length > 1e-12f)
            rotation[c] /= length;
    }
    const glm::quat q = glm::normalize(glm::quat_cast(rotation));
    const glm::vec3 t(m[3]);
    const glm::quat d = glm::quat(0.0f, t.x, t.y, t.z) * q * 0.5f;
    real = {q.x, q.y, q.z, q.w};
    dual = {d.x, d.y, d.z, d.w};
}

MeshRenderer::Gl::GpuMesh& MeshRenderer::Gl::meshFor(const SceneMesh& m)
{
    for (GpuMesh& gpu : meshes)
        if (gpu.model == m.model && gpu.mesh == m.mesh)
            return gpu;
    const model::Mesh& mesh = m.data();
    GpuMesh gpu;
    gpu.model = m.model;
    gpu.mesh = m.mesh;
    const std::vector<glm::vec3> computed = mesh.normals.size() == mesh.positions.size() ? std::vector<glm::vec3>{}
                                                                                           : model::vertexNormals(mesh);
    const std::vector<glm::vec3>& normals = computed.empty() ? mesh.normals : computed;
    std::vector<MeshVertex> vertices(mesh.positions.size());
    for (std::size_t v = 0; v < vertices.size(); ++v) {
        const glm::vec3& p = mesh.positions[v];
        const glm::vec3& n = normals[v];
        const glm::vec2 uv = v < mesh.uvs.size() ? mesh.uvs[v] : glm::vec2(0.0f);
        vertices[v] = {{p.x, p.y, p.z}, {n.x, n.y, n.z}, {uv.x, uv.y}};
    }
    std::vector<std::uint32_t> indices;
    indices.reserve(mesh.indices.size());
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) // a bad index drops its triangle, not the draw
        if (mesh.indices[t] < vertices.size() && mesh.indices[t + 1] < vertices.size() && mesh.indices[t + 2] < vertices.size())
            indices.insert(indices.end(), mesh.indices.begin() + std::ptrdiff_t(t), mesh.indices.begin() + std::ptrdiff_t(t + 3));
    glGenVertexArrays(1, &gpu.vao);
    glGenBuffers(1, &gpu.vertices);
    glGenBuffers(1, &gpu.influences);
    glGenBuffers(1, &gpu.indices);
    glGenBuffers(1, &gpu.colorBuffer);
    glBindVertexArray(gpu.vao);
    glBindBuffer(GL_ARRAY_BUFFER, gpu.vertices);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(MeshVertex)), vertices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(MeshVertex), reinterpret_cast<void*>(offsetof(MeshVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(MeshVertex), reinterpret_cast<void*>(offsetof(MeshVertex, normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(MeshVertex), reinterpret_cast<void*>(offsetof(MeshVertex, uv)));
    glBindBuffer(GL_ARRAY_BUFFER, gpu.influences);
    glVertexAttribIPointer(3, 4, GL_UNSIGNED_SHORT, sizeof(MeshInfluence), reinterpret_cast<void*>(offsetof(MeshInfluence, joints)));
    glVertexAttribPointer(4, 4, GL_FLOAT, GL_FALSE, sizeof(MeshInfluence), reinterpret_cast<void*>(offsetof(MeshInfluence, weights)));
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indices);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(std::uint32_t)), indices.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
    gpu.indexCount = GLsizei(indices.size());
    vertexUploads += vertices.size();
    meshes.push_back(std::move(gpu));
    return meshes.back();
}

void MeshRenderer::Gl::uploadWeights(GpuMesh& gpu, const SceneMesh& m)
{
    gpu.weights = m.weights;
    const std::size_t count = m.data().vertexCount();
    gpu.hasInfluences = m.weights && m.weights->vertexCount() == count;
    glBindVertexArray(gpu.vao);
    if (gpu.hasInfluences) {
        std::vector<std::uint16_t> joints;
        std::vector<float> shares;
        packInfluences(*m.weights, count, joints, shares);
        std::vector<MeshInfluence> packed(count);
        for (std::size_t v = 0; v < count; ++v)
            for (int k = 0; k < 4; ++k) {
                packed[v].joints[k] = joints[v * 4 + std::size_t(k)];
                packed[v].weights[k] = shares[v * 4 + std::size_t(k)];
            }
        glBindBuffer(GL_ARRAY_BUFFER, gpu.influences);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(packed.size() * sizeof(MeshInfluence)), packed.data(), GL_STATIC_DRAW);
        glEnableVertexAttribArray(3);
        glEnableVertexAttribArray(4);
        weightUploads += count;
    } else { // the attributes' constant values: no influence
        glDisableVertexAttribArray(3);
        glDisableVertexAttribArray(4);
    }
    glBindVertexArray(0);
}

void MeshRenderer::Gl::uploadColors(GpuMesh& gpu, const SceneMesh& m)
{
    gpu.colors = m.vertexColors;
    gpu.hasColors = m.vertexColors && m.vertexColors->size() == m.data().vertexCount();
    glBindVertexArray(gpu.vao);
    if (gpu.hasColors) {
        glBindBuffer(GL_ARRAY_BUFFER, gpu.colorBuffer);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(m.vertexColors->size() * sizeof(glm::vec3)), m.vertexColors->data(), GL_STATIC_DRAW);
        glVertexAttribPointer(5, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
        glEnableVertexAttribArray(5);
    } else {
        glDisableVertexAttribArray(5);
    }
    glBindVertexArray(0);
}

GLuint MeshRenderer::Gl::texture(const std::string& path, const std::string* encoded)
{
    if (path.empty())
        return 0;
    auto known = textures.find(path);
    if (known != textures.end())
        return known->second;
    GLuint id = 0;
    QImage image;
    if (encoded)
        image.loadFromData(reinterpret_cast<const uchar*>(encoded->data()), int(encoded->size()));
    else
        image.load(QString::fromStdString(path));
    if (image.isNull()) {
        warnings.push_back(path + ": warning: the texture cannot be read; the mesh is drawn in its material's base colour");
    } else {
        // GL's first row is the bottom (UV v = 0, as the model importer keeps it); QImage's is the top.
        image = image.convertToFormat(QImage::Format_RGBA8888).mirrored();
        glGenTextures(1, &id);
        glBindTexture(GL_TEXTURE_2D, id);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width(), image.height(), 0, GL_RGBA, GL_UNSIGNED_BYTE, image.constBits());
        glGenerateMipmap(GL_TEXTURE_2D);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    textures.emplace(path, id);
    return id;
}

void MeshRenderer::prepare(const Scene& scene)
{
    if (!m_gl)
        return;
    for (auto& gpu : m_gl->meshes)
        gpu.used = false;
    for (const SceneMesh& m : scene.meshes) {
        if (!m.model || m.mesh >= m.model->meshes.size())
            continue;
        const bool fresh = std::none_of(m_gl->meshes.begin(), m_gl->meshes.end(),
                                        [&](const Gl::GpuMesh& g) { return g.model == m.model && g.mesh == m.mesh; });
        Gl::GpuMesh& gpu = m_gl->meshFor(m);
        gpu.used = true;
        if (fresh || gpu.weights != m.weights)
            m_gl->uploadWeights(gpu, m);
        if (fresh || gpu.colors != m.vertexColors)
            m_gl->uploadColors(gpu, m);
        m_gl->texture(m.texturePath, m.textureImage.get());
    }
    for (auto& gpu : m_gl->meshes) // a model no longer drawn frees its buffers
        if (!gpu.used)
            m_gl->free(gpu);
    std::erase_if(m_gl->meshes, [](const Gl::GpuMesh& g) { return !g.used; });

    // The palette, every frame: 4 texels per bone (linear) or 2 (dual quaternion).
    std::vector<glm::vec4> texels;
    texels.reserve(scene.palette.size() * 4);
    for (const glm::mat4& m : scene.palette) {
        if (scene.skinning == Skinning::DualQuaternion) {
            glm::vec4 real, dual;
            toDualQuaternion(m, real, dual);
            texels.push_back(real);
            texels.push_back(dual);
        } else {
            for (int c = 0; c < 4; ++c)
                texels.push_back(m[c]);
        }
    }
    if (texels.empty())
        texels.push_back(glm::vec4(0.0f));
    glBindBuffer(GL_TEXTURE_BUFFER, m_gl->paletteBuffer);
    glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(texels.size() * sizeof(glm::vec4)), texels.data(), GL_STREAM_DRAW);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

bool MeshRenderer::hasSeeThrough(const Scene& scene) const
{
    return std::any_of(scene.meshes.begin(), scene.meshes.end(), [](const SceneMesh& m) { return !m.skinned; });
}

void MeshRenderer::draw(const Scene& scene, const glm::mat4& viewProjection, const glm::vec3& viewDirection, bool seeThrough)
{
    if (!m_gl || scene.meshes.empty())
        return;
    glUseProgram(m_gl->program);
    glUniformMatrix4fv(m_gl->viewProjection, 1, GL_FALSE, &viewProjection[0][0]);
    glUniform3fv(m_gl->viewDirection, 1, &viewDirection[0]);
    glUniform1i(m_gl->palette, 1);
    glUniform1i(m_gl->baseTexture, 0);
    glUniform1f(m_gl->alpha, seeThrough ? 0.22f : 1.0f);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_BUFFER, m_gl->paletteTexture);
    glActiveTexture(GL_TEXTURE0);
    const bool dq = scene.skinning == Skinning::DualQuaternion;
    for (const SceneMesh& m : scene.meshes) {
        if (m.skinned == seeThrough)
            continue;
        auto gpu = std::find_if(m_gl->meshes.begin(), m_gl->meshes.end(),
                                [&](const Gl::GpuMesh& g) { return g.model == m.model && g.mesh == m.mesh; });
        if (gpu == m_gl->meshes.end() || gpu->indexCount == 0)
            continue;
        const bool weighted = gpu->hasInfluences;
        glUniform1i(m_gl->skinning, m.skinned && weighted ? (dq ? 2 : 1) : 0);
        glUniform1i(m_gl->weightDisplay, gpu->hasColors ? 3 : weighted ? int(scene.weightDisplay) : 0);
        glUniform1i(m_gl->weightBone, scene.weightBone);
        glUniform3fv(m_gl->baseColor, 1, &m.baseColor[0]);
        const GLuint texture = m_gl->texture(m.texturePath, m.textureImage.get());
        glUniform1i(m_gl->hasTexture, texture != 0);
        glBindTexture(GL_TEXTURE_2D, texture);
        glBindVertexArray(gpu->vao);
        if (!weighted) {
            glVertexAttribI4ui(3, 0, 0, 0, 0);
            glVertexAttrib4f(4, 0.0f, 0.0f, 0.0f, 0.0f);
        }
        glDrawElements(GL_TRIANGLES, gpu->indexCount, GL_UNSIGNED_INT, nullptr);
    }
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glActiveTexture(GL_TEXTURE0);
}

} // namespace rs::viewport
