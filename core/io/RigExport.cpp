#include "io/RigExport.h"

#include "io/BoneInference.h"
#include "io/FbxExport.h"
#include "io/GltfExport.h"

#include "base/TextScalars.h"

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

namespace {

// Readers refuse ill-formed UTF-8 at its line; a name made by an edit or an API
// caller is caught here, by name, before a JSON writer throws over it.
Diagnostics checkNames(const model::Rig& rig, const std::string& path)
{
    Diagnostics out;
    for (const model::RigNode& node : rig.nodes)
        if (invalidUtf8Offset(node.name) != std::string::npos)
            out.push_back(makeError({path, 0, 0}, "the name of rig node '" + node.path + "' is not valid UTF-8; rename it"));
    return out;
}

Diagnostics exportRigOrThrow(const model::Rig& rig, const std::string& path, const ExportOptions& options)
{
    if (Diagnostics names = checkNames(rig, path); !names.empty())
        return names;
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
    FbxWriteOptions fbxOptions;
    fbxOptions.generator = options.generator;
    fbxOptions.embedTextures = options.embedTextures;
    if (options.stampTime)
        fbxOptions.creationTime = std::time(nullptr);
    if (fbx)
        for (int j : connectedMovingJoints(scene)) {
            const ExportJoint& joint = scene.joints[std::size_t(j)];
            const ExportJoint& parent = scene.joints[std::size_t(joint.parent)];
            Diagnostic d = makeWarning({path, 0, 0}, "Blender's FBX importer will connect joint '" + joint.name + "' to '" +
                                                         parent.name + "' (it lies on the parent's +Y axis) and ignore its "
                                                         "location curves: orient '" + parent.name +
                                                         "' so that its Y axis does not point at its child (X along the chain)");
            if (const auto node = rig.findPath(joint.id))
                d.subject = Subject::ofNode(rig.nodes[*node].key);
            prepared.report.push_back(std::move(d));
        }
    Diagnostics written = fbx ? writeFbx(scene, path, convention, fbxOptions) : writeGltf(scene, path, options.generator);
    prepared.report.insert(prepared.report.end(), written.begin(), written.end());
    progress(1.0);
    return prepared.report;
}

} // namespace

Diagnostics exportRig(const model::Rig& rig, const std::string& path, const ExportOptions& options)
{
    try { // nothing thrown by a writer (tinygltf, nlohmann-json, Assimp, allocation) crosses this boundary
        return exportRigOrThrow(rig, path, options);
    } catch (const std::exception& e) {
        return {makeError({path, 0, 0}, std::string("export failed: ") + e.what())};
    }
}

} // namespace rs::io
