#include "io/FbxBinary.h"

#include <cstring>
#include <limits>

namespace rs::io::fbx {

namespace {

constexpr char kMagic[] = "Kaydara FBX Binary  "; // followed by \0, 0x1A, 0x00
// The footer's opening id and closing magic: the fixed bytes FBX files carry
// (the id is the one most writers use; readers do not check it).
constexpr unsigned char kFooterId[16] = {0xfa, 0xbc, 0xab, 0x09, 0xd0, 0xc8, 0xd4, 0x66,
                                         0xb1, 0x76, 0xfb, 0x83, 0x1c, 0xf7, 0x26, 0x7e};
constexpr unsigned char kFooterMagic[16] = {0xf8, 0x5a, 0x8c, 0x6a, 0xde, 0xf5, 0xd9, 0x7e,
                                            0xec, 0xe9, 0x0c, 0xe3, 0x75, 0x8f, 0x29, 0x0b};

template <typename T>
void put(std::string& out, T value) // little-endian host (x86-64, ARM64)
{
    out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

class Writer {
public:
    Writer(std::uint32_t version) : m_wide(version >= kVersion75) {}
    std::string out;
    std::string error;

    void field(std::uint64_t v) { m_wide ? put<std::uint64_t>(out, v) : put<std::uint32_t>(out, std::uint32_t(v)); }
    void nullRecord() { out.append(m_wide ? 25 : 13, '\0'); }

    void record(const Node& node)
    {
        if (node.name().size() > 255) {
            error = "FBX record name longer than 255 bytes: " + node.name().substr(0, 32) + "...";
            return;
        }
        const std::size_t start = out.size();
        field(0); // EndOffset, patched below
        field(node.propertyCount());
        field(node.encodedProperties().size());
        out.push_back(char(node.name().size()));
        out += node.name();
        out += node.encodedProperties();
        for (const Node& child : node.children())
            record(child);
        if (!node.children().empty() || node.propertyCount() == 0)
            nullRecord();
        const std::uint64_t end = out.size();
        if (!m_wide && end > std::numeric_limits<std::uint32_t>::max())
            error = "the FBX file is larger than 4 GiB: version 7500 is needed";
        std::memcpy(out.data() + start, &end, m_wide ? 8 : 4);
    }

private:
    bool m_wide;
};

} // namespace

void Node::scalar(char type, const void* data, std::size_t size)
{
    m_properties.push_back(type);
    m_properties.append(static_cast<const char*>(data), size);
    ++m_count;
}

void Node::array(char type, const void* data, std::size_t count, std::size_t elementSize)
{
    m_properties.push_back(type);
    put<std::uint32_t>(m_properties, std::uint32_t(count));
    put<std::uint32_t>(m_properties, 0); // encoding: raw
    put<std::uint32_t>(m_properties, std::uint32_t(count * elementSize));
    m_properties.append(static_cast<const char*>(data), count * elementSize);
    ++m_count;
}

Node& Node::addInt16(std::int16_t v) { scalar('Y', &v, sizeof v); return *this; }
Node& Node::addBool(bool v) { const std::uint8_t b = v ? 1 : 0; scalar('C', &b, 1); return *this; }
Node& Node::addInt32(std::int32_t v) { scalar('I', &v, sizeof v); return *this; }
Node& Node::addFloat(float v) { scalar('F', &v, sizeof v); return *this; }
Node& Node::addDouble(double v) { scalar('D', &v, sizeof v); return *this; }
Node& Node::addInt64(std::int64_t v) { scalar('L', &v, sizeof v); return *this; }

Node& Node::addString(std::string_view v)
{
    m_properties.push_back('S');
    put<std::uint32_t>(m_properties, std::uint32_t(v.size()));
    m_properties += v;
    ++m_count;
    return *this;
}

Node& Node::addRaw(std::string_view bytes)
{
    addString(bytes);
    m_properties[m_properties.size() - bytes.size() - 5] = 'R';
    return *this;
}

Node& Node::addFloats(std::span<const float> v) { array('f', v.data(), v.size(), 4); return *this; }
Node& Node::addDoubles(std::span<const double> v) { array('d', v.data(), v.size(), 8); return *this; }
Node& Node::addInt64s(std::span<const std::int64_t> v) { array('l', v.data(), v.size(), 8); return *this; }
Node& Node::addInt32s(std::span<const std::int32_t> v) { array('i', v.data(), v.size(), 4); return *this; }
Node& Node::addBools(std::span<const std::uint8_t> v) { array('b', v.data(), v.size(), 1); return *this; }

std::string objectName(std::string_view name, std::string_view className)
{
    std::string out(name);
    out += '\0';
    out += '\x01';
    out += className;
    return out;
}

Result<std::string> serialise(const std::deque<Node>& topLevel, std::uint32_t version)
{
    Writer w(version);
    w.out.append(kMagic, sizeof kMagic); // with its terminating \0
    w.out += '\x1a';
    w.out += '\0';
    put<std::uint32_t>(w.out, version);
    for (const Node& node : topLevel) {
        w.record(node);
        if (!w.error.empty())
            break;
    }
    if (!w.error.empty())
        return Result<std::string>::refused(w.error);
    w.nullRecord();
    w.out.append(reinterpret_cast<const char*>(kFooterId), 16);
    w.out.append(4, '\0');
    const std::size_t pad = 16 - w.out.size() % 16; // 16 when already aligned
    w.out.append(pad, '\0');
    put<std::uint32_t>(w.out, version);
    w.out.append(120, '\0');
    w.out.append(reinterpret_cast<const char*>(kFooterMagic), 16);
    return std::move(w.out);
}

} // namespace rs::io::fbx
