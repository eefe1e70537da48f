// rigsmith-cli skin transfer SOURCE TARGET -o FILE (issue 20 item 6): for
// pipelines without a guide. SOURCE is a skin chunk file (every chunk in it,
// as `skin import` reads them) or a skinned model file (each skinned mesh a
// chunk, skin/ModelChunks.h); TARGET any model file io::importModel reads.
// Each target mesh gets weights by the decision tree and options of `skin
// import`, on the source's influences (there is no rig to resolve them onto),
// written as a bind-pose chunk per mesh to FILE (.rschunks), or as the
// target's meshes skinned on the source's skeleton (.glb/.gltf,
// SkinTransferExport.h); atomically either way.
#include "cli/Commands.h"
#include "cli/SkinChunkSupport.h"
#include "cli/SkinImportOptions.h"
#include "cli/SkinTransferExport.h"

#include "io/ModelImport.h"
#include "io/SkinChunks.h"
#include "skin/ModelChunks.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

namespace rs::cli {

namespace {

struct TransferArguments {
    std::string source, target, output, json;
    std::set<std::string> meshes;
    bool progress = false;
    skin::TransferOptions options;
};

int parseTransfer(const std::vector<std::string>& args, TransferArguments& t)
{
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& a = args[i];
        bool known = false;
        if (const int usage = parseTransferOption(args, i, t.options, known, "skin transfer"))
            return usage;
        if (known)
            continue;
        const bool hasValue = i + 1 < args.size() && !args[i + 1].empty();
        if ((a == "-o" || a == "--json") && hasValue)
            (a == "-o" ? t.output : t.json) = args[++i];
        else if (a == "--mesh" && hasValue)
            t.meshes.insert(args[++i]);
        else if (a == "--progress")
            t.progress = true;
        else if (parseTransferFlag(a, t.options))
            continue;
        else if (!a.empty() && a[0] != '-' && (t.source.empty() || t.target.empty()))
            (t.source.empty() ? t.source : t.target) = a;
        else
            return usageError("skin transfer", "unexpected argument '" + a + "'");
    }
    if (t.source.empty() || t.target.empty() || t.output.empty())
        return usageError("skin transfer", "expected SOURCE TARGET -o FILE.rschunks");
    const std::string ext = std::filesystem::path(t.output).extension().string();
    if (ext == ".fbx" || ext == ".FBX")
        return usageError("skin transfer", "-o writes a skin chunk file (.rschunks) or skinned glTF (.glb, .gltf); build a guide to export FBX");
    return 0;
}

bool writesGltf(const std::string& path)
{
    const std::string ext = std::filesystem::path(path).extension().string();
    return ext == ".glb" || ext == ".gltf" || ext == ".GLB" || ext == ".GLTF";
}

skin::ChunkExportOptions chunkMeta()
{
    skin::ChunkExportOptions meta;
    meta.tool = std::string("rigsmith ") + RIGSMITH_VERSION;
    meta.user = userName();
    meta.exportedAtMicroseconds = nowMicroseconds();
    return meta;
}

// The source's chunks: a skin chunk file's, or one per skinned mesh of a model
// file (skin/ModelChunks.h); problems printed.
std::optional<std::vector<skin::SkinChunk>> readSource(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    char magic[8] = {};
    if (!in || !in.read(magic, 8) || std::string(magic, 8) == "RSCHUNKS")
        return readChunkFiles({path});
    auto model = io::importModel(path);
    print(model.diagnostics());
    if (!model)
        return std::nullopt;
    auto chunks = skin::chunksFromModel(*model, chunkMeta());
    print(chunks.diagnostics());
    if (!chunks)
        return std::nullopt;
    std::cout << "source: " << chunks->size() << " skinned meshes, " << model->joints.size() << " joints\n";
    return chunks.take();
}

// Per influence key, its name and matrices from the chunk that has it.
std::vector<skin::ChunkJoint> jointsFor(const model::MeshWeights& weights, const std::vector<skin::SkinChunk>& chunks)
{
    std::map<NodeKey, skin::ChunkJoint> byKey;
    for (const skin::SkinChunk& c : chunks)
        for (std::size_t j = 0; j < c.joints.size() && j < c.weights.joints.size(); ++j)
            byKey.try_emplace(c.weights.joints[j], c.joints[j]);
    std::vector<skin::ChunkJoint> joints;
    for (const NodeKey& key : weights.joints) {
        auto it = byKey.find(key);
        joints.push_back(it != byKey.end() ? it->second : skin::ChunkJoint{key, key.tag});
        joints.back().key = key;
    }
    return joints;
}

Json transferJson(const TransferArguments& t, const std::vector<skin::MeshImportReport>& reports)
{
    Json meshes = Json::array();
    for (const skin::MeshImportReport& report : reports) {
        Json mesh{{"mesh", report.mesh}};
        mesh.update(importReportJson(report, t.options.method));
        meshes.push_back(std::move(mesh));
    }
    return Json{{"source", t.source},
                {"target", t.target},
                {"output", t.output},
                {"options", transferOptionsJson(t.options)},
                {"meshes", std::move(meshes)}};
}

// The target's meshes (those named, if any); null on an error (printed).
std::optional<std::vector<const model::Mesh*>> targetMeshes(const TransferArguments& t, const model::Model& model)
{
    std::vector<const model::Mesh*> meshes;
    std::set<std::string> names;
    for (const model::Mesh& mesh : model.meshes)
        if (t.meshes.empty() || t.meshes.count(mesh.name)) {
            if (!names.insert(mesh.name).second) {
                std::cerr << t.target << ": error: a second mesh named '" << mesh.name << "': a chunk file holds one chunk per name\n";
                return std::nullopt;
            }
            meshes.push_back(&mesh);
        }
    for (const std::string& name : t.meshes)
        if (!names.count(name)) {
            std::cerr << t.target << ": error: no mesh named '" << name << "'\n";
            return std::nullopt;
        }
    return meshes;
}

int writeJson(const TransferArguments& t, const std::vector<skin::MeshImportReport>& reports)
{
    return writeJsonReport(t.json, transferJson(t, reports));
}

// -o OUT.glb / .gltf: the target's meshes skinned on the source's skeleton.
int writeGltfOutput(const TransferArguments& t, const std::vector<const model::Mesh*>& meshes, const std::vector<model::MeshWeights>& weights,
                    const std::vector<skin::SkinChunk>& chunks, const std::vector<skin::MeshImportReport>& reports)
{
    for (const skin::MeshImportReport& report : reports)
        printImportReport(report, ImportTarget{});
    const Diagnostics written = writeTransferredGltf(t.output, meshes, weights, chunks, std::string("rigsmith ") + RIGSMITH_VERSION);
    print(written);
    if (hasErrors(written))
        return 1;
    std::cout << "skinned meshes: " << t.output << '\n';
    return writeJson(t, reports);
}

} // namespace

