// rigsmith-cli skin export: skin chunks of a guide's bound meshes (issue 20)
// into one file, or into a weight depot (one file per mesh), from any
// selection: meshes, vertices, the vertices joints influence (Skinner's
// "export any combination of mesh / joint / vertex selection"; the union);
// --json reports each chunk's header and file.
#include "cli/Commands.h"
#include "cli/SkinCharacter.h"
#include "cli/SkinChunkSupport.h"
#include "cli/SkinJson.h"

#include "eval/PoseTools.h"
#include "io/AtomicFile.h"
#include "io/SkinChunks.h"
#include "skin/Retarget.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <set>
#include <sstream>

namespace rs::cli {

namespace {

struct ExportArguments {
    std::string guide, output, depot, asset, json;
    std::set<std::string> meshes;
    std::vector<VertexSelection> vertices;
    std::vector<std::string> joints;
    bool bindPose = false;
    int neighbourSample = 4;
    skin::SkinningMethod method = skin::SkinningMethod::Linear;
    bool selects() const { return !meshes.empty() || !vertices.empty() || !joints.empty(); }
};

// An option with a value; `known` false: not one.
int parseExportOption(const std::vector<std::string>& args, std::size_t& i, ExportArguments& e, bool& known)
{
    const std::string& a = args[i];
    known = i + 1 < args.size();
    if (!known)
        return 0;
    const std::string& value = args[i + 1];
    auto bad = [&](const std::string& what) { return usageError("skin export", a + " is " + what + ", not '" + value + "'"); };
    if (a == "-o" || a == "--depot" || a == "--asset" || a == "--json") {
        if (value.empty())
            return bad(a == "--json" ? "a file name (or - for stdout)" : "a file or folder name");
        (a == "-o" ? e.output : a == "--depot" ? e.depot : a == "--asset" ? e.asset : e.json) = value;
    } else if (a == "--mesh") {
        e.meshes.insert(value);
    } else if (a == "--vertices") {
        if (!parseVertexSelection(value, e.vertices.emplace_back()))
            return bad("MESH:RANGES, vertex ids and ranges such as body:0-99,120");
    } else if (a == "--joints") {
        std::stringstream names(value);
        for (std::string name; std::getline(names, name, ',');)
            if (!name.empty())
                e.joints.push_back(name);
    } else if (a == "--neighbours") {
        if (!parseCount(value, 0, 32, e.neighbourSample))
            return bad("a whole number from 0 to 32");
    } else {
        known = false;
        return 0;
    }
    ++i;
    return 0;
}

// 0: parsed; 2: usage (printed).
int parseExport(const std::vector<std::string>& args, ExportArguments& e)
{
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& a = args[i];
        bool known = false;
        if (const int usage = parseExportOption(args, i, e, known))
            return usage;
        if (known)
            continue;
        if (a == "--bind-pose")
            e.bindPose = true;
        else if (a == "--dual-quaternion")
            e.method = skin::SkinningMethod::DualQuaternion;
        else if (e.guide.empty() && !a.empty() && a[0] != '-')
            e.guide = a;
        else
            return usageError("skin export", "unexpected argument '" + a + "'");
    }
    if (e.guide.empty() || e.output.empty() == e.depot.empty())
        return usageError("skin export", "expected GUIDE -o FILE or GUIDE --depot DIR");
    return 0;
}

// Per bone: whether --joints names it; errors for names that are no skin joint.
std::vector<bool> selectedBones(const ExportArguments& e, const Character& c, Diagnostics& problems)
{
    std::vector<bool> selected(c.bones.size(), false);
    for (const std::string& name : e.joints) {
        bool found = false;
        for (std::size_t b = 0; b < c.bones.size(); ++b)
            if (c.bones[b].node < c.rig.nodes.size() && c.rig.nodes[c.bones[b].node].name == name)
                selected[b] = found = true;
        if (!found)
            problems.push_back(makeError({e.guide, 0, 0}, "--joints: '" + name + "' is not a skin joint of the guide's rig"));
    }
    return selected;
}

// The mesh's weights on the rig's bones; null with an error when it has none that fit.
std::optional<model::MeshWeights> weightsOf(const Character& c, const CharacterMesh& m, Diagnostics& problems)
{
    if (m.binding < 0) {
        problems.push_back(makeError({m.model, 0, 0}, "mesh '" + m.mesh->name + "' has no weights to export (bind it with 'skin bind')"));
        return std::nullopt;
    }
    const model::MeshBinding& binding = c.guide.bindings[std::size_t(m.binding)];
    if (!model::bindingFits(binding, *m.mesh)) {
        problems.push_back(makeError({m.model, 0, 0}, "mesh '" + m.mesh->name + "' changed since it was bound (" +
                                                          std::to_string(binding.vertexCount) + " vertices then, " +
                                                          std::to_string(m.mesh->vertexCount()) + " now): its weights no longer fit it"));
        return std::nullopt;
    }
    if (isOnBones(binding.weights, c.bones))
        return binding.weights;
    auto weights = skin::retargetWeights(binding.weights, c.bones, m.mesh->name);
    problems.insert(problems.end(), weights.diagnostics().begin(), weights.diagnostics().end());
    return weights ? std::optional(weights.take()) : std::nullopt;
}

// The vertices of `m` the selection takes (ascending; all of them: every id).
std::vector<std::uint32_t> exportedVertices(const ExportArguments& e, const CharacterMesh& m, const model::MeshWeights& weights,
                                            const std::vector<bool>& bones, Diagnostics& problems)
{
    std::vector<std::uint32_t> ids;
    const std::size_t n = m.mesh->vertexCount();
    const bool whole = !e.selects() || e.meshes.count(m.mesh->name);
    for (std::size_t v = 0; v < n; ++v) {
        bool take = whole;
        for (const model::Influence* i = weights.begin(v); i != weights.end(v) && !take; ++i)
            take = i->weight > 0.0f && i->joint < bones.size() && bones[i->joint];
        if (take)
            ids.push_back(std::uint32_t(v));
    }
    for (const VertexSelection& s : e.vertices)
        if (s.mesh == m.mesh->name && !whole) {
            auto selected = selectedVertices(s, n);
            problems.insert(problems.end(), selected.diagnostics().begin(), selected.diagnostics().end());
            if (selected)
                ids.insert(ids.end(), selected->begin(), selected->end());
        }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
}

bool namedInSelection(const ExportArguments& e, const std::string& mesh)
{
    return e.meshes.count(mesh) || std::any_of(e.vertices.begin(), e.vertices.end(), [&](const VertexSelection& s) { return s.mesh == mesh; });
}

void checkMeshNames(const ExportArguments& e, const Character& c, Diagnostics& problems)
{
    std::set<std::string> names(e.meshes);
    for (const VertexSelection& s : e.vertices)
        names.insert(s.mesh);
    for (const std::string& name : names)
        if (std::none_of(c.meshes.begin(), c.meshes.end(), [&](const CharacterMesh& m) { return m.mesh->name == name; }))
            problems.push_back(makeError({e.guide, 0, 0}, "no mesh named '" + name + "' in the guide's models"));
}

// The chunks of the selection; errors in `problems`.
std::vector<skin::SkinChunk> exportChunks(const ExportArguments& e, const Character& c, const skin::ChunkExportOptions& options,
                                          Diagnostics& problems)
{
    const std::vector<bool> bones = selectedBones(e, c, problems);
    std::vector<skin::SkinChunk> chunks;
    for (const CharacterMesh& m : c.meshes) {
        const bool named = namedInSelection(e, m.mesh->name);
        if (e.selects() && !named && (e.joints.empty() || m.binding < 0))
            continue;
        const auto weights = weightsOf(c, m, problems);
        const auto ids = weights ? exportedVertices(e, m, *weights, bones, problems) : std::vector<std::uint32_t>{};
        if (ids.empty())
            continue;
        if (e.depot.empty() && std::any_of(chunks.begin(), chunks.end(), [&](const skin::SkinChunk& k) { return k.mesh == m.mesh->name; })) {
            problems.push_back(makeError({m.model, 0, 0}, "a second mesh named '" + m.mesh->name +
                                                              "': a chunk file holds one chunk per name (export it alone with --mesh to "
                                                              "another file, or to a weight depot with --depot)"));
            continue;
        }
        auto chunk = skin::makeSkinChunk({m.mesh, &*weights, m.model, ids}, c.bones, options);
        problems.insert(problems.end(), chunk.diagnostics().begin(), chunk.diagnostics().end());
        if (chunk)
            chunks.push_back(chunk.take());
    }
    checkMeshNames(e, c, problems);
    return chunks;
}

// One file, or one file per mesh in the depot, all or nothing: every file is
// written to a temp beside its target and checked before any is renamed, so a
// failure (a folder or an unwritable file where one goes, a full disk) leaves
// the depot's previous set as it was rather than a mix of old and new.
Status saveChunks(const ExportArguments& e, const std::vector<skin::SkinChunk>& chunks)
{
    if (e.depot.empty())
        return io::saveSkinChunkFile(e.output, chunks);
    std::vector<std::string> meshes;
    for (const skin::SkinChunk& k : chunks)
        meshes.push_back(k.mesh);
    const std::vector<std::string> paths = depotPaths(e.depot, e.asset.empty() ? assetOf(e.guide) : e.asset, meshes);
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(paths.front()).parent_path(), ec);
    if (ec)
        return Status::failure(makeError({paths.front(), 0, 0}, "cannot make the weight depot's folder: " + ec.message()));
    std::vector<std::string> encoded;
    encoded.reserve(chunks.size());
    std::vector<io::FileContent> files;
    for (std::size_t k = 0; k < chunks.size(); ++k) {
        encoded.push_back(io::writeSkinChunks({chunks[k]}));
        files.push_back({paths[k], encoded.back()});
    }
    const Status saved = io::writeFilesAtomically(files);
    if (saved.failed()) {
        Diagnostics why = saved.diagnostics();
        Diagnostic kept = makeWarning({paths.front(), 0, 0}, "nothing was written: the weight depot keeps its previous files");
        kept.severity = Severity::Note;
        why.push_back(std::move(kept));
        return Status::failure(std::move(why));
    }
    for (const std::string& path : paths)
        std::cout << "skin chunk: " << path << '\n';
    return saved;
}

