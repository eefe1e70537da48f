#include "io/ReferenceModel.h"

#include "io/ModelImport.h"

namespace rs::io {

// The character model reader's meshes, flattened to world-space triangles.
Result<ReferenceModel> loadReferenceModel(const std::string& path)
{
    auto model = importModel(path);
    if (!model)
        return Result<ReferenceModel>::failure(model.takeDiagnostics());
    ReferenceModel out;
    out.lo = glm::dvec3(1e300);
    out.hi = glm::dvec3(-1e300);
    for (const model::Mesh& mesh : model->meshes)
        for (std::uint32_t index : mesh.indices) {
            if (index >= mesh.positions.size())
                continue;
            const glm::vec3& p = mesh.positions[index];
            out.lo = glm::min(out.lo, glm::dvec3(p));
            out.hi = glm::max(out.hi, glm::dvec3(p));
            out.triangles.push_back(p);
        }
    if (out.triangles.empty())
        return Result<ReferenceModel>::failure(makeError({path, 0, 0}, "the file has no triangles to show"));
    return out;
}

} // namespace rs::io
