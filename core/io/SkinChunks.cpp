#include "io/SkinChunks.h"

#include "io/AtomicFile.h"
#include "io/BinaryCodec.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace rs::io {

namespace {

constexpr char kMagic[8] = {'R', 'S', 'C', 'H', 'U', 'N', 'K', 'S'};
constexpr std::uint32_t kVersion = 1;
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(2) << 30;

using binary::fnv1a;
using binary::Reader;
using binary::Writer;

void writeChunk(Writer& w, const skin::SkinChunk& c)
{
    w.text(c.mesh);
    w.text(c.model);
    w.text(c.tool);
    w.text(c.user);
    w.raw(c.exportedAtMicroseconds);
    w.raw(c.totalVertexCount);
    w.raw(c.fingerprint);
    w.raw(std::uint8_t(c.method == skin::SkinningMethod::DualQuaternion ? 1 : 0));
    w.raw(std::uint8_t(c.inBindPose ? 1 : 0));
    w.raw(std::uint16_t(0));
    w.raw(std::uint32_t(c.joints.size()));
    for (std::size_t j = 0; j < c.joints.size(); ++j) {
        const skin::ChunkJoint& joint = c.joints[j];
        w.raw(std::uint32_t(joint.key.instance));
        w.text(joint.key.branch);
        w.text(joint.key.tag);
        w.text(joint.name);
        w.raw(std::int32_t(j < c.weights.parents.size() ? c.weights.parents[j] : -1));
        w.matrix(joint.world);
        w.matrix(joint.local);
        w.matrix(joint.bind);
    }
    const std::size_t n = c.vertexIds.size();
    w.raw(std::uint32_t(n));
    w.array(c.vertexIds);
    w.array(c.positions);
    w.array(c.normals);
    if (!c.inBindPose) {
        w.array(c.bindPositions);
        w.array(c.bindNormals);
    }
    w.raw(std::uint32_t(c.weights.influences.size()));
    w.array(c.weights.offsets);
    for (const model::Influence& influence : c.weights.influences) {
        w.raw(influence.joint);
        w.raw(influence.weight);
    }
    w.raw(std::uint32_t(c.triangles.size() / 3));
    w.array(c.triangles, c.triangles.size() / 3 * 3);
    w.raw(std::uint32_t(c.neighbours.size()));
    if (c.neighbourOffsets.size() == n + 1)
        w.array(c.neighbourOffsets);
    else
        w.out.append((n + 1) * 4, '\0');
    w.array(c.neighbours);
}

bool readJoints(Reader& r, skin::SkinChunk& c)
{
    std::uint32_t count = 0;
    // An influence is at least 4 + 3 * 4 + 4 + 3 * 128 bytes.
    if (!r.count(count, 404, "influences"))
        return false;
    for (std::uint32_t j = 0; j < count; ++j) {
        skin::ChunkJoint joint;
        std::uint32_t instance = 0;
        std::int32_t parent = -1;
        const std::size_t where = r.at;
        if (!r.raw(instance) || !r.text(joint.key.branch) || !r.text(joint.key.tag) || !r.text(joint.name))
            return false;
        const std::size_t parentAt = r.at;
        if (!r.raw(parent) || !r.matrix(joint.world) || !r.matrix(joint.local) || !r.matrix(joint.bind))
            return false;
        if (parent < -1 || parent >= std::int32_t(count) || parent == std::int32_t(j))
            return r.fail("influence " + std::to_string(j) + " has a parent it does not list (" + std::to_string(parent) + ")", parentAt);
        if (joint.key.tag.empty())
            return r.fail("influence " + std::to_string(j) + " has no skin joint tag", where);
        joint.key.instance = instance;
        c.weights.joints.push_back(joint.key);
        c.weights.parents.push_back(parent);
        c.joints.push_back(std::move(joint));
    }
    // The parents form a forest: walking up from any influence ends at a root.
    for (std::uint32_t j = 0; j < count; ++j) {
        std::int32_t at = std::int32_t(j);
        for (std::uint32_t steps = 0; at >= 0; ++steps) {
            if (steps > count)
                return r.fail("influence " + std::to_string(j) + "'s parents form a cycle");
            at = c.weights.parents[std::size_t(at)];
        }
    }
    return true;
}

bool readVertices(Reader& r, skin::SkinChunk& c)
{
    std::uint32_t n = 0;
    // Per vertex at least an id, a position, a normal and two offsets.
    if (!r.count(n, 4 + 12 + 12 + 8, "vertices"))
        return false;
    const std::size_t idsAt = r.at;
    if (!r.array(c.vertexIds, n))
        return false;
    for (std::size_t i = 0; i < n; ++i) {
        if (c.vertexIds[i] >= c.totalVertexCount)
            return r.fail("vertex id " + std::to_string(c.vertexIds[i]) + " is not below the mesh's vertex count " +
                              std::to_string(c.totalVertexCount),
                          idsAt + 4 * i);
        if (i > 0 && c.vertexIds[i] <= c.vertexIds[i - 1])
            return r.fail("the vertex ids are not strictly ascending", idsAt + 4 * i);
    }
    if (!r.points(c.positions, n, "the position") || !r.points(c.normals, n, "the normal"))
        return false;
    if (!c.inBindPose && (!r.points(c.bindPositions, n, "the bind position") || !r.points(c.bindNormals, n, "the bind normal")))
        return false;
    std::uint32_t weights = 0;
    if (!r.count(weights, 8, "weights"))
        return false;
    if (!r.offsets(c.weights.offsets, n, weights, "weight"))
        return false;
    if (!r.influences(c.weights.influences, weights, c.joints.size()))
        return false;
    return true;
}

bool readTopology(Reader& r, skin::SkinChunk& c)
{
    const std::size_t n = c.vertexIds.size();
    std::uint32_t triangles = 0;
    if (!r.count(triangles, 12, "triangles"))
        return false;
    const std::size_t trianglesAt = r.at;
    if (!r.array(c.triangles, std::size_t(triangles) * 3))
        return false;
    for (std::size_t k = 0; k < c.triangles.size(); ++k)
        if (c.triangles[k] >= n)
            return r.fail("a triangle corner " + std::to_string(c.triangles[k]) + " is not one of the " + std::to_string(n) +
                              " exported vertices",
                          trianglesAt + 4 * k);
    std::uint32_t neighbours = 0;
    if (!r.count(neighbours, 4, "neighbours"))
        return false;
    if (!r.offsets(c.neighbourOffsets, n, neighbours, "neighbour"))
        return false;
    const std::size_t neighboursAt = r.at;
    if (!r.array(c.neighbours, neighbours))
        return false;
    for (std::size_t k = 0; k < c.neighbours.size(); ++k)
        if (c.neighbours[k] >= c.totalVertexCount)
            return r.fail("a neighbour " + std::to_string(c.neighbours[k]) + " is not one of the mesh's vertices", neighboursAt + 4 * k);
    return true;
}

bool readChunk(Reader& r, skin::SkinChunk& c)
{
    if (!r.text(c.mesh))
        return false;
    r.context.resize(r.context.size() - 2);
    r.context += " ('" + c.mesh + "'): ";
    if (!r.text(c.model) || !r.text(c.tool) || !r.text(c.user))
        return false;
    std::uint8_t method = 0, inBindPose = 0;
    std::uint16_t reserved = 0;
    if (!r.raw(c.exportedAtMicroseconds) || !r.raw(c.totalVertexCount) || !r.raw(c.fingerprint))
        return false;
    const std::size_t flagsAt = r.at;
    if (!r.raw(method) || !r.raw(inBindPose) || !r.raw(reserved))
        return false;
    if (method > 1)
        return r.fail("skinning method " + std::to_string(method) + " is not one this Rigsmith knows (0 linear, 1 dual quaternion)", flagsAt);
    if (inBindPose > 1 || reserved != 0)
        return r.fail("the bind pose flag is not 0 or 1, or the reserved bytes are not 0", flagsAt + 1);
    c.method = method == 1 ? skin::SkinningMethod::DualQuaternion : skin::SkinningMethod::Linear;
    c.inBindPose = inBindPose == 1;
    return readJoints(r, c) && readVertices(r, c) && readTopology(r, c);
}

} // namespace

