// Re-fitting a binding whose mesh changed topology (issue 20 item 5): the
// previous mesh (a chunk: bind positions, triangles) with the binding's own
// weights is imported onto the new mesh by the decision tree, as one undo step.
#include "session/Session.h"

#include <algorithm>
#include <chrono>
#include <filesystem>

namespace rs::session {

namespace {

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

std::int64_t nowMicroseconds()
{
    return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
}

// Binding `b`'s weights on a chunk's geometry (all of its mesh's vertices);
// influences named by the rig when it has them, else by their tag.
void putWeights(skin::SkinChunk& chunk, const model::MeshBinding& b, const model::Rig* rig)
{
    chunk.weights = b.weights;
    chunk.joints.clear();
    for (const NodeKey& key : b.weights.joints) {
        skin::ChunkJoint joint;
        joint.key = key;
        const auto node = rig ? rig->find(key) : std::nullopt;
        joint.name = node ? rig->nodes[*node].name : key.tag;
        if (node)
            joint.world = joint.bind = rig->nodes[*node].worldMatrix; // bind pose; `local` is not needed to re-fit
        chunk.joints.push_back(std::move(joint));
    }
}

// The chunk of a mesh as its binding fits it, in bind pose.
skin::SkinChunk bindingChunk(const model::MeshBinding& b, const model::Mesh& mesh, const model::Rig* rig)
{
    skin::SkinChunk chunk;
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
    chunk.normals = mesh.normals.size() == mesh.positions.size() ? mesh.normals : skin::vertexNormals(mesh);
    for (glm::vec3& n : chunk.normals) // a file's normals may be unnormalised
        n = glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f, 1.0f, 0.0f);
    chunk.triangles = mesh.indices;
    chunk.neighbourOffsets.assign(mesh.vertexCount() + 1, 0);
    putWeights(chunk, b, rig);
    return chunk;
}

bool describes(const skin::SkinChunk& c, const model::MeshBinding& b)
{
    return c.mesh == b.mesh && fileName(c.model) == fileName(b.model) && c.totalVertexCount == b.vertexCount &&
           c.fingerprint == b.fingerprint && c.vertexCount() == c.totalVertexCount;
}

Diagnostic refitNote(const std::string& model, const model::MeshBinding& was, const skin::MeshImportReport& r)
{
    Diagnostic d = makeWarning({model, 0, 0}, "");
    d.severity = Severity::Note;
    d.subject = Subject::ofMesh(r.mesh);
    d.message = "mesh '" + r.mesh + "' changed since it was bound (" + std::to_string(was.vertexCount) + " vertices then, " +
                std::to_string(r.vertices) + " now): its weights were re-fitted from the previous mesh (" + r.why + "): " +
                std::to_string(r.oneToOne) + " vertices matched 1:1, " +
                std::to_string(r.closestPoint + r.closestNeighbours + r.singleInfluence) + " transferred (" +
                std::to_string(r.normalFilterFallbacks) + " by the normal filter's fallback), " + std::to_string(r.inpainted) +
                " inpainted, in " + std::to_string(int(r.milliseconds)) + " ms; undo brings the previous weights back";
    return d;
}

} // namespace

skin::TransferOptions Session::defaultRefitOptions()
{
    skin::TransferOptions options;
    options.method = skin::TransferMethod::Inpainting;
    return options;
}

const skin::SkinChunk* Session::previousChunk(const model::MeshBinding& binding) const
{
    for (auto c = m_savedChunks.rbegin(); c != m_savedChunks.rend(); ++c)
        if (describes(*c, binding))
            return &*c;
    return nullptr;
}

void Session::rememberChunks(const LoadedModel& model)
{
    for (const CharacterMesh& m : m_characterMeshes) {
        if (m.binding < 0 || m.changed || m_models[m.model].path != model.path || !model.model)
            continue;
        const model::MeshBinding& b = m_document.bindings[std::size_t(m.binding)];
        std::erase_if(m_savedChunks, [&](const skin::SkinChunk& c) { return describes(c, b); });
        m_savedChunks.push_back(bindingChunk(b, m.data(m_models), rig()));
    }
}

std::vector<skin::SkinChunk> Session::bindingChunks() const
{
    std::vector<skin::SkinChunk> out;
    std::vector<bool> covered(m_document.bindings.size(), false);
    for (const CharacterMesh& m : m_characterMeshes)
        if (m.binding >= 0 && !m.changed) {
            covered[std::size_t(m.binding)] = true;
            out.push_back(bindingChunk(m_document.bindings[std::size_t(m.binding)], m.data(m_models), rig()));
        }
    for (std::size_t b = 0; b < covered.size(); ++b)
        if (!covered[b])
            if (const skin::SkinChunk* kept = previousChunk(m_document.bindings[b])) {
                out.push_back(*kept);
                putWeights(out.back(), m_document.bindings[b], rig());
            }
    return out;
}

std::vector<skin::MeshImportReport> Session::refitChangedMeshes()
{
    if (m_history.inTransaction())
        return {};
    std::vector<model::MeshBinding> records;
    std::vector<skin::MeshImportReport> reports;
    Diagnostics notes;
    for (const CharacterMesh& m : m_characterMeshes) {
        if (!m.changed)
            continue;
        const model::MeshBinding& was = m_document.bindings[std::size_t(m.binding)];
        const skin::SkinChunk* previous = previousChunk(was);
        if (!previous)
            continue; // reported by matchMeshes: kept, not applied
        skin::SkinChunk chunk = *previous;
        putWeights(chunk, was, rig()); // the record is the truth; the chunk gives where its vertices were
        const model::Mesh& mesh = m.data(m_models);
        std::vector<skin::MeshImportReport> one;
        auto weights = skin::importChunks({chunk}, {&mesh}, m_refitOptions, &one);
        if (!weights) {
            Diagnostic d = makeWarning({was.model, 0, 0}, "mesh '" + mesh.name + "' could not be re-fitted (" + formatAll(weights.diagnostics()) +
                                                              "): its weights are kept but not applied");
            d.subject = Subject::ofMesh(mesh.name);
            notes.push_back(std::move(d));
            continue;
        }
        notes.push_back(refitNote(was.model, was, one[0]));
        records.push_back({was.model, mesh.name, mesh.vertexCount(), model::topologyFingerprint(mesh), std::move(weights.take()[0])});
        reports.push_back(std::move(one[0]));
    }
    if (!records.empty()) {
        const std::string what = records.size() == 1 ? "Re-fit weights of mesh '" + records[0].mesh + "'"
                                                     : "Re-fit weights of " + std::to_string(records.size()) + " meshes";
        const Status set = setBindings(std::move(records), what);
        notes.insert(notes.end(), set.diagnostics().begin(), set.diagnostics().end());
        if (set.failed())
            reports.clear();
    }
    report(notes);
    return reports;
}

} // namespace rs::session
