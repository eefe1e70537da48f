#include "io/ReferenceModel.h"

#include "base/Math.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <filesystem>

namespace rs::io {

namespace {

// FBX: metres per file unit and whether Z is up, from the header Assimp keeps as metadata.
void fbxConvention(const aiScene& scene, double& metresPerUnit, bool& zUp)
{
    if (!scene.mMetaData)
        return;
    double unitScale = 0.0; // centimetres per unit
    if (scene.mMetaData->Get("UnitScaleFactor", unitScale) && unitScale > 0.0)
        metresPerUnit = metresPerFbxUnit(unitScale);
    else if (float f = 0.0f; scene.mMetaData->Get("UnitScaleFactor", f) && f > 0.0f)
        metresPerUnit = metresPerFbxUnit(f);
    int upAxis = 1;
    if (scene.mMetaData->Get("UpAxis", upAxis))
        zUp = upAxis == 2;
}

} // namespace

Result<ReferenceModel> loadReferenceModel(const std::string& path)
{
    const SourceLocation where{path, 0, 0};
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return Result<ReferenceModel>::failure(makeError(where, "no such file"));
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_PreTransformVertices | aiProcess_SortByPType);
    if (!scene)
        return Result<ReferenceModel>::failure(makeError(where, std::string("cannot read the model: ") + importer.GetErrorString()));
    double metresPerUnit = 1.0;
    bool zUp = false;
    const std::string extension = std::filesystem::path(path).extension().string();
    if (extension == ".fbx" || extension == ".FBX")
        fbxConvention(*scene, metresPerUnit, zUp);

    ReferenceModel model;
    model.lo = glm::dvec3(1e300);
    model.hi = glm::dvec3(-1e300);
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* mesh = scene->mMeshes[m];
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices != 3)
                continue; // points and lines
            for (unsigned k = 0; k < 3; ++k) {
                const aiVector3D& v = mesh->mVertices[face.mIndices[k]];
                glm::dvec3 p = zUp ? glm::dvec3(v.x, v.z, -v.y) : glm::dvec3(v.x, v.y, v.z);
                p *= metresPerUnit;
                model.lo = glm::min(model.lo, p);
                model.hi = glm::max(model.hi, p);
                model.triangles.emplace_back(p);
            }
        }
    }
    if (model.triangles.empty())
        return Result<ReferenceModel>::failure(makeError(where, "the file has no triangles to show"));
    return model;
}

} // namespace rs::io
