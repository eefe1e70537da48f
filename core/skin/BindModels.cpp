#include "skin/BindModels.h"

#include <chrono>

namespace rs::skin {

Result<std::vector<model::MeshBinding>> bindModels(const std::vector<ModelToBind>& models, const std::vector<SkinBone>& bones,
                                                   BindOptions options, std::vector<MeshBindReport>* reports)
{
    using Out = Result<std::vector<model::MeshBinding>>;
    double total = 0.0;
    for (const ModelToBind& m : models)
        if (m.model)
            for (const model::Mesh& mesh : m.model->meshes)
                total += double(mesh.vertexCount());
    if (total <= 0.0)
        return Out::failure(makeError({}, "there is no mesh to bind: add a model with vertices first"));
    const auto progress = std::move(options.progress);
    Diagnostics notes;
    std::vector<model::MeshBinding> out;
    double done = 0.0;
    for (const ModelToBind& m : models) {
        if (!m.model)
            continue;
        for (const model::Mesh& mesh : m.model->meshes) {
            const double share = double(mesh.vertexCount());
            if (progress)
                options.progress = [&](double fraction) { return progress((done + fraction * share) / total); };
            options.occluders.clear();
            for (const model::Mesh& other : m.model->meshes)
                if (&other != &mesh)
                    options.occluders.push_back(&other);
            const auto start = std::chrono::steady_clock::now();
            BindStats stats;
            auto weights = bindMesh(mesh, bones, options, &stats);
            notes.insert(notes.end(), weights.diagnostics().begin(), weights.diagnostics().end());
            if (!weights)
                return Out::failure(std::move(notes));
            if (reports)
                reports->push_back({m.path, mesh.name, stats,
                                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count()});
            out.push_back({m.path, mesh.name, mesh.vertexCount(), model::topologyFingerprint(mesh), weights.take()});
            done += share;
        }
    }
    if (progress && !progress(1.0))
        return Out::failure(makeError({}, "binding was cancelled; the previous weights are kept"));
    return Out(std::move(out), std::move(notes));
}

} // namespace rs::skin
