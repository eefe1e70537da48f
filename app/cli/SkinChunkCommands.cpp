// rigsmith-cli skin export / import / info: skin chunk files (issue 20) from
// and onto a guide's bound meshes, and what a chunk file holds.
#include "cli/Commands.h"
#include "cli/SkinCharacter.h"

#include "eval/PoseTools.h"
#include "io/AtomicFile.h"
#include "io/SkinChunks.h"
#include "io/WeightsFile.h"
#include "skin/Retarget.h"
#include "skin/Transfer.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <set>
#include <sstream>

#include <pwd.h>
#include <unistd.h>

namespace rs::cli {

namespace {

std::string userName()
{
    if (const char* user = std::getenv("USER"); user && *user)
        return user;
    if (const passwd* entry = getpwuid(getuid()))
        return entry->pw_name;
    return "";
}

std::int64_t nowMicroseconds()
{
    return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
}

struct ExportArguments {
    std::string guide, output;
    std::set<std::string> meshes;
    bool bindPose = false;
    int neighbourSample = 4;
    skin::SkinningMethod method = skin::SkinningMethod::Linear;
};

// 0: parsed; 2: usage (printed).
int parseExport(const std::vector<std::string>& args, ExportArguments& e)
{
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& a = args[i];
        const bool hasValue = i + 1 < args.size();
        if (a == "-o" && hasValue && !args[i + 1].empty()) {
            e.output = args[++i];
        } else if (a == "--mesh" && hasValue) {
            e.meshes.insert(args[++i]);
        } else if (a == "--bind-pose") {
            e.bindPose = true;
        } else if (a == "--dual-quaternion") {
            e.method = skin::SkinningMethod::DualQuaternion;
        } else if (a == "--neighbours" && hasValue) {
            if (!parseCount(args[++i], 0, 32, e.neighbourSample))
                return usageError("skin export", "--neighbours is a whole number from 0 to 32, not '" + args[i] + "'");
        } else if (e.guide.empty() && !a.empty() && a[0] != '-') {
            e.guide = a;
        } else {
            return usageError("skin export", "unexpected argument '" + a + "'");
        }
    }
    if (e.guide.empty() || e.output.empty())
        return usageError("skin export", "expected GUIDE -o FILE");
    return 0;
}

} // namespace

int runSkinExport(const std::vector<std::string>& args)
{
    ExportArguments e;
    if (const int usage = parseExport(args, e))
        return usage;
    if (!canWriteBeside(e.output, "skin chunks"))
        return 1;
    auto character = loadCharacter(e.guide);
    if (!character)
        return 1;
    Character& c = *character;
    std::optional<model::Rig> posed;
    if (!e.bindPose && !c.guide.pose.empty()) {
        auto withPose = eval::posedRig(c.rig, c.guide.pose);
        print(withPose.diagnostics());
        if (!withPose)
            return 1;
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

    Diagnostics problems;
    std::vector<skin::SkinChunk> chunks;
    std::set<std::string> found;
    for (const CharacterMesh& m : c.meshes) {
        if (!e.meshes.empty() && !e.meshes.count(m.mesh->name))
            continue;
        found.insert(m.mesh->name);
        if (m.binding < 0) {
            problems.push_back(makeError({m.model, 0, 0}, "mesh '" + m.mesh->name + "' has no weights to export (bind it with 'skin bind')"));
            continue;
        }
        const model::MeshBinding& binding = c.guide.bindings[std::size_t(m.binding)];
        if (!model::bindingFits(binding, *m.mesh)) {
            problems.push_back(makeError({m.model, 0, 0}, "mesh '" + m.mesh->name + "' changed since it was bound (" +
                                                              std::to_string(binding.vertexCount) + " vertices then, " +
                                                              std::to_string(m.mesh->vertexCount()) + " now): its weights no longer fit it"));
            continue;
        }
        auto weights = isOnBones(binding.weights, c.bones) ? Result<model::MeshWeights>(binding.weights)
                                                          : skin::retargetWeights(binding.weights, c.bones, m.mesh->name);
        print(weights.diagnostics());
        if (!weights)
            return 1;
        if (std::any_of(chunks.begin(), chunks.end(), [&](const skin::SkinChunk& k) { return k.mesh == m.mesh->name; })) {
            problems.push_back(makeError({m.model, 0, 0}, "a second mesh named '" + m.mesh->name +
                                                              "': a chunk file holds one chunk per name (export it alone with --mesh to another file)"));
            continue;
        }
        auto chunk = skin::makeSkinChunk({m.mesh, &*weights, m.model, {}}, c.bones, options);
        if (!chunk) {
            print(chunk.diagnostics());
            return 1;
        }
        chunks.push_back(chunk.take());
    }
    for (const std::string& name : e.meshes)
        if (!found.count(name))
            problems.push_back(makeError({e.guide, 0, 0}, "no mesh named '" + name + "' in the guide's models"));
    print(problems);
    if (hasErrors(problems))
        return 1;
    if (chunks.empty()) {
        std::cerr << e.guide << ": error: the guide has no bound mesh to export\n";
        return 1;
    }
    const Status saved = io::saveSkinChunkFile(e.output, chunks);
    print(saved.diagnostics());
    if (saved.failed())
        return 1;
    for (const skin::SkinChunk& k : chunks)
        std::cout << k.mesh << ": " << k.vertexCount() << " vertices, " << k.joints.size() << " influences, "
                  << (k.inBindPose ? "bind pose" : "the guide's test pose and bind pose") << '\n';
    std::cout << "skin chunks: " << e.output << '\n';
    return 0;
}

} // namespace rs::cli

