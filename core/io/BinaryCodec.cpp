#include "io/BinaryCodec.h"

#include <cmath>
#include <filesystem>
#include <fstream>

namespace rs::io::binary {

std::uint64_t fnv1a(const char* data, std::size_t size)
{
    std::uint64_t h = 1469598103934665603ull;
    for (std::size_t i = 0; i < size; ++i) {
        h ^= std::uint8_t(data[i]);
        h *= 1099511628211ull;
    }
    return h;
}

void Writer::text(const std::string& s)
{
    raw(std::uint32_t(s.size()));
    out += s;
}

void Writer::matrix(const Mat4& m)
{
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            raw(m[c][r]);
}

void Writer::influences(const std::vector<model::Influence>& values)
{
    raw(std::uint32_t(values.size()));
    for (const model::Influence& influence : values) {
        raw(influence.joint);
        raw(influence.weight);
    }
}

std::string Writer::finish()
{
    raw(fnv1a(out.data(), out.size()));
    return std::move(out);
}

bool Reader::fail(const std::string& what, std::size_t where)
{
    if (error.empty())
        error = context + what + " at byte " + std::to_string(where);
    return false;
}

bool Reader::text(std::string& s)
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

bool Reader::count(std::uint32_t& n, std::size_t itemBytes, const char* what)
{
    const std::size_t where = at;
    if (!raw(n))
        return false;
    if (std::size_t(n) > left() / std::max<std::size_t>(itemBytes, 1))
        return fail(std::string("a count of ") + std::to_string(n) + " " + what + " is more than the file holds", where);
    return true;
}

bool Reader::matrix(Mat4& m)
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

bool Reader::points(std::vector<glm::vec3>& values, std::size_t n, const char* what)
{
    const std::size_t where = at;
    if (!array(values, n))
        return false;
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(values[i].x) || !std::isfinite(values[i].y) || !std::isfinite(values[i].z))
            return fail(std::string(what) + " of vertex " + std::to_string(i) + " is not finite", where + i * 12);
    return true;
}

bool Reader::offsets(std::vector<std::uint32_t>& values, std::size_t n, std::uint32_t total, const char* what)
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

bool Reader::influences(std::vector<model::Influence>& values, std::size_t n, std::size_t jointCount)
{
    const std::size_t where = at;
    if (n > left() / 8)
        return fail("the weights run past the end of the file");
    values.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        model::Influence& influence = values[k];
        raw(influence.joint);
        raw(influence.weight);
        if (influence.joint >= jointCount)
            return fail("a weight names influence " + std::to_string(influence.joint) + ", which is not listed", where + 8 * k);
        if (!std::isfinite(influence.weight) || influence.weight < 0.0f || influence.weight > 1.0001f)
            return fail("a weight is outside [0, 1]", where + 8 * k + 4);
    }
    return true;
}

Result<std::string> readWholeFile(const std::string& path, const std::string& kind, std::uintmax_t maxBytes)
{
    auto failure = [&](const std::string& message) { return Result<std::string>::failure(makeError({path, 0, 0}, message)); };
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return failure("no such " + kind + " file (or not a regular file)");
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec || size > maxBytes)
        return failure("the " + kind + " file is larger than " + std::to_string(maxBytes >> 20) + " MB (or its size cannot be read)");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return failure("cannot open the " + kind + " file");
    std::string bytes(std::size_t(size), '\0');
    in.read(bytes.data(), std::streamsize(size));
    if (std::size_t(in.gcount()) != size)
        return failure("cannot read the " + kind + " file whole (it changed while being read?)");
    return bytes;
}

std::string checkEnvelope(const std::string& bytes, const char (&magic)[8], const std::string& kind)
{
    if (bytes.size() < sizeof(magic) || std::memcmp(bytes.data(), magic, sizeof(magic)) != 0)
        return "not a Rigsmith " + kind + " file (it does not start with " + std::string(magic, sizeof(magic)) + ")";
    if (bytes.size() < sizeof(magic) + 16)
        return "the " + kind + " file ends early at byte " + std::to_string(bytes.size()) + " (it is too short for its header)";
    std::uint64_t stored = 0;
    std::memcpy(&stored, bytes.data() + bytes.size() - 8, 8);
    if (stored != fnv1a(bytes.data(), bytes.size() - 8))
        return "the " + kind + " file is damaged or truncated: its checksum (the last 8 bytes, at byte " + std::to_string(bytes.size() - 8) +
               ") does not match its " + std::to_string(bytes.size() - 8) + " bytes";
    return {};
}

} // namespace rs::io::binary
