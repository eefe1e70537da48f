#pragma once
// Character models from any format Assimp reads (OBJ, FBX, glTF/GLB, Collada,
// ...): every mesh with its name, triangles in the file's vertex order, node
// transforms applied, normals, UVs and materials; FBX units and up axis turned
// into the guide's convention (an FBX in centimetres arrives in metres, Z-up
// stands up). Assimp stays in this file.
#include "base/Result.h"
#include "model/Mesh.h"

#include <string>

namespace rs::io {

// Fails with the reader's message (the file as location) on a missing,
// unreadable or triangle-less file.
Result<model::Model> importModel(const std::string& path);

} // namespace rs::io
