#pragma once
// Character models from any format Assimp reads (OBJ, FBX, glTF/GLB, Collada,
// ...): every mesh with its name, triangles in the file's vertex order, node
// transforms applied, normals, UVs and materials; FBX units and up axis turned
// into the guide's convention (an FBX in centimetres arrives in metres, Z-up
// stands up), and a skinned mesh's per-vertex weights on the file's
// skeleton (model::FileWeights, Model::joints). Assimp stays in this file.
#include "base/Result.h"
#include "model/Mesh.h"

#include <map>
#include <string>

namespace rs::io {

// Fails with the reader's message (the file as location) on a missing,
// unreadable or triangle-less file.
Result<model::Model> importModel(const std::string& path);

// The images a model file embeds (a .zae's media, a .glb's images, an FBX's
// video content), by the name its materials use for them (Material::texture,
// e.g. "./textures/skin.png", or "*0"), as file bytes (PNG, JPEG...). Images
// Assimp decoded to raw texels are left out. Empty for a file without any.
Result<std::map<std::string, std::string>> readEmbeddedImages(const std::string& path);

} // namespace rs::io
