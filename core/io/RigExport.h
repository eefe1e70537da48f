#pragma once
// Exports a built rig for engines (issue 6): .glb, .gltf (+ .bin) or binary
// .fbx, by the path's extension. Runs io::prepareExport (skeleton, preset,
// validator, options) and the format's writer in the preset's convention.
// Returns the validator's report and any failure; on errors (unless forced),
// cancellation or failure nothing is written.
#include "base/Diagnostic.h"
#include "io/ExportScene.h"

#include <optional>
#include <string>

namespace rs::io {

enum class ExportFormat { Glb, Gltf, Fbx };
std::optional<ExportFormat> exportFormatOf(const std::string& path);

Diagnostics exportRig(const model::Rig& rig, const std::string& path, const ExportOptions& options = {});

} // namespace rs::io
