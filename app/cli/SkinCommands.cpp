// rigsmith-cli skin bind: automatic weights without a display.
#include "cli/Commands.h"
#include "cli/SkinCharacter.h"
#include "cli/SkinJson.h"

#include "io/AtomicFile.h"
#include "io/GuideFile.h"
#include "io/ModelImport.h"
#include "io/TemplateFolders.h"
#include "io/WeightsFile.h"
#include "skin/Refit.h"
#include "rigging/RigBuilder.h"
#include "skin/AutoWeights.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include <unistd.h>

namespace rs::cli {

namespace {

// --json: the bones (rig node name, parent bone, head and segment ends) and
// each bound mesh's vertices (as imported: file order, metres, Y-up) with
// their weights as [bone, weight] pairs; read by tests/tools/compare-blender-weights.py.
Json weightsJson(const model::Rig& rig, const std::vector<skin::SkinBone>& bones, const std::vector<const model::Mesh*>& meshes,
                 const std::vector<io::BoundMesh>& bound)
{
    Json boneList = Json::array();
    for (const skin::SkinBone& bone : bones) {
        Json tails = Json::array();
        for (const Vec3& tail : bone.tails)
            tails.push_back(jsonPoint(glm::vec3(tail)));
        boneList.push_back(Json{{"name", rig.nodes[bone.node].name}, {"parent", bone.parent}, {"head", jsonPoint(glm::vec3(bone.head))},
                                {"tails", std::move(tails)}});
    }
    Json meshList = Json::array();
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        const model::MeshWeights& w = bound[m].weights;
        Json positions = Json::array(), weights = Json::array();
        for (const auto& p : meshes[m]->positions)
            positions.push_back(jsonPoint(glm::vec3(p)));
        for (std::size_t v = 0; v + 1 < w.offsets.size(); ++v) {
            Json vertex = Json::array();
            for (std::uint32_t k = w.offsets[v]; k < w.offsets[v + 1]; ++k)
                vertex.push_back(Json::array({w.influences[k].joint, jsonNumber(w.influences[k].weight)}));
            weights.push_back(std::move(vertex));
        }
        meshList.push_back(Json{{"model", bound[m].model}, {"name", bound[m].name}, {"positions", std::move(positions)},
                                {"weights", std::move(weights)}});
    }
    return Json{{"bones", std::move(boneList)}, {"meshes", std::move(meshList)}};
}

} // namespace

