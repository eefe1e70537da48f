#include "io/RigExport.h"

#include "io/FbxExport.h"
#include "io/GltfExport.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace rs::io {

std::optional<ExportFormat> exportFormatOf(const std::string& path)
{
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    if (extension == ".glb") return ExportFormat::Glb;
    if (extension == ".gltf") return ExportFormat::Gltf;
    if (extension == ".fbx") return ExportFormat::Fbx;
    return std::nullopt;
}

Diagnostics exportRig(const model::Rig& rig, const std::string& path, const ExportOptions& options)
{
    const auto format = exportFormatOf(path);
    if (!format)
        return {makeError({path, 0, 0}, "unknown export format: use .glb, .gltf or .fbx")};
    auto progress = [&](double fraction) { return !options.progress || options.progress(fraction); };
    if (!progress(0.0))
        return {makeWarning({path, 0, 0}, "export cancelled")};
    PreparedExport prepared = prepareExport(rig, options);
    for (auto& d : prepared.report)
        if (d.where.file.empty())
            d.where.file = path;
    if (prepared.cancelled || !progress(0.7)) {
        prepared.report.push_back(makeWarning({path, 0, 0}, "export cancelled, nothing written"));
        return prepared.report;
    }
    if (!prepared.scene)
        return prepared.report;
    const bool fbx = *format == ExportFormat::Fbx;
    const Convention convention = conventionFor(options.preset, fbx);
    const ExportScene scene = converted(std::move(*prepared.scene), convention);
    Diagnostics written = fbx ? writeFbx(scene, path, convention) : writeGltf(scene, path, options.generator);
    prepared.report.insert(prepared.report.end(), written.begin(), written.end());
    progress(1.0);
    return prepared.report;
}

} // namespace rs::io
