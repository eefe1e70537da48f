#include "io/WeightsFile.h"

#include "io/SkinChunks.h"

#include "io/AtomicFile.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace rs::io {

namespace {

constexpr char kMagic[8] = {'R', 'S', 'W', 'E', 'I', 'G', 'H', 'T'};
constexpr std::uint32_t kVersion = 1;

std::uint64_t fnv1a(const char* data, std::size_t size)
{
    std::uint64_t h = 1469598103934665603ull;
    for (std::size_t i = 0; i < size; ++i) {
        h ^= std::uint8_t(data[i]);
        h *= 1099511628211ull;
    }
    return h;
}

struct Writer {
    std::string out;
    template <class T>
    void raw(T value)
    {
        char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T)); // x86-64 and ARM64: little-endian
        out.append(bytes, sizeof(T));
    }
    void text(const std::string& s)
    {
        raw(std::uint32_t(s.size()));
        out += s;
    }
};

struct Reader {
    const std::string& in;
    const std::string& path;
    std::size_t at = 0;
    std::size_t end = 0;
    std::string error;

    bool fail(const std::string& what)
    {
        if (error.empty())
            error = what + " at byte " + std::to_string(at);
        return false;
    }
    template <class T>
    bool raw(T& value)
    {
        if (end - at < sizeof(T))
            return fail("the file ends early");
        std::memcpy(&value, in.data() + at, sizeof(T));
        at += sizeof(T);
        return true;
    }
    bool text(std::string& s)
    {
        std::uint32_t size = 0;
        if (!raw(size))
            return false;
        if (end - at < size)
            return fail("a name runs past the end of the file");
        s.assign(in.data() + at, size);
        at += size;
        return true;
    }
    // A count of items of `itemBytes` each that must fit in what is left.
    bool count(std::uint32_t& n, std::size_t itemBytes)
    {
        if (!raw(n))
            return false;
        if (std::size_t(n) > (end - at) / std::max<std::size_t>(itemBytes, 1))
            return fail("a count of " + std::to_string(n) + " is more than the file holds");
        return true;
    }
};

} // namespace

std::uint64_t weightsChecksum(const char* data, std::size_t size) { return fnv1a(data, size); }

std::string writeWeights(const std::vector<BoundMesh>& meshes)
{
    Writer w;
    w.out.append(kMagic, sizeof(kMagic));
    w.raw(kVersion);
    w.raw(std::uint32_t(meshes.size()));
    for (const BoundMesh& mesh : meshes) {
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
        for (std::uint32_t offset : mesh.weights.offsets)
            w.raw(offset);
        for (const model::Influence& influence : mesh.weights.influences) {
            w.raw(influence.joint);
            w.raw(influence.weight);
        }
    }
    w.raw(fnv1a(w.out.data(), w.out.size()));
    return w.out;
}

Result<std::vector<BoundMesh>> readWeights(const std::string& bytes, const std::string& path)
{
    using Out = Result<std::vector<BoundMesh>>;
    auto failure = [&](const std::string& message) { return Out::failure(makeError({path, 0, 0}, message)); };
    if (bytes.size() < sizeof(kMagic) + 16 || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
        return failure("not a Rigsmith weights file");
    std::uint64_t stored = 0;
    std::memcpy(&stored, bytes.data() + bytes.size() - 8, 8);
    if (stored != fnv1a(bytes.data(), bytes.size() - 8))
        return failure("the weights file is damaged (its checksum does not match)");
    Reader r{bytes, path, sizeof(kMagic), bytes.size() - 8, {}};
    std::uint32_t version = 0, meshCount = 0;
    r.raw(version);
    if (version != kVersion)
        return failure("weights file version " + std::to_string(version) + " is not one this Rigsmith reads (1)");
    std::vector<BoundMesh> meshes;
    if (r.count(meshCount, 28)) {
        for (std::uint32_t m = 0; m < meshCount && r.error.empty(); ++m) {
            BoundMesh mesh;
            std::uint32_t vertices = 0, joints = 0, influences = 0;
            if (!r.text(mesh.model) || !r.text(mesh.name) || !r.raw(vertices) || !r.raw(mesh.fingerprint) || !r.count(joints, 16))
                break;
            mesh.vertexCount = vertices;
            for (std::uint32_t j = 0; j < joints && r.error.empty(); ++j) {
                NodeKey key;
                std::uint32_t instance = 0;
                std::int32_t parent = -1;
                if (r.raw(instance) && r.text(key.branch) && r.text(key.tag) && r.raw(parent)) {
                    if (parent < -1 || parent >= std::int32_t(joints) || parent == std::int32_t(j))
                        r.fail("mesh '" + mesh.name + "': joint " + std::to_string(j) + " has a parent it does not list");
                    key.instance = instance;
                    mesh.weights.joints.push_back(std::move(key));
                    mesh.weights.parents.push_back(parent);
                }
            }
            if (!r.error.empty() || !r.count(influences, 8))
                break;
            if (std::size_t(vertices) + 1 > (r.end - r.at) / 4) {
                r.fail("a vertex count of " + std::to_string(vertices) + " is more than the file holds");
                break;
            }
            mesh.weights.offsets.resize(std::size_t(vertices) + 1);
            for (auto& offset : mesh.weights.offsets)
                r.raw(offset);
            if (mesh.weights.offsets.front() != 0 || mesh.weights.offsets.back() != influences)
                r.fail("mesh '" + mesh.name + "': the influence offsets do not cover its influences");
            for (std::size_t v = 0; v + 1 < mesh.weights.offsets.size(); ++v)
                if (mesh.weights.offsets[v] > mesh.weights.offsets[v + 1])
                    r.fail("mesh '" + mesh.name + "': vertex " + std::to_string(v) + "'s influences run backwards");
            if (!r.error.empty() || std::size_t(influences) > (r.end - r.at) / 8) {
                r.fail("the influences run past the end of the file");
                break;
            }
            mesh.weights.influences.resize(influences);
            for (auto& influence : mesh.weights.influences) {
                r.raw(influence.joint);
                r.raw(influence.weight);
                if (influence.joint >= joints || !std::isfinite(influence.weight) || influence.weight < 0.0f || influence.weight > 1.0001f)
                    r.fail("mesh '" + mesh.name + "': an influence names a joint it does not list or has a weight outside [0, 1]");
            }
            meshes.push_back(std::move(mesh));
        }
    }
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
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return Result<std::vector<BoundMesh>>::failure(makeError({path, 0, 0}, "no such weights file (or not a regular file)"));
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return Result<std::vector<BoundMesh>>::failure(makeError({path, 0, 0}, "cannot open the weights file"));
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return readWeights(bytes.str(), path);
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
