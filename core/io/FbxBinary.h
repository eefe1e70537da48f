#pragma once
// The binary FBX container (7.4 / 7.5): a tree of named records, each with a
// list of typed properties, serialised as Autodesk's reader and the public
// readers (Blender, Assimp) expect it. This file knows nothing of scenes;
// io/FbxExport.cpp builds the tree.
//
// Layout written (little-endian):
//   header   "Kaydara FBX Binary  \0", 0x1A 0x00, uint32 version (27 bytes)
//   records  EndOffset, NumProperties, PropertyListLen (uint32 before 7500,
//            uint64 from 7500), uint8 name length, name, properties, nested
//            records; EndOffset is the absolute offset just past the record.
//            A record with children or without properties ends with a null
//            record (13 zero bytes before 7500, 25 from 7500); so does the
//            top-level list.
//   property one type code, then: Y int16, C uint8 bool, I int32, F float32,
//            D float64, L int64; S string / R raw bytes: uint32 length + bytes;
//            arrays f d l i b: uint32 count, uint32 encoding (0: raw, which
//            is all we write), uint32 byte length, then the elements.
//   footer   a 16-byte id, 4 zero bytes, zero padding to a 16-byte boundary
//            (16 bytes when already aligned), uint32 version, 120 zero bytes,
//            the 16-byte closing magic.
// Object names use FBX's binary separator: "name\x00\x01Class".
#include "base/Result.h"
#include <cstdint>
#include <deque>
#include <span>
#include <string>
#include <string_view>

namespace rs::io::fbx {

constexpr std::uint32_t kVersion74 = 7400;
constexpr std::uint32_t kVersion75 = 7500;

// One record. Properties are encoded as they are added (in order), so adding a
// large array copies it once. Children live in a deque: a reference returned by
// child() stays valid while siblings are added.
class Node {
public:
    explicit Node(std::string name) : m_name(std::move(name)) {}

    const std::string& name() const { return m_name; }
    std::uint32_t propertyCount() const { return m_count; }
    const std::string& encodedProperties() const { return m_properties; }
    const std::deque<Node>& children() const { return m_children; }

    Node& child(std::string name) { return m_children.emplace_back(std::move(name)); }
    Node& append(Node node) { return m_children.emplace_back(std::move(node)); }

    Node& addInt16(std::int16_t v);
    Node& addBool(bool v);
    Node& addInt32(std::int32_t v);
    Node& addFloat(float v);
    Node& addDouble(double v);
    Node& addInt64(std::int64_t v);
    Node& addString(std::string_view v);
    Node& addRaw(std::string_view bytes);
    Node& addFloats(std::span<const float> v);
    Node& addDoubles(std::span<const double> v);
    Node& addInt64s(std::span<const std::int64_t> v);
    Node& addInt32s(std::span<const std::int32_t> v);
    Node& addBools(std::span<const std::uint8_t> v); // 0 or 1 each

private:
    void scalar(char type, const void* data, std::size_t size);
    void array(char type, const void* data, std::size_t count, std::size_t elementSize);

    std::string m_name;
    std::uint32_t m_count = 0;
    std::string m_properties;
    std::deque<Node> m_children;
};

// "name\x00\x01Class", the binary form of an object's "Class::name".
std::string objectName(std::string_view name, std::string_view className);

// The whole file: header, the top-level records, the closing null record and
// the footer. Record names must be shorter than 256 bytes and, before 7500,
// the file smaller than 4 GiB; a refusal says which broke.
Result<std::string> serialise(const std::deque<Node>& topLevel, std::uint32_t version);

} // namespace rs::io::fbx
