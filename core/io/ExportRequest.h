#pragma once
// One export as the CLI and the editor's Export dialog ask for it, by value:
// the path (format from the extension), the preset and options, the name map
// ("unity" or a YAML file), a generated proxy mesh for a rig without a
// character. runExport turns it into io::ExportOptions, adds the character's
// bound meshes (io/CharacterExport.h) and runs io::exportRig.
#include "base/Diagnostic.h"
#include "io/CharacterExport.h"
#include "io/ExportScene.h"
#include "model/GuideDocument.h"
#include "model/Rig.h"

#include <functional>
#include <string>
#include <vector>

namespace rs::io {

// The largest proxy mesh runExport generates (about 100 MB of vertex data);
// a larger request is an error, not an allocation failure.
constexpr std::size_t kMaxProxyVertices = 1'000'000;

struct ExportRequest {
    std::string path;
    ExportPreset preset = ExportPreset::Gltf;
    std::string names;              // empty, "unity" or a name map file (io/NameMap.h)
    bool controllers = false;
    bool rangeOfMotion = false;
    bool currentPose = false;       // the guide's pose on the nodes
    bool fixNames = false;
    bool fixWeights = false;
    bool force = false;
    std::size_t proxyVertices = 0;  // 0: no mesh; otherwise io::proxyMesh of about that many vertices (≤ kMaxProxyVertices)
    std::string referencePath;      // when set, also writes exportReferenceJson there
    double framesPerSecond = 30.0;  // the range of motion's frame grid (ExportOptions::framesPerSecond)
    bool clipPerControl = false;    // the range of motion as one clip per controller (ExportOptions::clipPerControl)
    bool embedTextures = true;      // FBX textures inside the file, or beside it (ExportOptions::embedTextures)
    std::vector<std::string> clips; // keyed clip files (io/ClipFile.h), exported with cubic keys
};

// The character an export carries: the guide's weight records and its models
// as read (the editor's session has them; the CLI reads them).
struct ExportCharacter {
    std::vector<model::MeshBinding> bindings;
    std::vector<CharacterModel> models;
};

// `guide` is the guide `rig` was built from (the Unity humanoid map resolves
// through its instances). `pose` is the guide's test pose relative to `rig`'s rest: put on the nodes
// with currentPose, and where the range of motion starts. For a rig already
// rebuilt in that pose (eval::posedRig) pass an empty pose, or it is applied twice. `progress` as in
// ExportOptions. With a `character`, its meshes are exported bound to the
// rig; its errors (a mesh without weights...) refuse the export unless forced,
// like the validator's.
Diagnostics runExport(const model::GuideDocument& guide, const model::Rig& rig, const model::PoseValues& pose, const ExportRequest& request,
                      std::function<bool(double)> progress = {}, const ExportCharacter* character = nullptr);

} // namespace rs::io
