#pragma once
// Binary FBX writer: Assimp 5.2.5's exporter with the rules of
// ../shared/reference/export-facts.md §6.2: exported through memory and repaired
// (io/FbxRepair.h), nodes in bind pose (a current pose goes into a one-key
// `pose` take), ticks per second 1 with times in seconds, units and axes
// declared in the scene metadata (UnitScaleFactor = centimetres per unit, UpAxis).
// Never ASCII. Assimp writes joints as skeleton limbs only when a mesh's bones
// name them, so every joint is a bone of each mesh (zero weights where unused);
// without meshes the joints come out as null nodes (a warning says so).
// Controllers are plain null nodes (Assimp 5.2.5 writes no custom properties).
// Meshes carry normals, UVs (LayerElementUV) and their materials (diffuse
// colour; the base colour image embedded as the Video's Content, named by its
// file name).
#include "base/Diagnostic.h"
#include "base/Result.h"
#include "io/ExportScene.h"

#include <string>

namespace rs::io {

// What Assimp 5.2.5 writes for `scene`, before the repair (for tests and checks).
Result<std::string> assimpFbxBytes(const ExportScene& scene, const Convention& convention);
// `scene` in the file's convention (converted()); `convention` is declared.
Diagnostics writeFbx(const ExportScene& scene, const std::string& path, const Convention& convention);

} // namespace rs::io
