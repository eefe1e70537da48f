#pragma once
// glTF 2.0 writer (.glb, or .gltf + .bin) with tinygltf, following
// ../shared/reference/export-facts.md §6.1: one skin whose `skeleton` is the
// root joint, inverse bind matrices = inverse(joint bind world), node TRS = the
// scene's pose; skinned meshes at the scene root with identity transforms and
// bind-space vertices, NORMAL, TEXCOORD_0 (V flipped: glTF's origin is the
// image's top-left), one material each (pbrMetallicRoughness: base colour
// factor and texture, not metallic), JOINTS_0 (u8, or u16 past 256 joints) / WEIGHTS_0
// (float, normalised, at most 4); every bufferView 4-byte aligned, vertex and
// index views with their targets, min/max on positions and clip times;
// controllers as plain nodes tagged {"rig": {"kind": "controller", ...}} in
// extras; cameras (ExportScene::cameras) as scene-root nodes with a
// perspective camera, tagged {"rig": {"kind": "camera", ...}}; clips as LINEAR
// samplers in seconds (CUBICSPLINE for keyed clips). glTF is metres, Y-up.
// Texture images (PNG or JPEG; other formats are left out with a warning) go
// into the buffer through a bufferView, in .glb and .gltf alike: the .gltf's
// .bin carries them, so the pair is the whole export, written atomically, and
// nothing is copied beside it.
#include "base/Diagnostic.h"
#include "io/ExportScene.h"

#include <string>

namespace rs::io {

// The format follows the extension (.glb binary, anything else text + .bin).
Diagnostics writeGltf(const ExportScene& scene, const std::string& path, const std::string& generator);

} // namespace rs::io