namespace rs::cli {

namespace {

struct ImportArguments {
    std::string guide, json;
    std::vector<std::string> files;
    std::set<std::string> meshes;
    skin::TransferOptions options;
};

// One option of `skin import` with a value; false: not one (or no value).
int parseImportOption(const std::vector<std::string>& args, std::size_t& i, ImportArguments& m, bool& known)
{
    const std::string& a = args[i];
    known = true;
    if (i + 1 >= args.size()) {
        known = false;
        return 0;
    }
    const std::string& value = args[i + 1];
    skin::TransferOptions& o = m.options;
    auto bad = [&](const std::string& what) { return usageError("skin import", a + " is " + what + ", not '" + value + "'"); };
    if (a == "--method") {
        const auto method = skin::parseTransferMethod(value);
        if (!method)
            return bad("closest, neighbours or inpaint");
        o.method = *method;
    } else if (a == "--normal-filter") {
        if (!parseNumber(value, -1.0, 1.0, o.normalTolerance))
            return bad("a dot product tolerance from -1 to 1 (0.75: within about 41 degrees)");
        o.normalFilter = true;
    } else if (a == "--neighbours") {
        if (!parseCount(value, 1, 32, o.neighbourCount))
            return bad("a whole number from 1 to 32");
    } else if (a == "--distance-multiplier") {
        if (!parseNumber(value, 1.0, 1000.0, o.neighbourDistanceMultiplier))
            return bad("a number from 1 to 1000");
    } else if (a == "--inpaint-distance") {
        if (!parseNumber(value, 0.0, 1000.0, o.inpaintDistance))
            return bad("metres, at least 0 (0: 5% of the mesh's size)");
    } else if (a == "--inpaint-angle") {
        if (!parseNumber(value, 0.0, 180.0, o.inpaintAngleDegrees))
            return bad("degrees from 0 to 180");
    } else if (a == "--smooth") {
        if (!parseCount(value, 0, 100, o.smoothSteps))
            return bad("a whole number of steps from 0 to 100");
    } else if (a == "--smooth-threshold") {
        if (!parseNumber(value, 0.0, 1.0, o.weightDifferenceThreshold))
            return bad("a weight difference from 0 to 1");
    } else if (a == "--max-influences") {
        if (!parseCount(value, 1, 16, o.maxInfluences))
            return bad("a whole number from 1 to 16");
    } else if (a == "--mesh") {
        m.meshes.insert(value);
    } else if (a == "--json") {
        if (value.empty())
            return bad("a file name (or - for stdout)");
        m.json = value;
    } else {
        known = false;
        return 0;
    }
    ++i;
    return 0;
}

int parseImport(const std::vector<std::string>& args, ImportArguments& m)
{
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& a = args[i];
        bool known = false;
        if (const int usage = parseImportOption(args, i, m, known))
            return usage;
        if (known)
            continue;
        if (a == "--no-search")
            m.options.searchByCountAndOrder = false;
        else if (a == "--uber")
            m.options.forceUberChunk = true;
        else if (a == "--export-pose")
            m.options.usePreDeformed = false;
        else if (!a.empty() && a[0] != '-')
            (m.guide.empty() ? m.guide : m.files.emplace_back()) = a;
        else
            return usageError("skin import", "unexpected argument '" + a + "'");
    }
    if (m.guide.empty() || m.files.empty())
        return usageError("skin import", "expected GUIDE FILE...");
    return 0;
}

// Progress on stderr once an import has taken a second: a terminal gets one
// updating line, a log a line per quarter.
std::function<bool(double)> progressPrinter()
{
    const auto start = std::chrono::steady_clock::now();
    const bool terminal = isatty(STDERR_FILENO) != 0;
    auto shown = std::make_shared<int>(-1);
    return [=](double fraction) {
        if (std::chrono::steady_clock::now() - start < std::chrono::seconds(1))
            return true;
        const int percent = int(fraction * 100.0), step = terminal ? 5 : 25;
        if (percent / step != *shown / step) {
            *shown = percent;
            std::cerr << (terminal ? "\r" : "") << "importing weights: " << percent << "%" << (terminal && percent < 100 ? "" : "\n")
                      << std::flush;
        }
        return true;
    };
}

std::string reportJson(const ImportArguments& m, const std::vector<skin::SkinChunk>& chunks, const std::vector<CharacterMesh>& targets,
                       const std::vector<skin::MeshImportReport>& reports)
{
    std::ostringstream out;
    out << "{\"guide\": " << jsonString(m.guide) << ", \"weights\": " << jsonString(io::weightsPathFor(m.guide)) << ",\n \"chunks\": [";
    for (std::size_t k = 0; k < chunks.size(); ++k)
        out << (k ? ", " : "") << "{\"mesh\": " << jsonString(chunks[k].mesh) << ", \"vertices\": " << chunks[k].vertexCount()
            << ", \"exported\": " << jsonString(skin::formatExportTime(chunks[k].exportedAtMicroseconds))
            << ", \"user\": " << jsonString(chunks[k].user) << "}";
    out << "],\n \"meshes\": [";
    for (std::size_t i = 0; i < reports.size(); ++i) {
        const skin::MeshImportReport& r = reports[i];
        out << (i ? ",\n  " : "\n  ") << "{\"model\": " << jsonString(targets[i].model) << ", \"mesh\": " << jsonString(r.mesh)
            << ", \"vertices\": " << r.vertices << ", \"route\": \"" << skin::importRouteName(r.route) << "\", \"source\": " << jsonString(r.source)
            << ", \"why\": " << jsonString(r.why) << ", \"method\": \"" << skin::transferMethodName(m.options.method)
            << "\", \"oneToOne\": " << r.oneToOne << ", \"singleInfluence\": " << r.singleInfluence << ", \"closestPoint\": " << r.closestPoint
            << ", \"closestNeighbours\": " << r.closestNeighbours << ", \"normalFilterFallbacks\": " << r.normalFilterFallbacks
            << ", \"inpainted\": " << r.inpainted << ", \"smoothed\": " << r.smoothed << ", \"milliseconds\": " << r.milliseconds << "}";
    }
    out << "]}\n";
    return out.str();
}

void printReport(const skin::MeshImportReport& r)
{
    std::cout << r.mesh << ": " << r.vertices << " vertices, " << skin::importRouteName(r.route) << " from "
              << (r.source == "uber chunk" ? r.source : "chunk '" + r.source + "'") << " (" << r.why << "): " << r.oneToOne << " 1:1, "
              << r.singleInfluence << " single influence, " << r.closestPoint << " closest point (" << r.normalFilterFallbacks
              << " where nothing passed the normal filter), " << r.closestNeighbours << " closest neighbours, " << r.inpainted << " inpainted, " << r.smoothed << " smoothed, "
              << int(r.milliseconds) << " ms\n";
}

// Every file's chunks, in the order given, merged: the newest of a name wins.
std::optional<std::vector<skin::SkinChunk>> readChunkFiles(const std::vector<std::string>& files)
{
    std::vector<skin::SkinChunk> all;
    for (const std::string& file : files) {
        auto chunks = io::loadSkinChunkFile(file);
        print(chunks.diagnostics());
        if (!chunks)
            return std::nullopt;
        for (skin::SkinChunk& chunk : *chunks)
            all.push_back(std::move(chunk));
    }
    auto merged = skin::mergeChunks(std::move(all));
    print(merged.diagnostics());
    return merged.take();
}

} // namespace