int runSkinTransfer(const std::vector<std::string>& args)
{
    TransferArguments t;
    if (const int usage = parseTransfer(args, t))
        return usage;
    const HumanLinesAside aside(t.json);
    if (!canWriteBeside(t.output, writesGltf(t.output) ? "skinned glTF" : "skin chunks"))
        return 1;
    const auto chunks = readSource(t.source);
    auto model = chunks ? io::importModel(t.target) : Result<model::Model>::failure(Diagnostics{});
    print(model.diagnostics());
    const auto meshes = model ? targetMeshes(t, *model) : std::nullopt;
    if (!meshes)
        return 1;
    t.options.progress = progressPrinter("transferring weights", t.progress);
    std::vector<skin::MeshImportReport> reports;
    auto weights = skin::importChunks(*chunks, *meshes, t.options, &reports);
    print(weights.diagnostics());
    if (!weights)
        return 1;
    if (writesGltf(t.output))
        return writeGltfOutput(t, *meshes, *weights, *chunks, reports);
    const skin::ChunkExportOptions meta = chunkMeta();
    std::vector<skin::SkinChunk> out;
    for (std::size_t i = 0; i < meshes->size(); ++i) {
        auto chunk = skin::makeBindPoseChunk(*(*meshes)[i], (*weights)[i], jointsFor((*weights)[i], *chunks), t.target, meta);
        print(chunk.diagnostics());
        if (!chunk)
            return 1;
        out.push_back(chunk.take());
        printImportReport(reports[i], ImportTarget{});
    }
    const Status saved = io::saveSkinChunkFile(t.output, out);
    print(saved.diagnostics());
    if (saved.failed())
        return 1;
    std::cout << "skin chunks: " << t.output << '\n';
    return writeJson(t, reports);
}

} // namespace rs::cli
