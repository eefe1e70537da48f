#include "io/FbxRepair.h"

#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

namespace rs::io {

namespace {

constexpr char kMagic[] = "Kaydara FBX Binary  ";
constexpr std::size_t kHeaderSize = 27;
// The fixed start of the FBX footer ("footer id") that follows the top-level records.
constexpr unsigned char kFooterId[] = {0xfa, 0xbc, 0xab, 0x09, 0xd0, 0xc8, 0xd4, 0x66,
                                       0xb1, 0x76, 0xfb, 0x83, 0x1c, 0xf7, 0x26, 0x7e};

struct Record {
    std::string head;       // numProperties, propertyListLength, nameLength, name, properties
    std::vector<Record> children;
    bool hadNullRecord = false;
    bool hasProperties = false;
};

class Reader {
public:
    Reader(const std::string& bytes, bool wide) : m_bytes(bytes), m_wide(wide) {}

    std::size_t field() const { return m_wide ? 8 : 4; }
    std::size_t nullSize() const { return 3 * field() + 1; }

    std::uint64_t readField(std::size_t at) const
    {
        std::uint64_t value = 0;
        std::memcpy(&value, m_bytes.data() + at, field()); // little-endian host (x86-64, ARM64)
        return value;
    }
    bool isNull(std::size_t at) const
    {
        if (at + nullSize() > m_bytes.size())
            return false;
        for (std::size_t i = 0; i < nullSize(); ++i)
            if (m_bytes[at + i] != 0)
                return false;
        return true;
    }

    // The record at `at`, which must end by `limit`; false when it is not one.
    bool read(std::size_t at, std::size_t limit, Record& out, std::size_t& end) const
    {
        if (at + nullSize() > limit)
            return false;
        end = std::size_t(readField(at));
        const std::uint64_t properties = readField(at + field());
        const std::uint64_t propertyBytes = readField(at + 2 * field());
        const std::size_t nameAt = at + 3 * field();
        const std::size_t nameLength = static_cast<unsigned char>(m_bytes[nameAt]);
        const std::size_t childrenAt = nameAt + 1 + nameLength + std::size_t(propertyBytes);
        if (end <= at || end > limit || childrenAt > end)
            return false;
        out.head.assign(m_bytes, at + field(), childrenAt - at - field());
        out.hasProperties = properties > 0;
        for (std::size_t p = childrenAt; p < end;) {
            if (isNull(p)) { // no record ends at offset 0: all zeros is a null record
                out.hadNullRecord = true;
                p += nullSize();
                continue;
            }
            Record child;
            std::size_t childEnd = 0;
            if (!read(p, end, child, childEnd))
                return false;
            out.children.push_back(std::move(child));
            p = childEnd;
        }
        return true;
    }

private:
    const std::string& m_bytes;
    bool m_wide;
};

class Writer {
public:
    explicit Writer(bool wide) : m_wide(wide) {}
    std::string out;

    void field(std::uint64_t value) { out.append(reinterpret_cast<const char*>(&value), m_wide ? 8 : 4); }
    void nullRecord() { out.append(3 * (m_wide ? 8 : 4) + 1, '\0'); }

    void write(const Record& record)
    {
        const std::size_t start = out.size();
        field(0); // end offset, patched below
        out += record.head;
        for (const auto& child : record.children)
            write(child);
        if (!record.children.empty() || record.hadNullRecord || !record.hasProperties)
            nullRecord();
        const std::uint64_t end = out.size();
        std::memcpy(out.data() + start, &end, m_wide ? 8 : 4);
    }

private:
    bool m_wide;
};

// The footer as FBX writers lay it out: id, 4 zero bytes, zero padding to a
// 16-byte boundary (16 when already aligned), version, 120 zero bytes, magic.
std::string alignedFooter(const std::string& footer, std::size_t offset)
{
    if (footer.size() < 16 + 4 + 4 + 120 + 16 || std::memcmp(footer.data(), kFooterId, 16) != 0)
        return footer; // not the usual layout: keep it as it is
    const std::string tail = footer.substr(footer.size() - (4 + 120 + 16));
    std::string out = footer.substr(0, 20);
    const std::size_t at = offset + out.size();
    std::size_t pad = ((at + 15) & ~std::size_t(15)) - at;
    if (pad == 0)
        pad = 16;
    return out + std::string(pad, '\0') + tail;
}

} // namespace

Result<std::string> repairFbxNullRecords(const std::string& bytes)
{
    if (bytes.size() < kHeaderSize || bytes.compare(0, sizeof(kMagic) - 1, kMagic) != 0)
        return Result<std::string>::failure(makeError({}, "not a binary FBX file"));
    std::uint32_t version = 0;
    std::memcpy(&version, bytes.data() + 23, 4);
    const bool wide = version >= 7500;
    Reader reader(bytes, wide);
    std::vector<Record> top;
    std::size_t p = kHeaderSize;
    while (p + reader.nullSize() <= bytes.size()) {
        if (reader.isNull(p)) {
            p += reader.nullSize();
            break;
        }
        Record record;
        std::size_t end = 0;
        if (!reader.read(p, bytes.size(), record, end))
            break; // the footer
        top.push_back(std::move(record));
        p = end;
    }
    if (top.empty())
        return Result<std::string>::failure(makeError({}, "the FBX file has no records"));
    Writer writer(wide);
    writer.out = bytes.substr(0, kHeaderSize);
    for (const auto& record : top)
        writer.write(record);
    writer.nullRecord();
    writer.out += alignedFooter(bytes.substr(p), writer.out.size());
    return std::move(writer.out);
}

} // namespace rs::io
