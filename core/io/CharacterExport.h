#pragma once
// The character an export carries (issue 19): the guide's models' meshes,
// their skin weights moved onto the rig's skin joints, as io::SkinnedMesh
// (joint indices into model::extractSkeleton(rig), the skeleton prepareExport
// starts from, so presets that rename joints or add a root keep them) and
// their materials with the base colour texture's image read.
//
// Meshes pair with the guide's weight records as the session pairs them: the
// n-th mesh of a name in a model with the n-th record of that model and name.
// What a professional tool refuses to export silently is an error here, naming
// the mesh and its model: a mesh without weights, a mesh changed since it was
// bound (its weights no longer apply 1:1), a model that could not be read.
// Such meshes are still in `meshes`, rigid on the skeleton's root joint, so an
// export forced past the errors (ExportRequest::force) stays a valid file.
// A record whose mesh is gone is a warning (the weights stay in the guide);
// a texture that cannot be read is a warning and its material has none. A
// texture is the file the model names (relative to the model's folder) or,
// when there is no such file, the image the model file embeds under that name
// (a .zae, .glb or .fbx with embedded media: the model is read again for its
// images, once per model and export).
#include "base/Diagnostic.h"
#include "io/ExportScene.h"
#include "model/Mesh.h"
#include "model/Rig.h"

#include <string>
#include <vector>

namespace rs::io {

// One of the guide's models as read (io::importModel); `model` null when the
// file could not be read.
struct CharacterModel {
    std::string path; // as in GuideDocument::models (absolute)
    const model::Model* model = nullptr;
};

struct CharacterExport {
    std::vector<SkinnedMesh> meshes;
    std::vector<ExportMaterial> materials; // SkinnedMesh::material indexes these
    Diagnostics problems;                  // errors refuse the export unless forced
};

CharacterExport characterExport(const model::Rig& rig, const std::vector<model::MeshBinding>& bindings,
                                const std::vector<CharacterModel>& models);

// "image/png" or "image/jpeg" from the image's first bytes; empty otherwise.
std::string imageMimeType(const std::string& bytes);

} // namespace rs::io
