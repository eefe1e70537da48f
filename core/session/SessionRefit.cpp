// Re-fitting a binding whose mesh changed topology (issue 20 item 5): the
// previous mesh (a chunk: bind positions, triangles) with the binding's own
// weights is imported onto the new mesh by the decision tree, as one undo step.
#include "session/Session.h"

#include "skin/Refit.h"

#include <algorithm>
#include <chrono>
#include <filesystem>

namespace rs::session {


skin::TransferOptions Session::defaultRefitOptions() { return skin::defaultRefitOptions(); }

const skin::SkinChunk* Session::previousChunk(const model::MeshBinding& binding) const
{
    return skin::previousChunk(m_savedChunks, binding);
}

void Session::rememberChunks(const LoadedModel& model)
{
    for (const CharacterMesh& m : m_characterMeshes) {
        if (m.binding < 0 || m.changed || m_models[m.model].path != model.path || !model.model)
            continue;
        const model::MeshBinding& b = m_document.bindings[std::size_t(m.binding)];
        std::erase_if(m_savedChunks, [&](const skin::SkinChunk& c) { return skin::chunkDescribes(c, b); });
        m_savedChunks.push_back(skin::bindingChunk(b, m.data(m_models), rig()));
    }
}

std::vector<skin::SkinChunk> Session::bindingChunks() const
{
    std::vector<skin::SkinChunk> out;
    std::vector<bool> covered(m_document.bindings.size(), false);
    for (const CharacterMesh& m : m_characterMeshes)
        if (m.binding >= 0 && !m.changed) {
            covered[std::size_t(m.binding)] = true;
            out.push_back(skin::bindingChunk(m_document.bindings[std::size_t(m.binding)], m.data(m_models), rig()));
        }
    for (std::size_t b = 0; b < covered.size(); ++b)
        if (!covered[b])
            if (const skin::SkinChunk* kept = previousChunk(m_document.bindings[b])) {
                out.push_back(*kept);
                skin::putBindingWeights(out.back(), m_document.bindings[b], rig());
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
        const model::Mesh& mesh = m.data(m_models);
        auto refit = skin::refitBinding(was, *previous, mesh, rig(), m_refitOptions);
        if (!refit) {
            Diagnostic d = makeWarning({was.model, 0, 0}, "mesh '" + mesh.name + "' could not be re-fitted (" + formatAll(refit.diagnostics()) +
                                                              "): its weights are kept but not applied");
            d.subject = Subject::ofMesh(mesh.name);
            notes.push_back(std::move(d));
            continue;
        }
        refit->note.message += "; undo brings the previous weights back";
        notes.push_back(std::move(refit->note));
        records.push_back(std::move(refit->binding));
        reports.push_back(std::move(refit->report));
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