int runSkinImport(const std::vector<std::string>& args)
{
    ImportArguments m;
    if (const int usage = parseImport(args, m))
        return usage;
    if (!canWriteBeside(io::weightsPathFor(m.guide), "weights"))
        return 1;
    auto chunks = readChunkFiles(m.files);
    if (!chunks)
        return 1;
    auto character = loadCharacter(m.guide);
    if (!character)
        return 1;
    Character& c = *character;
    std::vector<CharacterMesh> targets;
    std::vector<const model::Mesh*> meshes;
    for (const CharacterMesh& mesh : c.meshes)
        if (m.meshes.empty() || m.meshes.count(mesh.mesh->name)) {
            targets.push_back(mesh);
            meshes.push_back(mesh.mesh);
        }
    for (const std::string& name : m.meshes)
        if (std::none_of(targets.begin(), targets.end(), [&](const CharacterMesh& t) { return t.mesh->name == name; })) {
            std::cerr << m.guide << ": error: no mesh named '" << name << "' in the guide's models\n";
            return 1;
        }
    m.options.progress = progressPrinter();
    std::vector<skin::MeshImportReport> reports;
    auto imported = skin::importChunks(*chunks, meshes, m.options, &reports);
    print(imported.diagnostics());
    if (!imported)
        return 1;
    for (std::size_t i = 0; i < targets.size(); ++i) {
        // Onto the rig's skin joints: an influence the rig no longer has goes
        // to its nearest ancestor, with a warning. Weights already on them are
        // kept as they are (a 1:1 import is the file's weights, bit for bit).
        model::MeshWeights& weights = (*imported)[i];
        if (!isOnBones(weights, c.bones)) {
            auto retargeted = skin::retargetWeights(weights, c.bones, targets[i].mesh->name);
            print(retargeted.diagnostics());
            if (!retargeted)
                return 1;
            weights = retargeted.take();
        }
        model::MeshBinding binding{targets[i].model, targets[i].mesh->name, targets[i].mesh->vertexCount(),
                                   model::topologyFingerprint(*targets[i].mesh), std::move(weights)};
        if (targets[i].binding >= 0)
            c.guide.bindings[std::size_t(targets[i].binding)] = std::move(binding);
        else
            c.guide.bindings.push_back(std::move(binding));
        printReport(reports[i]);
    }
    const Status saved = io::saveGuideWeights(c.guide, m.guide);
    print(saved.diagnostics());
    if (saved.failed())
        return 1;
    std::cout << "weights: " << io::weightsPathFor(m.guide) << '\n';
    if (!m.json.empty()) {
        const std::string text = reportJson(m, *chunks, targets, reports);
        if (m.json == "-") {
            std::cout << text;
        } else {
            const Status written = io::writeFileAtomically(m.json, text);
            print(written.diagnostics());
            if (written.failed())
                return 1;
        }
    }
    return 0;
}

} // namespace rs::cli

