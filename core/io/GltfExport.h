#pragma once
// glTF 2.0 export (.glb or .gltf + .bin) with tinygltf, following
// ../shared/reference/export-facts.md §6.1: one skin whose `skeleton` is the root
// joint, inverse bind matrices = inverse(joint bind world), node TRS = bind pose.
#include "base/Diagnostic.h"
#include "model/Rig.h"

#include <string>

namespace rs::io {

struct GltfExportOptions {
    std::string generator = "Rigsmith";
};

// The format follows the extension (.glb binary, .gltf text). Returns errors
// (nothing written) when the rig has no single-rooted skeleton or I/O fails.
Diagnostics exportGltf(const model::Rig& rig, const std::string& path, const GltfExportOptions& options = {});

} // namespace rs::io
