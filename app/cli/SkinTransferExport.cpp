// Writing transferred weights as a skinned glTF: see SkinTransferExport.h.
#include "cli/SkinTransferExport.h"

#include "io/ExportScene.h"
#include "io/GltfExport.h"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>

namespace rs::cli {

namespace {

struct SourceJoint {
    skin::ChunkJoint joint;
    std::optional<NodeKey> parent;
};

// Every chunk influence once, by key, with its parent's key.
std::vector<SourceJoint> sourceJoints(const std::vector<skin::SkinChunk>& chunks)
{
    std::vector<SourceJoint> joints;
    std::map<NodeKey, std::size_t> seen;
    for (const skin::SkinChunk& c : chunks)
        for (std::size_t j = 0; j < c.weights.joints.size() && j < c.joints.size(); ++j) {
            if (!seen.emplace(c.weights.joints[j], joints.size()).second)
                continue;
            SourceJoint s{c.joints[j], std::nullopt};
            s.joint.key = c.weights.joints[j];
            const std::int32_t parent = j < c.weights.parents.size() ? c.weights.parents[j] : -1;
            if (parent >= 0 && std::size_t(parent) < c.weights.joints.size())
                s.parent = c.weights.joints[std::size_t(parent)];
            joints.push_back(std::move(s));
        }
    return joints;
}

// The skeleton, parents first; `index` maps each key to its joint.
std::vector<io::ExportJoint> skeletonOf(const std::vector<SourceJoint>& joints, std::map<NodeKey, int>& index)
{
    std::map<NodeKey, std::size_t> byKey;
    for (std::size_t j = 0; j < joints.size(); ++j)
        byKey[joints[j].joint.key] = j;
    std::vector<io::ExportJoint> out;
    std::function<int(std::size_t)> place = [&](std::size_t j) -> int {
        if (auto it = index.find(joints[j].joint.key); it != index.end())
            return it->second; // -1 while being placed: a cycle ends at a root
        index[joints[j].joint.key] = -1;
        int parent = -1;
        if (const auto up = joints[j].parent ? byKey.find(*joints[j].parent) : byKey.end(); up != byKey.end())
            parent = place(up->second);
        const Mat4 parentWorld = parent >= 0 ? out[std::size_t(parent)].bindWorld : Mat4(1.0);
        const Mat4& bind = joints[j].joint.bind;
        const Mat4 local = glm::inverse(parentWorld) * bind;
        out.push_back({joints[j].joint.name, "", parent, bind, local, local});
        return index[joints[j].joint.key] = int(out.size() - 1);
    };
    for (std::size_t j = 0; j < joints.size(); ++j)
        place(j);
    if (std::count_if(out.begin(), out.end(), [](const io::ExportJoint& j) { return j.parent < 0; }) > 1) {
        for (io::ExportJoint& j : out)
            j.parent += 1; // the roots' -1 becomes 0: the new root
        out.insert(out.begin(), io::ExportJoint{"root", "", -1, Mat4(1.0), Mat4(1.0), Mat4(1.0)});
        for (auto& [key, joint] : index)
            ++joint;
    }
    return out;
}

// One target mesh bound to the skeleton: at most 4 weights per vertex; an
// unweighted vertex on the root. Counts those in `unweighted`.
io::SkinnedMesh skinnedMesh(const model::Mesh& mesh, const model::MeshWeights& weights, const std::map<NodeKey, int>& index,
                            std::size_t& unweighted)
{
    io::SkinnedMesh out;
    out.name = mesh.name;
    out.positions = mesh.positions;
    out.normals = mesh.normals.size() == mesh.positions.size() ? mesh.normals : model::vertexNormals(mesh);
    if (mesh.uvs.size() == mesh.positions.size())
        out.uvs = mesh.uvs;
    out.indices = mesh.indices;
    out.influenceStart.push_back(0);
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const std::size_t before = out.influences.size();
        for (const model::Influence* i = weights.begin(v); i != weights.end(v); ++i)
            if (i->weight > 0.0f)
                out.influences.push_back({index.at(weights.joints[i->joint]), i->weight});
        if (out.influences.size() == before) {
            out.influences.push_back({0, 1.0f});
            ++unweighted;
        }
        out.influenceStart.push_back(std::uint32_t(out.influences.size()));
    }
    return io::limitInfluences(std::move(out), io::kMaxInfluences);
}

} // namespace

Diagnostics writeTransferredGltf(const std::string& path, const std::vector<const model::Mesh*>& meshes,
                                 const std::vector<model::MeshWeights>& weights, const std::vector<skin::SkinChunk>& chunks,
                                 const std::string& generator)
{
    std::map<NodeKey, int> index;
    io::ExportScene scene;
    scene.name = std::filesystem::path(path).stem().string();
    scene.joints = skeletonOf(sourceJoints(chunks), index);
    Diagnostics notes;
    for (std::size_t m = 0; m < meshes.size() && m < weights.size(); ++m) {
        for (const NodeKey& key : weights[m].joints)
            if (!index.count(key))
                return {makeError({path, 0, 0}, "mesh '" + meshes[m]->name + "': influence '" + key.tag + "' is in no source chunk")};
        std::size_t unweighted = 0;
        scene.meshes.push_back(skinnedMesh(*meshes[m], weights[m], index, unweighted));
        if (unweighted > 0)
            notes.push_back(makeWarning({path, 0, 0}, "mesh '" + meshes[m]->name + "': " + std::to_string(unweighted) +
                                                           " vertices got no weight and are written on the root joint"));
    }
    Diagnostics written = io::writeGltf(scene, path, generator);
    written.insert(written.begin(), notes.begin(), notes.end());
    return written;
}

} // namespace rs::cli