namespace rs::cli {

namespace {

std::string point(const glm::vec3& p)
{
    std::ostringstream out;
    out.precision(5);
    out << '(' << p.x << ' ' << p.y << ' ' << p.z << ')';
    return out.str();
}

std::string translation(const Mat4& m) { return point(glm::vec3(m[3])); }

std::string keyText(const NodeKey& key)
{
    std::ostringstream out; // (not string +: GCC 12 warns falsely on it, -Wrestrict)
    out << '#' << key.instance << (key.branch.empty() ? "" : ".") << key.branch << "::" << key.tag;
    return out.str();
}

void printChunk(const skin::SkinChunk& c, std::size_t index, std::size_t from, std::size_t limit)
{
    std::cout << "chunk " << index << ": " << c.mesh << "\n  model: " << c.model << "\n  exported: " << skin::formatExportTime(c.exportedAtMicroseconds)
              << " by " << (c.user.empty() ? "(unknown)" : c.user) << " with " << c.tool << "\n  mesh: " << c.totalVertexCount
              << " vertices, topology fingerprint " << std::hex << c.fingerprint << std::dec << "\n  exported vertices: " << c.vertexCount()
              << (c.vertexCount() == c.totalVertexCount ? " (all)" : " (a subset)") << ", " << c.triangles.size() / 3 << " triangles among them, "
              << c.neighbours.size() << " neighbours sampled\n  skinning: "
              << (c.method == skin::SkinningMethod::DualQuaternion ? "dual quaternion" : "linear blend") << "; "
              << (c.inBindPose ? "exported in bind pose" : "exported posed (bind positions and normals kept too)") << '\n';
    const std::size_t joints = c.joints.size(), vertices = c.vertexCount();
    std::cout << "  influences: " << joints;
    if (from < joints)
        std::cout << " (" << from << " to " << std::min(joints, from + limit) - 1 << ")";
    std::cout << '\n';
    for (std::size_t j = from; j < joints && j < from + limit; ++j) {
        const std::int32_t parent = c.weights.parents[j];
        std::cout << "    " << j << ' ' << c.joints[j].name << ' ' << keyText(c.joints[j].key) << " parent "
                  << (parent < 0 ? std::string("-") : c.joints[std::size_t(parent)].name) << " bind at " << translation(c.joints[j].bind)
                  << " now at " << translation(c.joints[j].world) << '\n';
    }
    std::cout << "  vertices: " << vertices;
    if (from < vertices)
        std::cout << " (" << from << " to " << std::min(vertices, from + limit) - 1 << ")";
    std::cout << '\n';
    for (std::size_t i = from; i < vertices && i < from + limit; ++i) {
        std::cout << "    " << i << " id " << c.vertexIds[i] << " at " << point(c.positions[i]);
        if (!c.inBindPose)
            std::cout << " bind " << point(c.bindPositions[i]);
        std::cout << " normal " << point(c.normals[i]) << " weights";
        for (const model::Influence* w = c.weights.begin(i); w != c.weights.end(i); ++w)
            std::cout << ' ' << c.joints[w->joint].name << ' ' << w->weight;
        if (c.neighbourOffsets.size() == vertices + 1 && c.neighbourOffsets[i] < c.neighbourOffsets[i + 1]) {
            std::cout << " neighbours";
            for (std::uint32_t k = c.neighbourOffsets[i]; k < c.neighbourOffsets[i + 1]; ++k)
                std::cout << ' ' << c.neighbours[k];
        }
        std::cout << '\n';
    }
}

} // namespace

int runSkinInfo(const std::vector<std::string>& args)
{
    std::string file, mesh;
    int limit = 10, from = 0;
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& a = args[i];
        const bool hasValue = i + 1 < args.size();
        if (a == "--limit" && hasValue) {
            if (!parseCount(args[++i], 0, 1 << 30, limit))
                return usageError("skin info", "--limit is a whole number of rows, not '" + args[i] + "'");
        } else if (a == "--from" && hasValue) {
            if (!parseCount(args[++i], 0, 1 << 30, from))
                return usageError("skin info", "--from is the first index to print, not '" + args[i] + "'");
        } else if (a == "--mesh" && hasValue) {
            mesh = args[++i];
        } else if (file.empty() && !a.empty() && a[0] != '-') {
            file = a;
        } else {
            return usageError("skin info", "unexpected argument '" + a + "'");
        }
    }
    if (file.empty())
        return usageError("skin info", "expected FILE");
    auto chunks = io::loadSkinChunkFile(file);
    print(chunks.diagnostics());
    if (!chunks)
        return 1;
    std::cout << file << ": " << chunks->size() << (chunks->size() == 1 ? " chunk\n" : " chunks\n");
    bool shown = false;
    for (std::size_t k = 0; k < chunks->size(); ++k)
        if (mesh.empty() || (*chunks)[k].mesh == mesh) {
            printChunk((*chunks)[k], k, std::size_t(from), std::size_t(limit));
            shown = true;
        }
    if (!shown && !mesh.empty()) {
        std::cerr << file << ": error: no chunk of a mesh named '" << mesh << "'\n";
        return 1;
    }
    return 0;
}

} // namespace rs::cli
