#pragma once
// The options `skin import` and `skin transfer` share (the fallback methods
// and the decision tree's switches), what `skin import` was asked, and its
// reports: a line per mesh on stdout and the --json report.
#include "cli/SkinCharacter.h"
#include "cli/SkinChunkSupport.h"
#include "cli/SkinJson.h"

#include "skin/InfluenceMap.h"
#include "skin/Transfer.h"

#include <set>
#include <string>
#include <vector>

namespace rs::cli {

struct ImportArguments {
    std::string guide, json, depot, asset, nameMap;
    std::vector<std::string> files;
    std::set<std::string> meshes;          // --mesh: every vertex of these
    std::vector<VertexSelection> vertices; // --vertices: these of those meshes
    bool append = false, progress = false;
    skin::InfluenceMapOptions influences;
    skin::TransferOptions options;
};

// One mesh an import writes: all of it, or the selected vertices.
struct ImportTarget {
    CharacterMesh mesh;
    std::vector<std::uint32_t> selection; // ascending; used when !whole
    bool whole = true;
    std::size_t written = 0, kept = 0;    // vertices given imported weights / keeping their own
};

// A transfer option with a value (--method, --normal-filter, --neighbours,
// --distance-multiplier, --inpaint-distance, --inpaint-angle, --smooth,
// --smooth-threshold, --max-influences) at args[i]: 2 on a bad value
// (printed for `command`), `known` false when args[i] is none of them.
int parseTransferOption(const std::vector<std::string>& args, std::size_t& i, skin::TransferOptions& o, bool& known,
                        const std::string& command);
// --no-search, --uber, --export-pose; false: none of them.
bool parseTransferFlag(const std::string& arg, skin::TransferOptions& o);

// The export names of the rig's skin joints, one per bone.
std::vector<std::string> boneNames(const Character& c);

void printImportReport(const skin::MeshImportReport& report, const ImportTarget& target);
// Writes the --json report (if asked); 0, or 1 when it cannot be written.
int writeImportJson(const ImportArguments& m, const std::vector<skin::SkinChunk>& chunks, const std::vector<ImportTarget>& targets,
                    const std::vector<skin::MeshImportReport>& reports, const skin::InfluenceResolution& influences);
// The transfer options as asked (the reports' "options").
Json transferOptionsJson(const skin::TransferOptions& options);

} // namespace rs::cli
