#pragma once
// A small binary FBX reader for the tests (not the writer's code read back):
// parses the header, every record by its end offset, checks that each nested
// list ends with a null record where the format wants one and that the
// footer is laid out as readers expect. Arrays come back as doubles.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace rs::test {

struct FbxProperty {
    char type = 0;
    std::int64_t integer = 0;        // Y C I L
    double number = 0.0;             // F D
    std::string text;                // S R
    std::vector<double> array;       // f d l i b
};

struct FbxRecord {
    std::string name;
    std::vector<FbxProperty> properties;
    std::vector<FbxRecord> children;

    const FbxRecord* find(const std::string& child) const;
    std::vector<const FbxRecord*> all(const std::string& child) const;
};

struct FbxFile {
    std::uint32_t version = 0;
    std::vector<FbxRecord> records;
    std::string error; // empty when the file parsed and every check held

    const FbxRecord* find(const std::string& name) const;
};

FbxFile readFbx(const std::string& bytes);

// "name\x00\x01Class" -> "name".
std::string fbxObjectName(const FbxRecord& object);

// A file's Objects by id, and its Connections child -> (parent, property).
struct FbxObjects {
    std::map<std::int64_t, const FbxRecord*> byId;
    std::multimap<std::int64_t, std::pair<std::int64_t, std::string>> parents;

    explicit FbxObjects(const FbxFile& file);
    // Objects of a record kind ("Model") and type ("LimbNode").
    std::vector<const FbxRecord*> ofKind(const std::string& kind, const std::string& type) const;
};

std::string readFileBytes(const std::string& path);

} // namespace rs::test
