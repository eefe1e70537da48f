#include "skin/Refit.h"

#include <chrono>
#include <filesystem>

namespace rs::skin {

namespace {

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

std::int64_t nowMicroseconds()
{
    return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
}



Diagnostic refitNote(const model::MeshBinding& was, const MeshImportReport& r)
{
    Diagnostic d = makeWarning({was.model, 0, 0}, "");
    d.severity = Severity::Note;
    d.subject = Subject::ofMesh(r.mesh);
    d.message = "mesh '" + r.mesh + "' changed since it was bound (" + std::to_string(was.vertexCount) + " vertices then, " +
                std::to_string(r.vertices) + " now): its weights were re-fitted from the previous mesh (" + r.why + "): " +
                std::to_string(r.oneToOne) + " vertices matched 1:1, " +
                std::to_string(r.closestPoint + r.closestNeighbours + r.singleInfluence) + " transferred (" +
                std::to_string(r.normalFilterFallbacks) + " by the normal filter's fallback), " + std::to_string(r.inpainted) +
                " inpainted, in " + std::to_string(int(r.milliseconds)) + " ms";
    return d;
}

} // namespace

void putBindingWeights(SkinChunk& chunk, const model::MeshBinding& b, const model::Rig* rig)
{
    chunk.weights = b.weights;
    chunk.joints.clear();
    for (const NodeKey& key : b.weights.joints) {
        ChunkJoint joint;
        joint.key = key;
        const auto node = rig ? rig->find(key) : std::nullopt;
        joint.name = node ? rig->nodes[*node].name : key.tag;
        if (node)
            joint.world = joint.bind = rig->nodes[*node].worldMatrix; // bind pose; `local` is not needed to re-fit
        chunk.joints.push_back(std::move(joint));
    }
}

bool chunkDescribes(const SkinChunk& c, const model::MeshBinding& b)
{
    return c.mesh == b.mesh && fileName(c.model) == fileName(b.model) && c.totalVertexCount == b.vertexCount &&
           c.fingerprint == b.fingerprint && c.vertexCount() == c.totalVertexCount;
}

SkinChunk bindingChunk(const model::MeshBinding& b, const model::Mesh& mesh, const model::Rig* rig)
{
    SkinChunk chunk;
    chunk.mesh = mesh.name;
    chunk.model = b.model;
    chunk.tool = "rigsmith (weights beside the guide)";
    chunk.exportedAtMicroseconds = nowMicroseconds();
    chunk.totalVertexCount = std::uint32_t(mesh.vertexCount());
    chunk.fingerprint = b.fingerprint;
    chunk.inBindPose = true;
    chunk.vertexIds.resize(mesh.vertexCount());
    for (std::uint32_t v = 0; v < chunk.vertexIds.size(); ++v)
        chunk.vertexIds[v] = v;
    chunk.positions = mesh.positions;
    chunk.normals = mesh.normals.size() == mesh.positions.size() ? mesh.normals : vertexNormals(mesh);
    for (glm::vec3& n : chunk.normals) // a file's normals may be unnormalised
        n = glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f, 1.0f, 0.0f);
    chunk.triangles = mesh.indices;
    chunk.neighbourOffsets.assign(mesh.vertexCount() + 1, 0);
    putBindingWeights(chunk, b, rig);
    return chunk;
}

const SkinChunk* previousChunk(const std::vector<SkinChunk>& chunks, const model::MeshBinding& binding)
{
    for (auto c = chunks.rbegin(); c != chunks.rend(); ++c)
        if (chunkDescribes(*c, binding))
            return &*c;
    return nullptr;
}

TransferOptions defaultRefitOptions()
{
    TransferOptions options;
    options.method = TransferMethod::Inpainting;
    return options;
}

Result<Refit> refitBinding(const model::MeshBinding& was, const SkinChunk& previous, const model::Mesh& mesh, const model::Rig* rig,
                           const TransferOptions& options)
{
    SkinChunk chunk = previous;
    putBindingWeights(chunk, was, rig); // the record is the truth; the chunk gives where its vertices were
    std::vector<MeshImportReport> one;
    auto weights = importChunks({chunk}, {&mesh}, options, &one);
    if (!weights)
        return Result<Refit>::failure(weights.takeDiagnostics());
    Refit out;
    out.binding = {was.model, mesh.name, mesh.vertexCount(), model::topologyFingerprint(mesh), std::move(weights.take()[0])};
    out.report = std::move(one[0]);
    out.note = refitNote(was, out.report);
    return out;
}

} // namespace rs::skin
