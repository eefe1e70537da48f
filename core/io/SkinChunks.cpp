#include "io/SkinChunks.h"

#include "io/AtomicFile.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace rs::io {

namespace {

constexpr char kMagic[8] = {'R', 'S', 'C', 'H', 'U', 'N', 'K', 'S'};
constexpr std::uint32_t kVersion = 1;
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(2) << 30;

std::uint64_t fnv1a(const char* data, std::size_t size)
{
    std::uint64_t h = 1469598103934665603ull;
    for (std::size_t i = 0; i < size; ++i) {
        h ^= std::uint8_t(data[i]);
        h *= 1099511628211ull;
    }
    return h;
}

// The host is little-endian (x86-64, ARM64): values are copied as they are.
struct Writer {
    std::string out;
    template <class T>
    void raw(T value)
    {
        char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        out.append(bytes, sizeof(T));
    }
    template <class T>
    void array(const std::vector<T>& values, std::size_t count)
    {
        if (count > 0)
            out.append(reinterpret_cast<const char*>(values.data()), count * sizeof(T));
    }
    template <class T>
    void array(const std::vector<T>& values) { array(values, values.size()); }
    void text(const std::string& s)
    {
        raw(std::uint32_t(s.size()));
        out += s;
    }
    void matrix(const Mat4& m)
    {
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                raw(m[c][r]);
    }
};

struct Reader {
    const std::string& in;
    std::size_t at = 0;
    std::size_t end = 0;
    std::string context; // "chunk 2 ('body'): "
    std::string error;

    std::size_t left() const { return end - at; }
    bool fail(const std::string& what, std::size_t where)
    {
        if (error.empty())
            error = context + what + " at byte " + std::to_string(where);
        return false;
    }
    bool fail(const std::string& what) { return fail(what, at); }
    template <class T>
    bool raw(T& value)
    {
        if (left() < sizeof(T))
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
        if (left() < size)
            return fail("a name of " + std::to_string(size) + " bytes runs past the end of the file");
        s.assign(in.data() + at, size);
        at += size;
        return true;
    }
    // A count of items of at least `itemBytes` each, which must fit in what is left.
    bool count(std::uint32_t& n, std::size_t itemBytes, const char* what)
    {
        const std::size_t where = at;
        if (!raw(n))
            return false;
        if (std::size_t(n) > left() / itemBytes)
            return fail(std::string("a count of ") + std::to_string(n) + " " + what + " is more than the file holds", where);
        return true;
    }
    template <class T>
    bool array(std::vector<T>& values, std::size_t n)
    {
        if (n > left() / sizeof(T))
            return fail("the file ends early");
        values.resize(n);
        if (n > 0) // (memcpy from or to no buffer is undefined even for 0 bytes)
            std::memcpy(values.data(), in.data() + at, n * sizeof(T));
        at += n * sizeof(T);
        return true;
    }
    bool matrix(Mat4& m)
    {
        const std::size_t where = at;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!raw(m[c][r]))
                    return false;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(m[c][r]))
                    return fail("a matrix has a value that is not a finite number", where);
        return true;
    }
    bool points(std::vector<glm::vec3>& values, std::size_t n, const char* what)
    {
        const std::size_t where = at;
        if (!array(values, n))
            return false;
        for (std::size_t i = 0; i < n; ++i)
            if (!std::isfinite(values[i].x) || !std::isfinite(values[i].y) || !std::isfinite(values[i].z))
                return fail(std::string(what) + " of vertex " + std::to_string(i) + " is not finite", where + i * 12);
        return true;
    }
    // offsets[n + 1] from 0, never decreasing, ending at `total`.
    bool offsets(std::vector<std::uint32_t>& values, std::size_t n, std::uint32_t total, const char* what)
    {
        const std::size_t where = at;
        if (!array(values, n + 1))
            return false;
        if (values.front() != 0)
            return fail(std::string("the ") + what + " offsets do not start at 0", where);
        for (std::size_t i = 0; i < n; ++i)
            if (values[i] > values[i + 1])
                return fail(std::string("vertex ") + std::to_string(i) + "'s " + what + " run backwards", where + 4 * (i + 1));
        if (values.back() != total)
            return fail(std::string("the ") + what + " offsets end at " + std::to_string(values.back()) + ", not at their count " +
                            std::to_string(total),
                        where + 4 * n);
        return true;
    }
};

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
    const std::size_t weightsAt = r.at;
    if (std::size_t(weights) > r.left() / 8)
        return r.fail("the weights run past the end of the file");
    c.weights.influences.resize(weights);
    for (std::size_t k = 0; k < weights; ++k) {
        model::Influence& influence = c.weights.influences[k];
        r.raw(influence.joint);
        r.raw(influence.weight);
        if (influence.joint >= c.joints.size())
            return r.fail("a weight names influence " + std::to_string(influence.joint) + ", which the chunk does not list", weightsAt + 8 * k);
        if (!std::isfinite(influence.weight) || influence.weight < 0.0f || influence.weight > 1.0001f)
            return r.fail("a weight is outside [0, 1]", weightsAt + 8 * k + 4);
    }
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
    w.raw(fnv1a(w.out.data(), w.out.size()));
    return w.out;
}

Result<std::vector<skin::SkinChunk>> readSkinChunks(const std::string& bytes, const std::string& path)
{
    using Out = Result<std::vector<skin::SkinChunk>>;
    auto failure = [&](const std::string& message) { return Out::failure(makeError({path, 0, 0}, message)); };
    if (bytes.size() < sizeof(kMagic) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
        return failure("not a Rigsmith skin chunk file (it does not start with RSCHUNKS)");
    if (bytes.size() < sizeof(kMagic) + 16)
        return failure("the skin chunk file ends early at byte " + std::to_string(bytes.size()) + " (it is too short for its header)");
    std::uint64_t stored = 0;
    std::memcpy(&stored, bytes.data() + bytes.size() - 8, 8);
    if (stored != fnv1a(bytes.data(), bytes.size() - 8))
        return failure("the skin chunk file is damaged or truncated: its checksum (the last 8 bytes, at byte " +
                       std::to_string(bytes.size() - 8) + ") does not match its " + std::to_string(bytes.size() - 8) + " bytes");
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
    using Out = Result<std::vector<skin::SkinChunk>>;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return Out::failure(makeError({path, 0, 0}, "no such skin chunk file (or not a regular file)"));
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec || size > kMaxFileBytes)
        return Out::failure(makeError({path, 0, 0}, "the skin chunk file is larger than 2 GB (or its size cannot be read)"));
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return Out::failure(makeError({path, 0, 0}, "cannot open the skin chunk file"));
    std::string bytes(std::size_t(size), '\0');
    in.read(bytes.data(), std::streamsize(size));
    if (std::size_t(in.gcount()) != size)
        return Out::failure(makeError({path, 0, 0}, "cannot read the skin chunk file whole (it changed while being read?)"));
    return readSkinChunks(bytes, path);
}

} // namespace rs::io
