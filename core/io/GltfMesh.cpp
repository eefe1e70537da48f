// glTF skinned meshes and materials (io/GltfParts.h).
#include "io/GltfParts.h"

#include <cmath>
#include <cstdint>
#include <optional>

namespace rs::io::gltf {

namespace {

template <typename Index>
std::vector<Index> packJoints(const SkinnedMesh& mesh)
{
    std::vector<Index> joints(mesh.vertexCount() * 4, 0);
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
        for (std::size_t k = 0; k < mesh.influenceCount(v); ++k)
            joints[v * 4 + k] = Index(mesh.influencesOf(v)[k].joint);
    return joints;
}

// At most kMaxInfluences weights summing to 1 on every vertex: what glTF
// requires, and what the validator already ensured unless the export was forced.
bool isPackable(const SkinnedMesh& mesh)
{
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        if (mesh.influenceCount(v) > std::size_t(kMaxInfluences))
            return false;
        double sum = 0.0;
        for (std::size_t k = 0; k < mesh.influenceCount(v); ++k)
            sum += mesh.influencesOf(v)[k].weight;
        if (std::abs(sum - 1.0) > kWeightTolerance)
            return false;
    }
    return true;
}

// UVs as glTF wants them: its origin is the image's top-left corner, the
// imported (OpenGL) UVs' is the bottom-left.
std::vector<float> gltfUvs(const SkinnedMesh& mesh)
{
    std::vector<float> uvs;
    uvs.reserve(mesh.uvs.size() * 2);
    for (const auto& uv : mesh.uvs)
        uvs.insert(uvs.end(), {uv.x, 1.f - uv.y});
    return uvs;
}

} // namespace

int addMesh(tinygltf::Model& m, GltfBuilder& b, const SkinnedMesh& source, std::size_t jointCount)
{
    std::optional<SkinnedMesh> limited; // only forced exports of bad weights pay for a fixed copy
    if (!isPackable(source))
        limited = limitInfluences(source);
    const SkinnedMesh& mesh = limited ? *limited : source;
    std::vector<float> positions, normals, weights(mesh.vertexCount() * 4, 0.f);
    positions.reserve(mesh.vertexCount() * 3);
    for (const auto& p : mesh.positions)
        positions.insert(positions.end(), {p.x, p.y, p.z});
    for (const auto& n : mesh.normals)
        normals.insert(normals.end(), {n.x, n.y, n.z});
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        double sum = 0.0; // normalised again in float, as the Khronos validator checks it
        for (std::size_t k = 0; k < mesh.influenceCount(v); ++k)
            sum += mesh.influencesOf(v)[k].weight;
        for (std::size_t k = 0; k < mesh.influenceCount(v); ++k)
            weights[v * 4 + k] = float(mesh.influencesOf(v)[k].weight / sum);
    }

    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.attributes["POSITION"] = b.bounded(positions, TINYGLTF_TYPE_VEC3, 3, kArrayBuffer);
    if (!normals.empty())
        primitive.attributes["NORMAL"] = b.accessor(normals, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                                                    mesh.vertexCount(), kArrayBuffer);
    if (!mesh.uvs.empty())
        primitive.attributes["TEXCOORD_0"] = b.accessor(gltfUvs(mesh), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2,
                                                        mesh.vertexCount(), kArrayBuffer);
    if (mesh.material >= 0 && std::size_t(mesh.material) < m.materials.size())
        primitive.material = mesh.material;
    primitive.attributes["JOINTS_0"] =
        jointCount <= 256 ? b.accessor(packJoints<std::uint8_t>(mesh), TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                       TINYGLTF_TYPE_VEC4, mesh.vertexCount(), kArrayBuffer)
                          : b.accessor(packJoints<std::uint16_t>(mesh), TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                       TINYGLTF_TYPE_VEC4, mesh.vertexCount(), kArrayBuffer);
    primitive.attributes["WEIGHTS_0"] = b.accessor(weights, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4,
                                                   mesh.vertexCount(), kArrayBuffer);
    primitive.indices = b.accessor(mesh.indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                   mesh.indices.size(), kElementArrayBuffer);
    tinygltf::Mesh out;
    out.name = mesh.name;
    out.primitives.push_back(primitive);
    m.meshes.push_back(out);
    return int(m.meshes.size() - 1);
}

void addMaterials(tinygltf::Model& m, GltfBuilder& b, const ExportScene& scene, Diagnostics& report)
{
    for (const ExportMaterial& source : scene.materials) {
        tinygltf::Material material;
        material.name = source.name;
        material.pbrMetallicRoughness.baseColorFactor = {source.baseColor.x, source.baseColor.y, source.baseColor.z, 1.0};
        material.pbrMetallicRoughness.metallicFactor = 0.0; // a character's skin and cloth are not metal
        material.pbrMetallicRoughness.roughnessFactor = 1.0;
        material.doubleSided = false;
        if (!source.image.empty() && source.mimeType.empty())
            report.push_back(makeWarning({}, "material '" + source.name + "': its texture " + source.imageName +
                                                 " is neither PNG nor JPEG, which glTF needs; exported without it"));
        if (!source.image.empty() && !source.mimeType.empty()) {
            if (m.samplers.empty()) {
                tinygltf::Sampler sampler;
                sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
                sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
                m.samplers.push_back(sampler);
            }
            tinygltf::Image image;
            image.name = source.imageName;
            image.mimeType = source.mimeType;
            image.bufferView = b.view(std::vector<unsigned char>(source.image.begin(), source.image.end()), 0);
            m.images.push_back(image);
            tinygltf::Texture texture;
            texture.sampler = 0;
            texture.source = int(m.images.size() - 1);
            m.textures.push_back(texture);
            material.pbrMetallicRoughness.baseColorTexture.index = int(m.textures.size() - 1);
        }
        m.materials.push_back(material);
    }
}

} // namespace rs::io::gltf
