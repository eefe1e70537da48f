// Skin chunk export and import on the session's character (issue 20): the
// export reads the applied weights (on the skin bones), an import is
// prepared here, run anywhere and applied as one undo step.
#include "session/Session.h"

#include "skin/ImportScope.h"

#include <algorithm>
#include <set>

namespace rs::session {

namespace {

Diagnostic meshError(const std::string& model, const std::string& mesh, const std::string& why)
{
    Diagnostic d = makeError({model, 0, 0}, "mesh '" + mesh + "': " + why);
    d.subject = Subject::ofMesh(mesh);
    return d;
}

// `imported` (on its own influences) on the selected `vertices` of `existing`;
// the other vertices keep theirs. Influences are joined by skin joint key.
model::MeshWeights mergeVertices(const model::MeshWeights& existing, const model::MeshWeights& imported,
                                 const std::vector<std::uint32_t>& vertices)
{
    model::MeshWeights out;
    out.joints = existing.joints;
    out.parents = existing.parents;
    std::vector<std::uint32_t> toOut(imported.joints.size());
    for (std::size_t j = 0; j < imported.joints.size(); ++j) {
        auto at = std::find(out.joints.begin(), out.joints.end(), imported.joints[j]);
        toOut[j] = std::uint32_t(at - out.joints.begin());
        if (at == out.joints.end()) {
            out.joints.push_back(imported.joints[j]);
            out.parents.push_back(-2); // set below, once every joint has its index
        }
    }
    for (std::size_t j = 0; j < imported.joints.size(); ++j)
        if (out.parents[toOut[j]] == -2)
            out.parents[toOut[j]] = imported.parents[j] < 0 ? -1 : std::int32_t(toOut[std::size_t(imported.parents[j])]);
    const std::set<std::uint32_t> selected(vertices.begin(), vertices.end());
    out.offsets.push_back(0);
    for (std::size_t v = 0; v < existing.vertexCount(); ++v) {
        if (selected.count(std::uint32_t(v)))
            for (const model::Influence* i = imported.begin(v); i != imported.end(v); ++i)
                out.influences.push_back({toOut[i->joint], i->weight});
        else
            out.influences.insert(out.influences.end(), existing.begin(v), existing.end(v));
        out.offsets.push_back(std::uint32_t(out.influences.size()));
    }
    return out;
}

// True when `weights` are on `bones` as they are (their keys and parents, in
// order): an export then writes the record bit for bit, not a retargeted copy
// (retargeting normalises again), so a 1:1 round trip is exact.
bool isOnBones(const model::MeshWeights& weights, const std::vector<skin::SkinBone>& bones)
{
    if (weights.joints.size() != bones.size())
        return false;
    for (std::size_t b = 0; b < bones.size(); ++b)
        if (weights.joints[b] != bones[b].key || weights.parents[b] != bones[b].parent)
            return false;
    return true;
}

// Per skin bone, whether `joints` names it; an error per key that is no skin joint.
std::vector<bool> bonesOf(const std::vector<NodeKey>& joints, const std::vector<skin::SkinBone>& bones, Diagnostics& problems)
{
    std::vector<bool> selected(bones.size(), false);
    for (const NodeKey& key : joints) {
        auto at = std::find_if(bones.begin(), bones.end(), [&](const skin::SkinBone& b) { return b.key == key; });
        if (at == bones.end())
            problems.push_back(makeError({}, "'" + key.tag + "' of instance " + std::to_string(key.instance) + " is not a skin joint of the rig"));
        else
            selected[std::size_t(at - bones.begin())] = true;
    }
    return selected;
}

// The vertices (ascending) some bone in `bones` weights, on weights whose joints are the skin bones.
std::vector<std::uint32_t> weightedBy(const model::MeshWeights& weights, const std::vector<bool>& bones)
{
    std::vector<std::uint32_t> out;
    for (std::size_t v = 0; v < weights.vertexCount(); ++v)
        for (const model::Influence* i = weights.begin(v); i != weights.end(v); ++i)
            if (i->weight > 0.0f && i->joint < bones.size() && bones[i->joint]) {
                out.push_back(std::uint32_t(v));
                break;
            }
    return out;
}

} // namespace

Result<std::vector<std::pair<std::size_t, std::vector<std::uint32_t>>>> Session::scopeMeshes(const SkinScope& scope) const
{
    std::vector<std::pair<std::size_t, std::vector<std::uint32_t>>> out;
    switch (scope.kind) {
    case SkinScope::Kind::All:
    case SkinScope::Kind::Joints: // every mesh; the export keeps the vertices the joints weight
        for (std::size_t m = 0; m < m_characterMeshes.size(); ++m)
            out.emplace_back(m, std::vector<std::uint32_t>{});
        break;
    case SkinScope::Kind::Meshes:
        for (std::size_t m : scope.meshes) {
            if (m >= m_characterMeshes.size())
                return Result<decltype(out)>::refused("no character mesh " + std::to_string(m));
            out.emplace_back(m, std::vector<std::uint32_t>{});
        }
        break;
    case SkinScope::Kind::SelectedVertices:
        for (const auto& [m, vertices] : m_selectedVertices)
            if (!vertices.empty() && m < m_characterMeshes.size())
                out.emplace_back(m, vertices);
        if (out.empty())
            return Result<decltype(out)>::refused("no vertex is selected");
        break;
    }
    return out;
}

std::optional<model::Rig> Session::posedRigNow() const
{
    const bool rest = std::all_of(m_skinPalette.begin(), m_skinPalette.end(),
                                  [](const Mat4& m) { return maxAbsDifference(m, Mat4(1.0)) < 1e-9; });
    if (!m_rig || !m_program || rest)
        return std::nullopt;
    model::Rig posed = *m_rig;
    for (std::size_t n = 0; n < posed.nodes.size(); ++n)
        posed.nodes[n].worldMatrix = m_evaluation.worldMatrix(model::RigNodeIndex(n));
    return posed;
}

Result<std::vector<skin::SkinChunk>> Session::exportSkinChunks(const SkinScope& scope, skin::ChunkExportOptions stamp) const
{
    using Out = Result<std::vector<skin::SkinChunk>>;
    if (!m_rig || m_skinBones.empty())
        return Out::refused("build the rig before exporting skin weights: there are no skin joints to name them by");
    auto meshes = scopeMeshes(scope);
    if (!meshes)
        return Out::failure(meshes.takeDiagnostics());
    const std::optional<model::Rig> posed = posedRigNow();
    stamp.rig = &*m_rig;
    stamp.posedRig = posed ? &*posed : nullptr;
    Diagnostics problems;
    const bool byJoints = scope.kind == SkinScope::Kind::Joints;
    if (byJoints && scope.joints.empty())
        return Out::refused("no skin joint is selected: select joints (or their template instance), or export the whole character");
    const std::vector<bool> bones = bonesOf(scope.joints, m_skinBones, problems);
    if (hasErrors(problems))
        return Out::failure(std::move(problems));
    std::vector<skin::SkinChunk> chunks;
    for (const auto& [index, scoped] : *meshes) {
        std::vector<std::uint32_t> vertices = scoped;
        const CharacterMesh& m = m_characterMeshes[index];
        const model::Mesh& mesh = m.data(m_models);
        const std::string& path = m_models[m.model].path;
        if (!m.weights) {
            if (scope.kind != SkinScope::Kind::All && !byJoints) // the whole character: its bound meshes
                problems.push_back(meshError(path, mesh.name, m.changed ? "it changed since it was bound: its weights no longer fit it"
                                                                        : "it has no weights to export (Skin > Bind first)"));
            continue;
        }
        if (std::any_of(chunks.begin(), chunks.end(), [&](const skin::SkinChunk& c) { return c.mesh == mesh.name; })) {
            problems.push_back(meshError(path, mesh.name, "a second mesh of this name: a chunk file holds one chunk per name"));
            continue;
        }
        const model::MeshWeights& record = m_document.bindings[std::size_t(m.binding)].weights;
        const model::MeshWeights* weights = isOnBones(record, m_skinBones) ? &record : m.weights.get();
        if (byJoints && (vertices = weightedBy(*weights, bones)).empty())
            continue; // no selected joint weights this mesh
        auto chunk = skin::makeSkinChunk({&mesh, weights, path, vertices}, m_skinBones, stamp);
        if (!chunk)
            return Out::failure(chunk.takeDiagnostics());
        chunks.push_back(chunk.take());
    }
    if (hasErrors(problems))
        return Out::failure(std::move(problems));
    if (chunks.empty())
        return Out::refused(byJoints ? "the selected joints weight no vertex: nothing to export" : "no bound mesh to export: Skin > Bind first");
    return chunks;
}

std::vector<std::string> Session::skinBoneNames() const
{
    std::vector<std::string> names;
    for (const skin::SkinBone& bone : m_skinBones)
        names.push_back(m_rig && bone.node < m_rig->nodes.size() ? m_rig->nodes[bone.node].name : "");
    return names;
}

std::vector<skin::InfluenceMatch> Session::missingInfluences(const std::vector<skin::SkinChunk>& chunks,
                                                             const skin::InfluenceMapOptions& influences) const
{
    return skin::missingInfluences(chunks, m_skinBones, skinBoneNames(), influences);
}

Result<SkinImportJob> Session::prepareSkinImport(std::vector<skin::SkinChunk> chunks, skin::TransferOptions options,
                                                 const SkinScope& onto, const skin::InfluenceMapOptions& influences) const
{
    using Out = Result<SkinImportJob>;
    if (!m_rig || m_skinBones.empty())
        return Out::refused("build the rig before importing skin weights: their influences land on its skin joints");
    if (influences.missing == skin::MissingInfluences::Map && influences.names.empty())
        return Out::refused("missing influences: map needs a name map (influence name = rig skin joint name)");
    if (onto.kind == SkinScope::Kind::Joints)
        return Out::refused("an import writes meshes or vertices: import onto the character, meshes or selected vertices, not joints");
    const Status valid = skin::validateTransferOptions(options);
    if (valid.failed())
        return Out::failure(valid.diagnostics());
    auto merged = skin::mergeChunks(std::move(chunks));
    if (!merged)
        return Out::failure(merged.takeDiagnostics());
    auto meshes = scopeMeshes(onto);
    if (!meshes)
        return Out::failure(meshes.takeDiagnostics());
    SkinImportJob job;
    job.notes = merged.takeDiagnostics();
    if (merged->empty())
        return Out::refused("no skin chunk to import");
    std::vector<std::string> names = skinBoneNames();
    std::vector<skin::SkinBone> bones = m_skinBones;
    skin::InfluenceMapOptions rules = influences;
    if (influences.missing == skin::MissingInfluences::Create) { // the missing ones become joints, then match by name
        auto planned = planCreatedInfluences(m_document, *m_rig, *m_templates, *merged, influences, bones, names);
        if (!planned)
            return Out::failure(planned.takeDiagnostics());
        for (Diagnostic& d : planned.takeDiagnostics())
            job.notes.push_back(std::move(d));
        job.created = planned.take();
        rules = rulesWithCreated(influences, job.created);
    }
    auto resolved = skin::resolveInfluences(*merged, bones, names, rules);
    if (!resolved)
        return Out::failure(resolved.takeDiagnostics());
    for (Diagnostic& d : resolved.takeDiagnostics())
        job.notes.push_back(std::move(d));
    markCreated(*resolved, job.created);
    job.chunks = skin::applyInfluences(merged.take(), *resolved, bones, names);
    job.influences = resolved.take();
    job.options = std::move(options);
    for (auto& [index, vertices] : *meshes) {
        std::sort(vertices.begin(), vertices.end());
        const CharacterMesh& m = m_characterMeshes[index];
        if (!vertices.empty() && !m.weights)
            return Out::failure(meshError(m_models[m.model].path, m.data(m_models).name,
                                          "only some of its vertices are selected but it has no applied weights for the others: "
                                          "import onto the whole mesh"));
        job.targets.push_back({index, m_models[m.model].model, &m.data(m_models), std::move(vertices)});
    }
    if (job.targets.empty())
        return Out::refused("the guide has no mesh to import weights onto: Guide > Add Model first");
    return job;
}

Status SkinImportJob::run()
{
    std::vector<const model::Mesh*> meshes;
    for (const Target& t : targets)
        meshes.push_back(t.mesh);
    reports.clear();
    weights.clear();
    auto imported = skin::importChunks(chunks, meshes, options, &reports);
    if (!imported) {
        Diagnostics why = imported.takeDiagnostics();
        if (why.empty())
            why.push_back(makeError({}, "the import was cancelled; nothing changed"));
        return Status::failure(std::move(why));
    }
    Diagnostics notes = imported.takeDiagnostics();
    weights = imported.take();
    return Status::success(std::move(notes));
}

std::vector<VertexRoute> vertexRoutes(const skin::MeshImportReport& r, std::size_t count, const std::vector<std::uint32_t>* oneToOne)
{
    if (r.route == skin::ImportRoute::SingleInfluence)
        return std::vector<VertexRoute>(count, VertexRoute::SingleInfluence);
    std::vector<VertexRoute> out(count, VertexRoute::Transferred);
    if (r.route == skin::ImportRoute::OneToOne) {
        if (!oneToOne)
            std::fill(out.begin(), out.end(), VertexRoute::OneToOne);
        else
            for (std::uint32_t id : *oneToOne)
                if (id < count)
                    out[id] = VertexRoute::OneToOne;
    }
    for (std::uint32_t v : r.inpaintedVertices)
        if (v < count)
            out[v] = VertexRoute::Inpainted;
    return out;
}

std::vector<VertexRoute> SkinImportJob::routes(std::size_t t) const
{
    if (t >= reports.size() || t >= targets.size())
        return {};
    const skin::MeshImportReport& r = reports[t];
    const std::vector<std::uint32_t> none;
    const std::vector<std::uint32_t>* ids = &none;
    for (const skin::SkinChunk& c : chunks)
        if (c.mesh == r.source)
            ids = &c.vertexIds;
    return vertexRoutes(r, targets[t].mesh->vertexCount(), ids);
}

Result<std::vector<skin::MeshImportReport>> Session::applySkinImport(SkinImportJob job, const std::string& what)
{
    using Out = Result<std::vector<skin::MeshImportReport>>;
    if (job.weights.size() != job.targets.size())
        return Out::refused("the import has not run");
    std::vector<model::MeshBinding> records;
    for (std::size_t t = 0; t < job.targets.size(); ++t) {
        const SkinImportJob::Target& target = job.targets[t];
        const CharacterMesh* m = target.characterMesh < m_characterMeshes.size() ? &m_characterMeshes[target.characterMesh] : nullptr;
        if (!m || m_models[m->model].model != target.model || &m->data(m_models) != target.mesh)
            return Out::refused("the guide's models changed while the weights were imported; nothing changed: import again");
        model::MeshWeights weights = std::move(job.weights[t]);
        std::vector<std::uint32_t> written = target.vertices;
        if (job.append && t < job.reports.size() && m->binding >= 0 && m->weights) {
            const std::size_t n = target.mesh->vertexCount();
            const std::vector<bool> write =
                skin::writtenVertices(job.chunks, job.reports[t], n, {target.vertices.empty() ? nullptr : &target.vertices, true});
            const std::size_t count = std::size_t(std::count(write.begin(), write.end(), true));
            if (count < n) {
                written.clear();
                for (std::uint32_t v = 0; v < n; ++v)
                    if (write[v])
                        written.push_back(v);
                Diagnostic kept = makeWarning({m_models[m->model].path, 0, 0}, "mesh '" + target.mesh->name + "': appended: " +
                                                                                 std::to_string(count) + " vertices written, " +
                                                                                 std::to_string(n - count) + " kept their weights");
                kept.severity = Severity::Note;
                kept.subject = Subject::ofMesh(target.mesh->name);
                job.notes.push_back(std::move(kept));
            }
        }
        if (!written.empty()) {
            if (m->binding < 0 || !m->weights)
                return Out::refused("mesh '" + target.mesh->name + "' lost its weights while importing; nothing changed");
            weights = mergeVertices(m_document.bindings[std::size_t(m->binding)].weights, weights, written);
        }
        records.push_back({m_models[m->model].path, target.mesh->name, target.mesh->vertexCount(), model::topologyFingerprint(*target.mesh),
                           std::move(weights)});
    }
    if (!job.created.empty()) { // the created joints and the weights: one undo step
        if (m_history.inTransaction())
            return Out::refused("finish the edit in progress before importing weights that create joints; nothing changed");
        m_history.begin(what);
        if (const Status added = addCreatedInstances(m_history, job.created); added.failed()) {
            m_history.rollback();
            return Out::failure(added.diagnostics());
        }
    }
    const Status set = setBindings(std::move(records), what);
    if (!job.created.empty()) {
        if (set.failed())
            m_history.rollback();
        else
            m_history.commit(what);
    }
    if (set.failed())
        return Out::failure(set.diagnostics());
    Diagnostics notes = std::move(job.notes);
    notes.insert(notes.end(), set.diagnostics().begin(), set.diagnostics().end());
    return Out(std::move(job.reports), std::move(notes));
}

Result<std::vector<skin::MeshImportReport>> Session::importSkinChunks(std::vector<skin::SkinChunk> chunks, skin::TransferOptions options,
                                                                     const SkinScope& onto, const skin::InfluenceMapOptions& influences,
                                                                     const std::string& what)
{
    using Out = Result<std::vector<skin::MeshImportReport>>;
    auto job = prepareSkinImport(std::move(chunks), std::move(options), onto, influences);
    if (!job)
        return Out::failure(job.takeDiagnostics());
    const Status ran = job->run();
    if (ran.failed())
        return Out::failure(ran.diagnostics());
    return applySkinImport(job.take(), what);
}

} // namespace rs::session
