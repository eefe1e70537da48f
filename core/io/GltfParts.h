#pragma once
// Pieces of the glTF writer (internal to io/GltfExport.cpp and
// io/GltfMesh.cpp): the buffer builder and the skinned meshes and materials.
#include "base/Diagnostic.h"
#include "io/ExportScene.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace rs::io::gltf {

constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
// Appends bufferViews and accessors to one buffer, 4-byte aligned.
class GltfBuilder {
public:
    explicit GltfBuilder(tinygltf::Model& model) : m_model(model) { m_model.buffers.emplace_back(); }

    template <typename T>
    int view(const std::vector<T>& data, int target)
    {
        auto& bytes = m_model.buffers[0].data;
        bytes.resize((bytes.size() + 3) & ~std::size_t(3), 0);
        tinygltf::BufferView v;
        v.buffer = 0;
        v.byteOffset = bytes.size();
        v.byteLength = data.size() * sizeof(T);
        v.target = target;
        const auto* raw = reinterpret_cast<const unsigned char*>(data.data());
        bytes.insert(bytes.end(), raw, raw + v.byteLength);
        m_model.bufferViews.push_back(v);
        return int(m_model.bufferViews.size() - 1);
    }

    template <typename T>
    int accessor(const std::vector<T>& data, int componentType, int type, std::size_t count, int target = 0)
    {
        tinygltf::Accessor a;
        a.bufferView = view(data, target);
        a.componentType = componentType;
        a.type = type;
        a.count = count;
        m_model.accessors.push_back(a);
        return int(m_model.accessors.size() - 1);
    }

    // A float accessor of `width` components with min/max (positions, clip times).
    int bounded(const std::vector<float>& data, int type, int width, int target = 0)
    {
        const int index = accessor(data, TINYGLTF_COMPONENT_TYPE_FLOAT, type, data.size() / std::size_t(width), target);
        auto& a = m_model.accessors[std::size_t(index)];
        a.minValues.assign(std::size_t(width), 1e300);
        a.maxValues.assign(std::size_t(width), -1e300);
        for (std::size_t i = 0; i < data.size(); ++i) {
            const auto k = i % std::size_t(width);
            a.minValues[k] = std::min(a.minValues[k], double(data[i]));
            a.maxValues[k] = std::max(a.maxValues[k], double(data[i]));
        }
        return index;
    }

private:
    tinygltf::Model& m_model;
};

// A skinned mesh (positions, normals, UVs, 4 joints and weights per vertex,
// triangles) as a glTF mesh; its index in m.meshes. `jointCount` picks the
// joint index width.
int addMesh(tinygltf::Model& m, GltfBuilder& b, const SkinnedMesh& source, std::size_t jointCount);
// Materials in the scene's order (so SkinnedMesh::material indexes them); a
// PNG or JPEG base colour image goes into the buffer (the .glb's BIN chunk,
// the .gltf's .bin), other formats are left out with a warning.
void addMaterials(tinygltf::Model& m, GltfBuilder& b, const ExportScene& scene, Diagnostics& report);

} // namespace rs::io::gltf
