#pragma once
// glTF 2.0 export (.glb or .gltf + .bin) with tinygltf, following
// ../shared/reference/export-facts.md §6.1: one skin whose `skeleton` is the root
// joint, inverse bind matrices = inverse(joint bind world), node TRS = bind pose.
#include "base/Diagnostic.h"
#include "io/ExportCheck.h"
#include "io/NameMap.h"
#include "model/Rig.h"

#include <string>

namespace rs::io {

struct GltfExportOptions {
    std::string generator = "Rigsmith";
    const NameMap* names = nullptr; // export names (io/NameMap.h), applied before the validator
    bool fixNames = false;  // apply the validator's safe renames (io/ExportCheck.h)
    bool force = false;     // write even when the validator finds errors (they come back as warnings)
};

// The format follows the extension (.glb binary, .gltf text). The validator
// (io/ExportCheck.h) runs first: its errors refuse the export (nothing written)
// unless forced. Also fails when the rig has no single-rooted skeleton or I/O fails.
Diagnostics exportGltf(const model::Rig& rig, const std::string& path, const GltfExportOptions& options = {});

} // namespace rs::io