std::uint64_t skinChunksChecksum(const char* data, std::size_t size) { return fnv1a(data, size); }

std::string writeSkinChunks(const std::vector<skin::SkinChunk>& chunks)
{
    Writer w;
    w.out.append(kMagic, sizeof(kMagic));
    w.raw(kVersion);
    w.raw(std::uint32_t(chunks.size()));
    for (const skin::SkinChunk& chunk : chunks)
        writeChunk(w, chunk);
    return w.finish();
}

Result<std::vector<skin::SkinChunk>> readSkinChunks(const std::string& bytes, const std::string& path)
{
    using Out = Result<std::vector<skin::SkinChunk>>;
    auto failure = [&](const std::string& message) { return Out::failure(makeError({path, 0, 0}, message)); };
    if (const std::string envelope = binary::checkEnvelope(bytes, kMagic, "skin chunk"); !envelope.empty())
        return failure(envelope);
    Reader r{bytes, sizeof(kMagic), bytes.size() - 8, {}, {}};
    std::uint32_t version = 0, count = 0;
    r.raw(version);
    if (version != kVersion)
        return failure("skin chunk file version " + std::to_string(version) + " is not one this Rigsmith reads (1)");
    std::vector<skin::SkinChunk> chunks;
    // A chunk is at least 4 names, its header and three counts with one offset each.
    if (r.count(count, 4 * 4 + 8 + 4 + 8 + 4 + 4 + 4 + 4 + 4 + 4 + 4 + 4, "chunks")) {
        for (std::uint32_t k = 0; k < count && r.error.empty(); ++k) {
            skin::SkinChunk chunk;
            r.context = "chunk " + std::to_string(k) + ": ";
            if (!readChunk(r, chunk))
                break;
            chunks.push_back(std::move(chunk));
        }
    }
    r.context.clear();
    if (r.error.empty() && r.at != r.end)
        r.fail("unexpected bytes after the last chunk");
    if (!r.error.empty())
        return failure(r.error);
    return chunks;
}

Status saveSkinChunkFile(const std::string& path, const std::vector<skin::SkinChunk>& chunks)
{
    return writeFileAtomically(path, writeSkinChunks(chunks));
}

Result<std::vector<skin::SkinChunk>> loadSkinChunkFile(const std::string& path)
{
    auto bytes = binary::readWholeFile(path, "skin chunk", kMaxFileBytes);
    if (!bytes)
        return Result<std::vector<skin::SkinChunk>>::failure(bytes.takeDiagnostics());
    return readSkinChunks(*bytes, path);
}

} // namespace rs::io