int runSkin(const std::vector<std::string>& args)
{
    if (!args.empty() && args[0] == "export")
        return runSkinExport(args);
    if (!args.empty() && args[0] == "import")
        return runSkinImport(args);
    if (!args.empty() && args[0] == "info")
        return runSkinInfo(args);
    if (!args.empty() && args[0] == "transfer")
        return runSkinTransfer(args);
    if (args.empty() || args[0] != "bind") {
        std::cerr << "rigsmith-cli skin: expected bind, export, import, transfer or info\n" << usage();
        return 2;
    }
    std::string guidePath, modelPath, output, jsonPath;
    skin::BindOptions options;
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& a = args[i];
        const bool hasValue = i + 1 < args.size();
        if (a == "--model" && hasValue) {
            modelPath = args[++i];
        } else if (a == "--method" && hasValue) {
            const auto method = skin::parseBindMethod(args[++i]);
            if (!method) {
                std::cerr << "rigsmith-cli skin bind: --method is heat, envelope or closest, not '" << args[i] << "'\n";
                return 2;
            }
            options.method = *method;
        } else if (a == "--max-influences" && hasValue) {
            char* end = nullptr;
            const long n = std::strtol(args[++i].c_str(), &end, 10);
            if (args[i].empty() || *end != '\0' || n < 1 || n > 8) {
                std::cerr << "rigsmith-cli skin bind: --max-influences is a whole number from 1 to 8, not '" << args[i] << "'\n";
                return 2;
            }
            options.maxInfluences = int(n);
        } else if (a == "--json" && hasValue) {
            jsonPath = args[++i];
            if (jsonPath.empty()) {
                std::cerr << "rigsmith-cli skin bind: --json needs a file name\n";
                return 2;
            }
        } else if (a == "-o" && hasValue) {
            output = args[++i];
            if (output.empty()) {
                std::cerr << "rigsmith-cli skin bind: -o needs a file name\n";
                return 2;
            }
        } else if (guidePath.empty() && !a.empty() && a[0] != '-') {
            guidePath = a;
        } else {
            std::cerr << "rigsmith-cli skin bind: unexpected argument '" << a << "'\n" << usage();
            return 2;
        }
    }
    if (guidePath.empty()) {
        std::cerr << usage();
        return 2;
    }
    if (output.empty())
        output = std::filesystem::path(guidePath).replace_extension(".weights").string();

    {
        // Where the weights go is checked before any work: a bind can take a while.
        std::string target;
        const Status writable = io::resolveWriteTarget(output, target);
        if (writable.failed()) {
            print(writable.diagnostics());
            return 1;
        }
        const auto folder = std::filesystem::absolute(target).parent_path();
        std::error_code ec;
        if (!std::filesystem::is_directory(folder, ec) || access(folder.c_str(), W_OK) != 0) {
            std::cerr << output << ": error: cannot write the weights there: " << folder.string()
                      << " is not a folder this user may write to\n";
            return 1;
        }
    }
    Diagnostics templateDiagnostics;
    auto templates = io::loadDefaultTemplates(templateDiagnostics);
    auto guide = io::readGuideFile(guidePath);
    print(guide.diagnostics());
    if (!guide)
        return 1;
    const model::Rig rig = rigging::buildRig(*guide, *templates);
    if (hasErrors(rig.diagnostics)) {
        print(rig.diagnostics);
        return 1;
    }
    auto bones = skin::skinBones(rig);
    if (!bones) {
        print(bones.diagnostics());
        return 1;
    }
    std::vector<std::string> modelPaths = guide->models;
    if (!modelPath.empty())
        modelPaths = {modelPath};
    if (modelPaths.empty()) {
        std::cerr << guidePath << ": error: the guide has no model to bind; add one with 'rigsmith-cli model add " << guidePath
                  << " FILE' or name one with --model\n";
        return 1;
    }
    std::vector<io::BoundMesh> bound;
    std::vector<model::Model> models; // kept for --json (reserved: boundMeshes points into it)
    models.reserve(modelPaths.size());
    std::vector<const model::Mesh*> boundMeshes;
    const auto weightsFolder = std::filesystem::absolute(output).parent_path();
    for (const std::string& path : modelPaths) {
    auto model = io::importModel(path);
    if (!model) {
        print(model.diagnostics());
        return 1;
    }
    const std::string relativeModel = std::filesystem::absolute(path).lexically_relative(weightsFolder).string();
    models.push_back(model.take());
    for (const model::Mesh& mesh : models.back().meshes) {
        int shown = -1;
        const bool terminal = isatty(STDERR_FILENO) != 0;
        options.progress = [&](double fraction) {
            const int percent = int(fraction * 100.0);
            const int step = terminal ? 10 : 25; // a log gets a line per quarter, a terminal one updating line
            if (percent / step != shown / step) {
                shown = percent;
                std::cerr << (terminal ? "\r" : "") << "binding " << mesh.name << ": " << percent << "%" << (terminal ? "" : "\n")
                          << std::flush;
            }
            return true;
        };
        options.occluders.clear();
        for (const model::Mesh& other : models.back().meshes)
            if (&other != &mesh)
                options.occluders.push_back(&other);
        const auto start = std::chrono::steady_clock::now();
        skin::BindStats stats;
        auto weights = skin::bindMesh(mesh, *bones, options, &stats);
        if (terminal)
            std::cerr << '\n';
        print(weights.diagnostics());
        if (!weights)
            return 1;
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        std::cout << mesh.name << ": " << mesh.vertexCount() << " vertices (" << stats.surfaceVertices << " welded, "
                  << stats.parts << (stats.parts == 1 ? " part" : " parts") << ") bound to " << bones->size() << " skin joints by "
                  << skin::bindMethodName(options.method) << " in " << int(ms) << " ms; " << stats.verticesByClosestBone
                  << " vertices by their closest bone\n";
        bound.push_back({relativeModel, mesh.name, mesh.vertexCount(), model::topologyFingerprint(mesh), weights.take()});
        boundMeshes.push_back(&mesh);
    }
    }
    const Status saved = io::saveWeightsFile(output, bound);
    print(saved.diagnostics());
    if (saved.failed())
        return 1;
    std::cout << "weights: " << output << '\n';
    // The guide's own weights: the meshes as bound go beside them, to re-fit from
    // when a model changes later (the editor's open and the CLI's build do).
    if (std::filesystem::absolute(output) == std::filesystem::absolute(io::weightsPathFor(guidePath))) {
        std::vector<skin::SkinChunk> chunks;
        for (std::size_t i = 0; i < bound.size(); ++i)
            chunks.push_back(skin::bindingChunk({bound[i].model, bound[i].name, bound[i].vertexCount, bound[i].fingerprint, bound[i].weights},
                                                *boundMeshes[i], &rig));
        const Status kept = io::saveGuideChunks(chunks, guidePath);
        print(kept.diagnostics());
        if (kept.failed())
            return 1;
    }
    if (!jsonPath.empty()) {
        if (writeJsonReport(jsonPath, weightsJson(rig, *bones, boundMeshes, bound), true) != 0)
            return 1;
        std::cout << "weights as JSON: " << jsonPath << '\n';
    }
    return 0;
}

int runModel(const std::vector<std::string>& args)
{
    if (args.size() != 3 || args[0] != "add") {
        std::cerr << "rigsmith-cli model: expected 'add GUIDE FILE'\n" << usage();
        return 2;
    }
    const std::string& guidePath = args[1];
    auto guide = io::readGuideFile(guidePath);
    print(guide.diagnostics());
    if (!guide)
        return 1;
    auto model = io::importModel(args[2]);
    print(model.diagnostics());
    if (!model)
        return 1;
    const std::string absolute = std::filesystem::absolute(args[2]).lexically_normal().string();
    if (std::find(guide->models.begin(), guide->models.end(), absolute) != guide->models.end()) {
        std::cerr << guidePath << ": error: " << args[2] << " is already one of the guide's models\n";
        return 1;
    }
    guide->models.push_back(absolute);
    const Status saved = io::saveGuideFile(*guide, guidePath);
    print(saved.diagnostics());
    if (saved.failed())
        return 1;
    std::size_t vertices = 0;
    for (const auto& mesh : model->meshes)
        vertices += mesh.vertexCount();
    std::cout << guidePath << ": added " << args[2] << " (" << model->meshes.size() << (model->meshes.size() == 1 ? " mesh, " : " meshes, ")
              << vertices << " vertices)\n";
    return 0;
}

} // namespace rs::cli
