#pragma once
// Binding a character: every mesh of its models bound to the rig's skin
// joints, each mesh hidden by the model's other meshes (the eyes inside a
// closed head take their closest bone). One job for the editor's worker thread
// and the CLI: it reads only what it is given (shared, immutable models).
#include "model/Mesh.h"
#include "skin/AutoWeights.h"

#include <memory>
#include <string>
#include <vector>

namespace rs::skin {

struct ModelToBind {
    std::string path; // as in GuideDocument::models (the binding records carry it)
    std::shared_ptr<const model::Model> model;
};

struct MeshBindReport {
    std::string model, mesh;
    BindStats stats;
    double milliseconds = 0.0;
};

// Binds every mesh; `options.progress` hears the fraction of all vertices done
// and may cancel (then nothing is returned: the caller keeps its weights).
// `options.occluders` is ignored: each mesh's occluders are its model's other
// meshes. Notes name the parts that fell back to their closest bone.
Result<std::vector<model::MeshBinding>> bindModels(const std::vector<ModelToBind>& models, const std::vector<SkinBone>& bones,
                                                   BindOptions options, std::vector<MeshBindReport>* reports = nullptr);

} // namespace rs::skin
