#include "io/ExportRequest.h"

#include "io/AtomicFile.h"
#include "io/ClipFile.h"
#include "io/HumanoidMap.h"
#include "io/NameMap.h"
#include "io/RigExport.h"
#include "model/Skeleton.h"

namespace rs::io {

namespace {

// The character's meshes and materials into `meshes`/`materials`; false when
// its errors refuse the export (they are in `report`, and nothing is written).
bool addCharacter(const model::Rig& rig, const ExportRequest& request, const ExportCharacter& character,
                  std::vector<SkinnedMesh>& meshes, std::vector<ExportMaterial>& materials, Diagnostics& report)
{
    CharacterExport bound = characterExport(rig, character.bindings, character.models);
    for (Diagnostic& d : bound.problems) {
        if (d.where.file.empty())
            d.where.file = request.path;
        if (d.severity == Severity::Error && request.force) {
            d.severity = Severity::Warning;
            d.message = "exported anyway (forced): " + d.message;
        }
    }
    report.insert(report.end(), bound.problems.begin(), bound.problems.end());
    if (hasErrors(bound.problems))
        return false;
    // Materials follow any the proxy brought (none today), so indices shift by that.
    const int first = int(materials.size());
    for (SkinnedMesh& mesh : bound.meshes) {
        if (mesh.material >= 0)
            mesh.material += first;
        meshes.push_back(std::move(mesh));
    }
    materials.insert(materials.end(), bound.materials.begin(), bound.materials.end());
    return true;
}

Diagnostics runExportOrThrow(const model::GuideDocument& guide, const model::Rig& rig, const model::PoseValues& pose, const ExportRequest& request,
                             std::function<bool(double)> progress, const ExportCharacter* character)
{
    if (request.proxyVertices > kMaxProxyVertices)
        return {makeError({request.path, 0, 0}, "a proxy mesh of " + std::to_string(request.proxyVertices) +
                                                     " vertices is too large (at most " + std::to_string(kMaxProxyVertices) + ")")};
    ExportOptions options;
    options.preset = request.preset;
    options.guide = &guide;
    options.controllers = request.controllers;
    options.rangeOfMotion = request.rangeOfMotion;
    options.fixNames = request.fixNames;
    options.fixWeights = request.fixWeights;
    options.force = request.force;
    options.progress = std::move(progress);
    if (request.currentPose)
        options.pose = &pose;
    options.testPose = &pose;
    options.framesPerSecond = request.framesPerSecond;
    options.clipPerControl = request.clipPerControl;
    options.embedTextures = request.embedTextures;

    Diagnostics report;
    NameMap names;
    if (request.names == "unity") {
        names = unityHumanoidMap(guide, rig);
    } else if (!request.names.empty()) {
        auto read = readNameMap(request.names);
        report = read.diagnostics();
        if (!read)
            return report;
        names = read.take();
    }
    if (!request.names.empty())
        options.names = &names;

    std::vector<KeyedClip> keyed;
    for (const std::string& path : request.clips) {
        auto read = readClipFile(path);
        Diagnostics d = read.diagnostics();
        report.insert(report.end(), d.begin(), d.end());
        if (!read)
            return report;
        keyed.push_back(read.take());
    }
    if (!keyed.empty())
        options.keyedClips = &keyed;

    std::vector<SkinnedMesh> meshes;
    std::vector<ExportMaterial> materials;
    if (request.proxyVertices > 0) {
        auto skeleton = model::extractSkeleton(rig);
        if (!skeleton)
            return skeleton.takeDiagnostics();
        meshes.push_back(proxyMesh(*skeleton, request.proxyVertices));
    }
    if (character && !addCharacter(rig, request, *character, meshes, materials, report))
        return report;
    if (!meshes.empty())
        options.meshes = &meshes;
    if (!materials.empty())
        options.materials = &materials;
    if (!request.referencePath.empty()) {
        auto prepared = prepareExport(rig, options);
        if (!prepared.scene)
            return prepared.report;
        Diagnostics written = writeFileAtomically(request.referencePath, exportReferenceJson(*prepared.scene)).takeDiagnostics();
        report.insert(report.end(), written.begin(), written.end());
    }
    if (request.path.empty())
        return report;
    Diagnostics exported = exportRig(rig, request.path, options);
    report.insert(report.end(), exported.begin(), exported.end());
    return report;
}

} // namespace

Diagnostics runExport(const model::GuideDocument& guide, const model::Rig& rig, const model::PoseValues& pose, const ExportRequest& request,
                      std::function<bool(double)> progress, const ExportCharacter* character)
{
    try { // the reference JSON and the meshes are made here, outside exportRig's guard
        return runExportOrThrow(guide, rig, pose, request, std::move(progress), character);
    } catch (const std::exception& e) {
        return {makeError({request.path, 0, 0}, std::string("export failed: ") + e.what())};
    }
}

} // namespace rs::io
