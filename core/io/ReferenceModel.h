#pragma once
// A reference model for placing guides: a character model (io/ModelImport.h:
// any mesh file Assimp reads), flattened to world-space triangles in the
// document's convention (Y-up, metres). FBX files say their unit and up axis in their header; Z-up
// centimetre files (Unreal's) come in standing and metre-sized. Display only:
// the guide keeps the file's path (`reference_model:`, relative to the guide)
// and the editor loads it again on open; its triangles are never saved.
#include "base/Result.h"

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace rs::io {

struct ReferenceModel {
    std::vector<glm::vec3> triangles; // three points per triangle
    glm::dvec3 lo{0.0}, hi{0.0};       // bounds
};

// Fails with the reader's message (file as location) on a missing, unreadable
// or mesh-less file.
Result<ReferenceModel> loadReferenceModel(const std::string& path);

} // namespace rs::io
