// Re-fitting a binding whose mesh changed topology (issue 20 item 5): the
// previous mesh (a chunk: bind positions, triangles) with the binding's own
// weights is imported onto the new mesh by the decision tree, as one undo step.
#include "session/Session.h"

#include "skin/Refit.h"

#include <algorithm>
#include <chrono>
#include <filesystem>

namespace rs::session {

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

std::optional<RefitJob> Session::prepareRefit() const
{
    if (m_history.inTransaction())
        return std::nullopt;
    RefitJob job;
    for (const CharacterMesh& m : m_characterMeshes) {
        if (!m.changed)
            continue;
        const model::MeshBinding& was = m_document.bindings[std::size_t(m.binding)];
        const skin::SkinChunk* previous = previousChunk(was);
        if (!previous)
            continue; // reported by matchMeshes: kept, not applied
        job.items.push_back({was, *previous, m_models[m.model].model, &m.data(m_models)});
    }
    if (job.items.empty())
        return std::nullopt;
    job.rig = m_rig ? std::make_shared<const model::Rig>(*m_rig) : nullptr;
    job.options = m_refitOptions;
    job.revision = m_revision;
    return job;
}

Status RefitJob::run()
{
    refits.clear();
    notes.clear();
    for (const Item& item : items) {
        auto refit = skin::refitBinding(item.was, item.previous, *item.mesh, rig.get(), options);
        if (!refit) {
            if (refit.diagnostics().empty()) // cancelled (options.progress), not failed
                return Status::refused("the re-fit was cancelled; nothing changed");
            Diagnostic d = makeWarning({item.was.model, 0, 0}, "mesh '" + item.mesh->name + "' could not be re-fitted (" +
                                                                   formatAll(refit.diagnostics()) + "): its weights are kept but not applied");
            d.subject = Subject::ofMesh(item.mesh->name);
            notes.push_back(std::move(d));
            refits.emplace_back();
            continue;
        }
        refit->note.message += "; undo brings the previous weights back";
        refits.push_back(refit.take());
    }
    return Status::success();
}

std::vector<VertexRoute> RefitJob::routes(std::size_t i) const
{
    if (i >= refits.size() || !refits[i])
        return {};
    return vertexRoutes(refits[i]->report, items[i].mesh->vertexCount()); // the previous chunk covers the whole mesh
}

Result<std::vector<skin::MeshImportReport>> Session::applyRefit(RefitJob job)
{
    using Out = Result<std::vector<skin::MeshImportReport>>;
    if (!isCurrent(job))
        return Out::refused("the guide changed while its meshes were re-fitted; the result is stale");
    if (job.refits.size() != job.items.size())
        return Out::refused("the re-fit has not run");
    std::vector<model::MeshBinding> records;
    std::vector<skin::MeshImportReport> reports;
    Diagnostics notes = std::move(job.notes);
    for (std::optional<skin::Refit>& refit : job.refits)
        if (refit) {
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
    return Out(std::move(reports));
}

std::vector<skin::MeshImportReport> Session::refitChangedMeshes()
{
    std::optional<RefitJob> job = prepareRefit();
    if (!job)
        return {};
    if (m_refitRunner) { // the host runs it (the editor: on a worker thread) and applies it later
        m_refitRunner(std::move(*job));
        return {};
    }
    job->run();
    auto applied = applyRefit(std::move(*job));
    return applied ? applied.take() : std::vector<skin::MeshImportReport>{};
}

} // namespace rs::session