std::optional<skin::ChunkExportOptions> exportOptions(const ExportArguments& e, const Character& c, std::optional<model::Rig>& posed)
{
    if (const model::PoseValues pose = model::testPose(c.guide.overrides); !e.bindPose && !pose.empty()) {
        auto withPose = eval::posedRig(c.rig, pose);
        print(withPose.diagnostics());
        if (!withPose)
            return std::nullopt;
        posed = withPose.take();
    }
    skin::ChunkExportOptions options;
    options.rig = &c.rig;
    options.posedRig = posed ? &*posed : nullptr;
    options.method = e.method;
    options.neighbourSample = e.neighbourSample;
    options.tool = std::string("rigsmith ") + RIGSMITH_VERSION;
    options.user = userName();
    options.exportedAtMicroseconds = nowMicroseconds();
    return options;
}

std::vector<std::string> chunkFiles(const ExportArguments& e, const std::vector<skin::SkinChunk>& chunks)
{
    if (e.depot.empty())
        return std::vector<std::string>(chunks.size(), e.output);
    std::vector<std::string> meshes;
    for (const skin::SkinChunk& k : chunks)
        meshes.push_back(k.mesh);
    return depotPaths(e.depot, e.asset.empty() ? assetOf(e.guide) : e.asset, meshes);
}

