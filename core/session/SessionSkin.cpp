// The character: the guide's models, their meshes and skin weights on the
// built rig, and the palette they skin with.
#include "session/Session.h"

#include "skin/Retarget.h"

#include <algorithm>
#include <filesystem>

namespace rs::session {

namespace {

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

bool sameKeys(const std::vector<skin::SkinBone>& a, const std::vector<skin::SkinBone>& b)
{
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const skin::SkinBone& x, const skin::SkinBone& y) { return x.key == y.key && x.parent == y.parent; });
}

} // namespace

void Session::setModelLoader(ModelLoader loader)
{
    m_modelLoader = std::move(loader);
    m_models.clear();
    followCharacter(Change::of(ChangeKind::Models));
}

void Session::followCharacter(const Change& change)
{
    const bool models = change.hasAny(ChangeKind::Document | ChangeKind::Models);
    if (models) {
        loadModels();
        m_surfaces.clear(); // keyed by mesh address: a reloaded model may reuse one
        m_selectedVertices.clear();
    }
    if (models || change.hasAny(ChangeKind::Rig | ChangeKind::Weights)) {
        std::vector<skin::SkinBone> bones;
        if (m_rig)
            if (auto found = skin::skinBones(*m_rig))
                bones = found.take();
        const bool bonesChanged = !sameKeys(bones, m_skinBones);
        m_skinBones = std::move(bones);
        m_bindInverse.clear();
        for (const skin::SkinBone& bone : m_skinBones)
            m_bindInverse.push_back(glm::inverse(m_rig->nodes[bone.node].worldMatrix));
        if (models || bonesChanged)
            matchMeshes();
        else if (change.has(ChangeKind::Weights))
            matchMeshes(change.bindings.empty() ? nullptr : &change.bindings); // a weight edit: only its meshes again
    }
    if (models || change.hasAny(ChangeKind::Rig | ChangeKind::Evaluation | ChangeKind::Weights))
        updatePalette();
}

void Session::loadModels()
{
    std::vector<LoadedModel> loaded;
    Diagnostics problems;
    for (const std::string& path : m_document.models) {
        auto known = std::find_if(m_models.begin(), m_models.end(), [&](const LoadedModel& m) { return m.path == path; });
        if (known != m_models.end()) {
            loaded.push_back(std::move(*known));
            continue;
        }
        LoadedModel model{path, nullptr, {}};
        if (!m_modelLoader) {
            model.problems.push_back(makeError({path, 0, 0}, "this program cannot read model files"));
        } else {
            auto read = m_modelLoader(path);
            model.problems = read.takeDiagnostics();
            if (read)
                model.model = std::make_shared<const model::Model>(read.take());
            else
                model.problems.insert(model.problems.begin(),
                                      makeError({path, 0, 0}, "the guide's model " + fileName(path) +
                                                                  " could not be read; the guide keeps it and its weights"));
        }
        problems.insert(problems.end(), model.problems.begin(), model.problems.end());
        loaded.push_back(std::move(model));
    }
    m_models = std::move(loaded);
    report(problems);
}

