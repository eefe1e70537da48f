#include "io/WeightsFile.h"

#include "io/SkinChunks.h"

#include "io/AtomicFile.h"
#include "io/BinaryCodec.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace rs::io {

namespace {

constexpr char kMagic[8] = {'R', 'S', 'W', 'E', 'I', 'G', 'H', 'T'};
constexpr std::uint32_t kVersion = 1;

constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(2) << 30;

using binary::fnv1a;
using binary::Reader;
using binary::Writer;

void writeMesh(Writer& w, const BoundMesh& mesh)
{
    w.text(mesh.model);
    w.text(mesh.name);
    w.raw(std::uint32_t(mesh.vertexCount));
    w.raw(mesh.fingerprint);
    w.raw(std::uint32_t(mesh.weights.joints.size()));
    for (std::size_t j = 0; j < mesh.weights.joints.size(); ++j) {
        const NodeKey& key = mesh.weights.joints[j];
        w.raw(std::uint32_t(key.instance));
        w.text(key.branch);
        w.text(key.tag);
        w.raw(std::int32_t(j < mesh.weights.parents.size() ? mesh.weights.parents[j] : -1));
    }
    w.raw(std::uint32_t(mesh.weights.influences.size()));
    w.array(mesh.weights.offsets);
    for (const model::Influence& influence : mesh.weights.influences) {
        w.raw(influence.joint);
        w.raw(influence.weight);
    }
}

bool readJoints(Reader& r, BoundMesh& mesh)
{
    std::uint32_t joints = 0;
    if (!r.count(joints, 16, "joints"))
        return false;
    for (std::uint32_t j = 0; j < joints; ++j) {
        NodeKey key;
        std::uint32_t instance = 0;
        std::int32_t parent = -1;
        if (!r.raw(instance) || !r.text(key.branch) || !r.text(key.tag))
            return false;
        const std::size_t parentAt = r.at;
        if (!r.raw(parent))
            return false;
        if (parent < -1 || parent >= std::int32_t(joints) || parent == std::int32_t(j))
            return r.fail("joint " + std::to_string(j) + " has a parent it does not list", parentAt);
        key.instance = instance;
        mesh.weights.joints.push_back(std::move(key));
        mesh.weights.parents.push_back(parent);
    }
    return true;
}

bool readMesh(Reader& r, BoundMesh& mesh)
{
    std::uint32_t vertices = 0, influences = 0;
    if (!r.text(mesh.model) || !r.text(mesh.name))
        return false;
    r.context = "mesh '" + mesh.name + "': ";
    if (!r.raw(vertices) || !r.raw(mesh.fingerprint) || !readJoints(r, mesh) || !r.count(influences, 8, "influences"))
        return false;
    mesh.vertexCount = vertices;
    return r.offsets(mesh.weights.offsets, vertices, influences, "influence") &&
           r.influences(mesh.weights.influences, influences, mesh.weights.joints.size());
}

} // namespace

std::uint64_t weightsChecksum(const char* data, std::size_t size) { return fnv1a(data, size); }

std::string writeWeights(const std::vector<BoundMesh>& meshes)
{
    Writer w;
    w.out.append(kMagic, sizeof(kMagic));
    w.raw(kVersion);
    w.raw(std::uint32_t(meshes.size()));
    for (const BoundMesh& mesh : meshes)
        writeMesh(w, mesh);
    return w.finish();
}

Result<std::vector<BoundMesh>> readWeights(const std::string& bytes, const std::string& path)
{
    using Out = Result<std::vector<BoundMesh>>;
    auto failure = [&](const std::string& message) { return Out::failure(makeError({path, 0, 0}, message)); };
    if (const std::string envelope = binary::checkEnvelope(bytes, kMagic, "weights"); !envelope.empty())
        return failure(envelope);
    Reader r{bytes, sizeof(kMagic), bytes.size() - 8, {}, {}};
    std::uint32_t version = 0, meshCount = 0;
    r.raw(version);
    if (version != kVersion)
        return failure("weights file version " + std::to_string(version) + " is not one this Rigsmith reads (1)");
    std::vector<BoundMesh> meshes;
    // A mesh is at least two names, its counts, fingerprint and one offset.
    if (r.count(meshCount, 28, "meshes")) {
        for (std::uint32_t m = 0; m < meshCount; ++m) {
            BoundMesh mesh;
            if (!readMesh(r, mesh))
                break;
            meshes.push_back(std::move(mesh));
        }
    }
    r.context.clear();
    if (r.error.empty() && r.at != r.end)
        r.fail("unexpected bytes after the last mesh");
    if (!r.error.empty())
        return failure(r.error);
    return meshes;
}

Status saveWeightsFile(const std::string& path, const std::vector<BoundMesh>& meshes)
{
    return writeFileAtomically(path, writeWeights(meshes));
}

Result<std::vector<BoundMesh>> loadWeightsFile(const std::string& path)
{
    auto bytes = binary::readWholeFile(path, "weights", kMaxFileBytes);
    if (!bytes)
        return Result<std::vector<BoundMesh>>::failure(bytes.takeDiagnostics());
    return readWeights(*bytes, path);
}

std::string weightsPathFor(const std::string& guidePath)
{
    return std::filesystem::path(guidePath).replace_extension(".weights").string();
}

Status loadGuideWeights(const std::string& guidePath, model::GuideDocument& document)
{
    const std::string path = weightsPathFor(guidePath);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return {};
    auto loaded = loadWeightsFile(path);
    if (!loaded)
        return Status::failure(loaded.takeDiagnostics());
    const auto folder = std::filesystem::absolute(path).parent_path();
    std::vector<model::MeshBinding> bindings;
    for (BoundMesh& mesh : *loaded)
        bindings.push_back({(folder / mesh.model).lexically_normal().string(), std::move(mesh.name), mesh.vertexCount, mesh.fingerprint,
                            std::move(mesh.weights)});
    document.bindings = std::move(bindings);
    return Status::success(loaded.takeDiagnostics());
}

Status saveGuideWeights(const model::GuideDocument& document, const std::string& guidePath)
{
    if (document.bindings.empty())
        return {};
    const std::string path = weightsPathFor(guidePath);
    const auto folder = std::filesystem::absolute(path).parent_path();
    std::vector<BoundMesh> meshes;
    for (const model::MeshBinding& b : document.bindings)
        meshes.push_back({std::filesystem::path(b.model).lexically_relative(folder).string(), b.mesh, b.vertexCount, b.fingerprint, b.weights});
    return saveWeightsFile(path, meshes);
}

std::string chunksPathFor(const std::string& guidePath)
{
    return std::filesystem::path(guidePath).replace_extension(".weights.rschunks").string();
}

Result<std::vector<skin::SkinChunk>> loadGuideChunks(const std::string& guidePath)
{
    const std::string path = chunksPathFor(guidePath);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return std::vector<skin::SkinChunk>{};
    return loadSkinChunkFile(path);
}

Status saveGuideChunks(const std::vector<skin::SkinChunk>& chunks, const std::string& guidePath)
{
    if (chunks.empty())
        return {};
    return saveSkinChunkFile(chunksPathFor(guidePath), chunks);
}

} // namespace rs::io
