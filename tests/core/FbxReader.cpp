#include "core/FbxReader.h"

#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rs::test {

namespace {

class Parser {
public:
    Parser(const std::string& bytes, bool wide) : m_b(bytes), m_wide(wide) {}

    template <typename T>
    T read(std::size_t at) const
    {
        if (at + sizeof(T) > m_b.size())
            throw std::runtime_error("read past the end at " + std::to_string(at));
        T v;
        std::memcpy(&v, m_b.data() + at, sizeof v);
        return v;
    }
    std::uint64_t field(std::size_t at) const { return m_wide ? read<std::uint64_t>(at) : read<std::uint32_t>(at); }
    std::size_t fieldSize() const { return m_wide ? 8 : 4; }
    std::size_t nullSize() const { return 3 * fieldSize() + 1; }
    bool isNull(std::size_t at) const
    {
        return at + nullSize() <= m_b.size() && m_b.compare(at, nullSize(), std::string(nullSize(), '\0')) == 0;
    }

    // The record at `at`; returns its end.
    std::size_t record(std::size_t at, FbxRecord& out) const
    {
        const std::size_t end = field(at), count = field(at + fieldSize()), length = field(at + 2 * fieldSize());
        std::size_t p = at + 3 * fieldSize();
        const std::size_t nameLength = std::uint8_t(m_b.at(p));
        out.name = m_b.substr(p + 1, nameLength);
        p += 1 + nameLength;
        const std::size_t propertiesEnd = p + length;
        for (std::size_t i = 0; i < count; ++i)
            p = property(p, out.properties.emplace_back());
        if (p != propertiesEnd)
            throw std::runtime_error(out.name + ": PropertyListLen does not match its properties");
        if (end < p || end > m_b.size())
            throw std::runtime_error(out.name + ": EndOffset out of range");
        bool sawNull = false;
        while (p < end) {
            if (isNull(p)) {
                p += nullSize();
                sawNull = true;
                if (p != end)
                    throw std::runtime_error(out.name + ": a null record before the end of its list");
                break;
            }
            p = record(p, out.children.emplace_back());
        }
        if (p != end)
            throw std::runtime_error(out.name + ": children overrun EndOffset");
        if ((!out.children.empty() || count == 0) && !sawNull)
            throw std::runtime_error(out.name + ": nested list without its null record");
        return end;
    }

private:
    std::size_t property(std::size_t p, FbxProperty& out) const
    {
        out.type = m_b.at(p++);
        switch (out.type) {
        case 'Y': out.integer = read<std::int16_t>(p); return p + 2;
        case 'C': out.integer = read<std::uint8_t>(p); return p + 1;
        case 'I': out.integer = read<std::int32_t>(p); return p + 4;
        case 'L': out.integer = read<std::int64_t>(p); return p + 8;
        case 'F': out.number = read<float>(p); return p + 4;
        case 'D': out.number = read<double>(p); return p + 8;
        case 'S':
        case 'R': {
            const std::uint32_t n = read<std::uint32_t>(p);
            out.text = m_b.substr(p + 4, n);
            return p + 4 + n;
        }
        case 'f': case 'd': case 'l': case 'i': case 'b': {
            const std::uint32_t n = read<std::uint32_t>(p), encoding = read<std::uint32_t>(p + 4),
                                bytes = read<std::uint32_t>(p + 8);
            const std::size_t size = out.type == 'd' || out.type == 'l' ? 8 : out.type == 'b' ? 1 : 4;
            if (encoding != 0 || bytes != n * size)
                throw std::runtime_error("array with an unexpected encoding or length");
            p += 12;
            for (std::uint32_t i = 0; i < n; ++i, p += size)
                out.array.push_back(out.type == 'f' ? double(read<float>(p)) : out.type == 'd' ? read<double>(p)
                                    : out.type == 'l' ? double(read<std::int64_t>(p)) : out.type == 'i' ? double(read<std::int32_t>(p))
                                                      : double(read<std::uint8_t>(p)));
            return p;
        }
        }
        throw std::runtime_error(std::string("unknown property type '") + out.type + "'");
    }

    const std::string& m_b;
    bool m_wide;
};

const unsigned char kFooterMagic[16] = {0xf8, 0x5a, 0x8c, 0x6a, 0xde, 0xf5, 0xd9, 0x7e,
                                        0xec, 0xe9, 0x0c, 0xe3, 0x75, 0x8f, 0x29, 0x0b};

} // namespace

const FbxRecord* FbxRecord::find(const std::string& child) const
{
    for (const auto& c : children)
        if (c.name == child)
            return &c;
    return nullptr;
}

std::vector<const FbxRecord*> FbxRecord::all(const std::string& child) const
{
    std::vector<const FbxRecord*> out;
    for (const auto& c : children)
        if (c.name == child)
            out.push_back(&c);
    return out;
}

const FbxRecord* FbxFile::find(const std::string& name) const
{
    for (const auto& r : records)
        if (r.name == name)
            return &r;
    return nullptr;
}

FbxFile readFbx(const std::string& bytes)
{
    FbxFile file;
    if (bytes.size() < 27 || bytes.compare(0, 23, std::string("Kaydara FBX Binary  \0\x1a\0", 23)) != 0) {
        file.error = "not a binary FBX header";
        return file;
    }
    std::memcpy(&file.version, bytes.data() + 23, 4);
    const Parser parser(bytes, file.version >= 7500);
    try {
        std::size_t p = 27;
        while (!parser.isNull(p))
            p = parser.record(p, file.records.emplace_back());
        p += parser.nullSize();
        // Footer: 16-byte id, 4 zeros, padding to 16, version, 120 zeros, magic; nothing after.
        const std::size_t versionAt = ((p + 20 + 15) / 16) * 16 + ((p + 20) % 16 == 0 ? 16 : 0);
        if (versionAt + 4 + 120 + 16 != bytes.size())
            throw std::runtime_error("footer size or alignment");
        if (parser.read<std::uint32_t>(versionAt) != file.version)
            throw std::runtime_error("footer version");
        if (std::memcmp(bytes.data() + bytes.size() - 16, kFooterMagic, 16) != 0)
            throw std::runtime_error("footer magic");
    } catch (const std::exception& e) {
        file.error = e.what();
    }
    return file;
}

std::string fbxObjectName(const FbxRecord& object)
{
    const std::string& full = object.properties.at(1).text;
    return full.substr(0, full.find(std::string("\0\x01", 2)));
}

FbxObjects::FbxObjects(const FbxFile& file)
{
    for (const auto& o : file.find("Objects")->children)
        byId[o.properties.at(0).integer] = &o;
    for (const auto* c : file.find("Connections")->all("C"))
        parents.emplace(c->properties[1].integer,
                        std::pair{c->properties[2].integer, c->properties.size() > 3 ? c->properties[3].text : ""});
}

std::vector<const FbxRecord*> FbxObjects::ofKind(const std::string& kind, const std::string& type) const
{
    std::vector<const FbxRecord*> out;
    for (const auto& [id, o] : byId)
        if (o->name == kind && o->properties.at(2).text == type)
            out.push_back(o);
    return out;
}

std::string readFileBytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

} // namespace rs::test