// --json: what was asked and, per chunk, its header and the file it went to.
int writeExportJson(const ExportArguments& e, const std::vector<skin::SkinChunk>& chunks)
{
    Json vertices = Json::array();
    for (const VertexSelection& s : e.vertices) {
        Json ranges = Json::array();
        for (const auto& [first, last] : s.ranges)
            ranges.push_back(Json::array({first, last}));
        vertices.push_back(Json{{"mesh", s.mesh}, {"ranges", std::move(ranges)}});
    }
    const std::vector<std::string> files = chunkFiles(e, chunks);
    Json chunkList = Json::array();
    for (std::size_t k = 0; k < chunks.size(); ++k) {
        Json chunk = chunkHeaderJson(chunks[k]);
        chunk["file"] = files[k];
        chunkList.push_back(std::move(chunk));
    }
    const Json report{{"guide", e.guide},
                      {"output", e.output.empty() ? Json(nullptr) : Json(e.output)},
                      {"depot", e.depot.empty() ? Json(nullptr) : Json(e.depot)},
                      {"options", Json{{"bindPose", e.bindPose},
                                       {"skinning", e.method == skin::SkinningMethod::DualQuaternion ? "dual-quaternion" : "linear"},
                                       {"neighbours", e.neighbourSample}}},
                      {"selection", Json{{"meshes", e.meshes}, {"vertices", std::move(vertices)}, {"joints", e.joints}}},
                      {"chunks", std::move(chunkList)}};
    return writeJsonReport(e.json, report);
}

} // namespace

int runSkinExport(const std::vector<std::string>& args)
{
    ExportArguments e;
    if (const int usage = parseExport(args, e))
        return usage;
    const HumanLinesAside aside(e.json);
    if (e.depot.empty() && !canWriteBeside(e.output, "skin chunks"))
        return 1;
    auto character = loadCharacter(e.guide);
    if (!character)
        return 1;
    std::optional<model::Rig> posed;
    const auto options = exportOptions(e, *character, posed);
    if (!options)
        return 1;
    Diagnostics problems;
    const std::vector<skin::SkinChunk> chunks = exportChunks(e, *character, *options, problems);
    print(problems);
    if (hasErrors(problems))
        return 1;
    if (chunks.empty()) {
        std::cerr << e.guide << ": error: " << (e.selects() ? "the selection has no bound vertex to export" : "the guide has no bound mesh to export")
                  << '\n';
        return 1;
    }
    const Status saved = saveChunks(e, chunks);
    print(saved.diagnostics());
    if (saved.failed())
        return 1;
    for (const skin::SkinChunk& k : chunks)
        std::cout << k.mesh << ": " << k.vertexCount() << " vertices, " << k.joints.size() << " influences, "
                  << (k.inBindPose ? "bind pose" : "the guide's test pose and bind pose") << '\n';
    if (e.depot.empty())
        std::cout << "skin chunks: " << e.output << '\n';
    return writeExportJson(e, chunks);
}

} // namespace rs::cli
