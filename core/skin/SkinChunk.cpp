#include "skin/SkinChunk.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <set>

namespace rs::skin {

std::string formatExportTime(std::int64_t microseconds)
{
    const std::time_t seconds = std::time_t(microseconds / 1000000);
    std::tm utc{};
    if (!gmtime_r(&seconds, &utc))
        return "(no date)";
    char text[40];
    std::strftime(text, sizeof(text), "%Y-%m-%d %H:%M:%S UTC", &utc);
    return text;
}


namespace {

// The mesh's own normals when it has usable ones, else computed.
std::vector<glm::vec3> normalsOf(const model::Mesh& mesh)
{
    if (mesh.normals.size() != mesh.positions.size())
        return vertexNormals(mesh);
    std::vector<glm::vec3> out = mesh.normals;
    for (glm::vec3& n : out) {
        const float length = glm::length(n);
        n = length > 0.0f && std::isfinite(length) ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
    }
    return out;
}

Result<SkinChunk> refuse(const std::string& mesh, const std::string& why)
{
    return Result<SkinChunk>::failure(makeError({}, "mesh '" + mesh + "': " + why));
}

// Triangles among the exported vertices, and a sample of neighbours.
void addTopology(SkinChunk& chunk, const model::Mesh& mesh, const std::vector<std::uint32_t>& exported, int neighbourSample)
{
    const std::vector<std::uint32_t>& ids = chunk.vertexIds;
    std::vector<std::set<std::uint32_t>> around(neighbourSample > 0 ? mesh.vertexCount() : 0);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t c[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
        if (c[0] >= mesh.vertexCount() || c[1] >= mesh.vertexCount() || c[2] >= mesh.vertexCount())
            continue;
        if (exported[c[0]] != ~0u && exported[c[1]] != ~0u && exported[c[2]] != ~0u)
            chunk.triangles.insert(chunk.triangles.end(), {exported[c[0]], exported[c[1]], exported[c[2]]});
        for (int k = 0; k < 3 && !around.empty(); ++k) {
            around[c[k]].insert(c[(k + 1) % 3]);
            around[c[k]].insert(c[(k + 2) % 3]);
        }
    }
    chunk.neighbourOffsets.push_back(0);
    for (const std::uint32_t v : ids) {
        int taken = 0;
        if (!around.empty())
            for (auto it = around[v].begin(); it != around[v].end() && taken < neighbourSample; ++it, ++taken)
                chunk.neighbours.push_back(*it);
        chunk.neighbourOffsets.push_back(std::uint32_t(chunk.neighbours.size()));
    }
}

} // namespace

Result<SkinChunk> makeSkinChunk(const ChunkSource& source, const std::vector<SkinBone>& bones, const ChunkExportOptions& options)
{
    if (!source.mesh || !source.weights || !options.rig)
        return refuse(source.mesh ? source.mesh->name : "", "nothing to export (no mesh, weights or rig)");
    const model::Mesh& mesh = *source.mesh;
    const model::MeshWeights& weights = *source.weights;
    if (weights.vertexCount() != mesh.vertexCount())
        return refuse(mesh.name, "its weights cover " + std::to_string(weights.vertexCount()) + " vertices, the mesh has " +
                                     std::to_string(mesh.vertexCount()));
    if (weights.joints.size() != bones.size())
        return refuse(mesh.name, "its weights are not on the rig's skin joints");
    if (mesh.vertexCount() > 0xffffffffu)
        return refuse(mesh.name, "too many vertices for a chunk");

    SkinChunk chunk;
    chunk.mesh = mesh.name;
    chunk.model = source.model;
    chunk.tool = options.tool;
    chunk.user = options.user;
    chunk.exportedAtMicroseconds = options.exportedAtMicroseconds;
    chunk.totalVertexCount = std::uint32_t(mesh.vertexCount());
    chunk.fingerprint = model::topologyFingerprint(mesh);
    chunk.method = options.method;
    chunk.inBindPose = options.posedRig == nullptr;

    std::vector<std::uint32_t> ids = source.vertices;
    if (ids.empty()) {
        ids.resize(mesh.vertexCount());
        for (std::uint32_t v = 0; v < ids.size(); ++v)
            ids[v] = v;
    }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    if (!ids.empty() && ids.back() >= mesh.vertexCount())
        return refuse(mesh.name, "vertex " + std::to_string(ids.back()) + " is not one of its " + std::to_string(mesh.vertexCount()));
    chunk.vertexIds = ids;

    // Influences: every skin joint, with names and matrices from the rig.
    const model::Rig& rest = *options.rig;
    const model::Rig& posed = options.posedRig ? *options.posedRig : rest;
    chunk.weights.joints = weights.joints;
    chunk.weights.parents = weights.parents;
    std::vector<Mat4> skinMatrices;
    for (std::size_t b = 0; b < bones.size(); ++b) {
        const model::RigNodeIndex node = bones[b].node;
        if (node >= rest.nodes.size() || node >= posed.nodes.size())
            return refuse(mesh.name, "a skin joint is not in the rig");
        ChunkJoint joint;
        joint.key = bones[b].key;
        joint.name = rest.nodes[node].name;
        joint.bind = rest.nodes[node].worldMatrix;
        joint.world = posed.nodes[node].worldMatrix;
        const int parent = bones[b].parent;
        joint.local = parent >= 0 ? glm::inverse(posed.nodes[bones[std::size_t(parent)].node].worldMatrix) * joint.world : joint.world;
        skinMatrices.push_back(joint.world * glm::inverse(joint.bind));
        chunk.joints.push_back(std::move(joint));
    }

    // Positions and normals: bind pose from the mesh, the current pose skinned.
    const std::vector<glm::vec3> bindNormals = normalsOf(mesh);
    std::vector<glm::vec3> posedPositions = mesh.positions, posedNormals = bindNormals;
    if (!chunk.inBindPose) {
        SkinningJob job;
        job.method = options.method;
        job.positions = mesh.positions;
        job.normals = bindNormals;
        job.weights = &weights;
        job.skinMatrices = skinMatrices;
        job.outPositions = posedPositions;
        job.outNormals = posedNormals;
        const Status valid = job.validate();
        if (valid.failed())
            return Result<SkinChunk>::failure(valid.diagnostics());
        job.run();
    }
    std::vector<std::uint32_t> exported(mesh.vertexCount(), ~0u); // mesh vertex -> exported index
    chunk.weights.offsets.push_back(0);
    for (std::uint32_t i = 0; i < ids.size(); ++i) {
        const std::uint32_t v = ids[i];
        exported[v] = i;
        chunk.positions.push_back(posedPositions[v]);
        chunk.normals.push_back(posedNormals[v]);
        if (!chunk.inBindPose) {
            chunk.bindPositions.push_back(mesh.positions[v]);
            chunk.bindNormals.push_back(bindNormals[v]);
        }
        chunk.weights.influences.insert(chunk.weights.influences.end(), weights.begin(v), weights.end(v));
        chunk.weights.offsets.push_back(std::uint32_t(chunk.weights.influences.size()));
    }

    addTopology(chunk, mesh, exported, options.neighbourSample);
    return chunk;
}

Result<SkinChunk> makeBindPoseChunk(const model::Mesh& mesh, const model::MeshWeights& weights, std::vector<ChunkJoint> joints,
                                    const std::string& model, const ChunkExportOptions& options)
{
    if (weights.vertexCount() != mesh.vertexCount() || joints.size() != weights.joints.size() || weights.parents.size() != joints.size())
        return refuse(mesh.name, "its weights do not fit the mesh or their influences");
    SkinChunk chunk;
    chunk.mesh = mesh.name;
    chunk.model = model;
    chunk.tool = options.tool;
    chunk.user = options.user;
    chunk.exportedAtMicroseconds = options.exportedAtMicroseconds;
    chunk.totalVertexCount = std::uint32_t(mesh.vertexCount());
    chunk.fingerprint = model::topologyFingerprint(mesh);
    chunk.method = options.method;
    chunk.vertexIds.resize(mesh.vertexCount());
    std::vector<std::uint32_t> exported(mesh.vertexCount());
    for (std::uint32_t v = 0; v < mesh.vertexCount(); ++v)
        chunk.vertexIds[v] = exported[v] = v;
    chunk.positions = mesh.positions;
    chunk.normals = normalsOf(mesh);
    chunk.weights = weights;
    chunk.joints = std::move(joints);
    addTopology(chunk, mesh, exported, options.neighbourSample);
    return chunk;
}

} // namespace rs::skin