// Pairs every mesh with its binding (the n-th mesh of a name with the n-th
// record of it) and carries the weights onto the skin bones. Reports what
// does not apply: a changed mesh, a record without its mesh, a gone joint.
void Session::matchMeshes(const std::vector<std::size_t>* only)
{
    // Only some bindings changed (a weight edit): carry just their weights
    // again, unless a binding is new to a mesh or its weights bring a message
    // (a gone joint): then everything is paired and reported again.
    if (only && !m_skinBones.empty()) {
        std::vector<std::pair<CharacterMesh*, model::MeshWeights>> updated;
        bool whole = false;
        for (std::size_t b : *only) {
            auto mesh = std::find_if(m_characterMeshes.begin(), m_characterMeshes.end(),
                                     [&](const CharacterMesh& m) { return m.binding == int(b); });
            if (mesh == m_characterMeshes.end() || b >= m_document.bindings.size()) {
                whole = true;
                break;
            }
            if (mesh->changed || !model::bindingFits(m_document.bindings[b], mesh->data(m_models))) {
                // A re-fit, an import or its undo changes whether it fits: pair it anew.
                whole = true;
                break;
            }
            auto retargeted = skin::retargetWeights(m_document.bindings[b].weights, m_skinBones, m_document.bindings[b].mesh);
            if (!retargeted || !retargeted.diagnostics().empty()) {
                whole = true;
                break;
            }
            updated.emplace_back(&*mesh, retargeted.take());
        }
        if (!whole) {
            for (auto& [mesh, weights] : updated)
                mesh->weights = std::make_shared<const model::MeshWeights>(std::move(weights));
            return;
        }
    }
    m_characterMeshes.clear();
    Diagnostics notes;
    std::vector<bool> used(m_document.bindings.size(), false);
    std::vector<std::string> paths;
    std::vector<const model::Model*> read;
    for (const LoadedModel& loaded : m_models) {
        paths.push_back(loaded.path);
        read.push_back(loaded.model.get());
    }
    const auto pairs = model::pairBindings(paths, read, m_document.bindings);
    for (std::size_t m = 0; m < m_models.size(); ++m) {
        const LoadedModel& loaded = m_models[m];
        if (!loaded.model)
            continue;
        for (std::size_t i = 0; i < loaded.model->meshes.size(); ++i) {
            const model::Mesh& mesh = loaded.model->meshes[i];
            CharacterMesh out;
            out.model = m;
            out.mesh = i;
            out.binding = pairs[m][i];
            if (out.binding >= 0) {
                used[std::size_t(out.binding)] = true;
                const model::MeshBinding& binding = m_document.bindings[std::size_t(out.binding)];
                out.changed = !model::bindingFits(binding, mesh);
                if (out.changed) {
                    Diagnostic d = makeWarning({loaded.path, 0, 0},
                                               "mesh '" + mesh.name + "' changed since it was bound (" + std::to_string(binding.vertexCount) +
                                                   " vertices then, " + std::to_string(mesh.vertexCount()) +
                                                   (binding.vertexCount == mesh.vertexCount() ? " now, other triangles" : " now") +
                                                   "): its weights are kept but not applied; " +
                                                   (previousChunk(binding) ? "the next open, reload or build re-fits them" : "bind it again"));
                    d.subject = Subject::ofMesh(mesh.name);
                    notes.push_back(std::move(d));
                } else if (!m_skinBones.empty()) {
                    auto retargeted = skin::retargetWeights(binding.weights, m_skinBones, mesh.name);
                    notes.insert(notes.end(), retargeted.diagnostics().begin(), retargeted.diagnostics().end());
                    if (retargeted)
                        out.weights = std::make_shared<const model::MeshWeights>(retargeted.take());
                }
            }
            m_characterMeshes.push_back(std::move(out));
        }
    }
    for (std::size_t b = 0; b < m_document.bindings.size(); ++b) {
        if (used[b])
            continue;
        const model::MeshBinding& binding = m_document.bindings[b];
        const bool modelThere = std::any_of(m_models.begin(), m_models.end(),
                                            [&](const LoadedModel& m) { return m.path == binding.model && m.model; });
        if (!modelThere && std::any_of(m_models.begin(), m_models.end(), [&](const LoadedModel& m) { return m.path == binding.model; }))
            continue; // the model could not be read: said when it was loaded
        Diagnostic d = makeWarning({binding.model, 0, 0},
                                   "the weights of mesh '" + binding.mesh + "' match no mesh (" +
                                       (modelThere ? fileName(binding.model) + " has no such mesh now" : "the guide has no model " + fileName(binding.model)) +
                                       "); they are kept");
        d.subject = Subject::ofMesh(binding.mesh);
        notes.push_back(std::move(d));
    }
    const std::string text = formatAll(notes);
    if (text != m_reportedCharacter) {
        m_reportedCharacter = text;
        report(notes);
    }
}

void Session::updatePalette()
{
    m_skinPalette.assign(m_skinBones.size(), Mat4(1.0));
    if (!m_program)
        return;
    for (std::size_t b = 0; b < m_skinBones.size(); ++b)
        m_skinPalette[b] = m_evaluation.worldMatrix(m_skinBones[b].node) * m_bindInverse[b];
}

Status Session::addModel(const std::string& given)
{
    if (given.empty())
        return Status::refused("no model file given");
    const std::string path = std::filesystem::absolute(given).lexically_normal().string();
    if (std::find(m_document.models.begin(), m_document.models.end(), path) != m_document.models.end())
        return Status::refused(given + " is already one of the guide's models", Subject::ofFile(path));
    if (!m_modelLoader)
        return Status::failure({makeError({path, 0, 0}, "this program cannot read model files")});
    auto read = m_modelLoader(path);
    if (!read)
        return Status::failure(read.takeDiagnostics());
    Diagnostics warnings = read.takeDiagnostics();
    m_models.push_back({path, std::make_shared<const model::Model>(read.take()), warnings});
    Status added = edit::addModel(m_history, path);
    if (added.failed())
        return added;
    return Status::success(std::move(warnings));
}

Status Session::removeModel(const std::string& path) { return edit::removeModel(m_history, path); }

Status Session::reloadModel(const std::string& path)
{
    auto known = std::find_if(m_models.begin(), m_models.end(), [&](const LoadedModel& m) { return m.path == path; });
    if (known == m_models.end())
        return Status::refused(path + " is not one of the guide's models", Subject::ofFile(path));
    if (!m_modelLoader)
        return Status::failure({makeError({path, 0, 0}, "this program cannot read model files")});
    auto read = m_modelLoader(path);
    if (!read)
        return Status::failure(read.takeDiagnostics()); // the model as it was stays
    rememberChunks(*known); // the meshes as bound, to re-fit the changed ones from
    known->problems = read.takeDiagnostics();
    known->model = std::make_shared<const model::Model>(read.take());
    const Diagnostics warnings = known->problems;
    m_reportedCharacter.clear(); // say again what does not fit the reloaded meshes
    emitChange(Change::of(ChangeKind::Models));
    refitChangedMeshes();
    return Status::success(warnings);
}

Status Session::setBindings(std::vector<model::MeshBinding> bindings, const std::string& what)
{
    return edit::setBindings(m_history, std::move(bindings), what);
}

Status Session::setVertexWeights(edit::WeightEdit edit, const std::string& what)
{
    return edit::setVertexWeights(m_history, std::move(edit), what);
}

void Session::beginWeightStroke(const std::string& what) { m_history.begin(what); }

void Session::endWeightStroke() { m_history.commit(); }

} // namespace rs::session
