#pragma once
// The byte-level codec the binary files share (io/WeightsFile.h,
// io/SkinChunks.h): little-endian values, length-prefixed UTF-8 strings,
// FNV-1a checksums, and a reader that checks every count against the bytes
// left and says at which byte a file breaks. io-internal: the file formats
// are documented in their own headers.
#include "base/Math.h"
#include "base/Result.h"
#include "model/Mesh.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace rs::io::binary {

// FNV-1a, 64 bits: the checksum both formats end with.
std::uint64_t fnv1a(const char* data, std::size_t size);

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
    void text(const std::string& s);
    void matrix(const Mat4& m); // f64[16], column-major
    // u32 count, then {u32 joint, f32 weight} per influence.
    void influences(const std::vector<model::Influence>& influences);
    // Appends the checksum of everything written so far and returns the bytes.
    std::string finish();
};

struct Reader {
    const std::string& in;
    std::size_t at = 0;
    std::size_t end = 0; // where the checksum starts
    std::string context; // prefixes every error: "chunk 2 ('body'): "
    std::string error;   // the first failure, "... at byte N"

    std::size_t left() const { return end - at; }
    bool fail(const std::string& what, std::size_t where);
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
    bool text(std::string& s);
    // A count of items of at least `itemBytes` each, which must fit in what is left.
    bool count(std::uint32_t& n, std::size_t itemBytes, const char* what);
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
    bool matrix(Mat4& m); // finite values only
    bool points(std::vector<glm::vec3>& values, std::size_t n, const char* what); // finite values only
    // offsets[n + 1] from 0, never decreasing, ending at `total`.
    bool offsets(std::vector<std::uint32_t>& values, std::size_t n, std::uint32_t total, const char* what);
    // `n` influences {u32 joint < jointCount, f32 weight in [0, 1]}.
    bool influences(std::vector<model::Influence>& values, std::size_t n, std::size_t jointCount);
};

// The whole of a regular file of at most `maxBytes` ("no such <kind> file",
// "the <kind> file is larger than ...", ... naming the path).
Result<std::string> readWholeFile(const std::string& path, const std::string& kind, std::uintmax_t maxBytes);

// Checks the magic (8 bytes), the minimum size (magic, version, a count and
// the checksum) and the checksum; an error message for `kind`, or "".
std::string checkEnvelope(const std::string& bytes, const char (&magic)[8], const std::string& kind);

} // namespace rs::io::binary
