// rigsmith-cli skin info: what a skin chunk file (issue 20) holds. Export,
// import and transfer are SkinExportCommand.cpp, SkinImportCommand.cpp and
// SkinTransferCommand.cpp.
#include "cli/Commands.h"
#include "cli/SkinCharacter.h"

#include "io/SkinChunks.h"

#include <algorithm>
#include <iostream>
#include <sstream>

namespace rs::cli {

namespace {

std::string point(const glm::vec3& p)
{
    std::ostringstream out;
    out.precision(5);
    out << '(' << p.x << ' ' << p.y << ' ' << p.z << ')';
    return out.str();
}

std::string translation(const Mat4& m) { return point(glm::vec3(m[3])); }

std::string keyText(const NodeKey& key)
{
    std::ostringstream out; // (not string +: GCC 12 warns falsely on it, -Wrestrict)
    out << '#' << key.instance << (key.branch.empty() ? "" : ".") << key.branch << "::" << key.tag;
    return out.str();
}

void printChunk(const skin::SkinChunk& c, std::size_t index, std::size_t from, std::size_t limit)
{
    std::cout << "chunk " << index << ": " << c.mesh << "\n  model: " << c.model << "\n  exported: " << skin::formatExportTime(c.exportedAtMicroseconds)
              << " by " << (c.user.empty() ? "(unknown)" : c.user) << " with " << c.tool << "\n  mesh: " << c.totalVertexCount
              << " vertices, topology fingerprint " << std::hex << c.fingerprint << std::dec << "\n  exported vertices: " << c.vertexCount()
              << (c.vertexCount() == c.totalVertexCount ? " (all)" : " (a subset)") << ", " << c.triangles.size() / 3 << " triangles among them, "
              << c.neighbours.size() << " neighbours sampled\n  skinning: "
              << (c.method == skin::SkinningMethod::DualQuaternion ? "dual quaternion" : "linear blend") << "; "
              << (c.inBindPose ? "exported in bind pose" : "exported posed (bind positions and normals kept too)") << '\n';
    const std::size_t joints = c.joints.size(), vertices = c.vertexCount();
    std::cout << "  influences: " << joints;
    if (from < joints && limit > 0)
        std::cout << " (" << from << " to " << std::min(joints, from + limit) - 1 << ")";
    std::cout << '\n';
    for (std::size_t j = from; j < joints && j < from + limit; ++j) {
        const std::int32_t parent = c.weights.parents[j];
        std::cout << "    " << j << ' ' << c.joints[j].name << ' ' << keyText(c.joints[j].key) << " parent "
                  << (parent < 0 ? std::string("-") : c.joints[std::size_t(parent)].name) << " bind at " << translation(c.joints[j].bind)
                  << " now at " << translation(c.joints[j].world) << '\n';
    }
    std::cout << "  vertices: " << vertices;
    if (from < vertices && limit > 0)
        std::cout << " (" << from << " to " << std::min(vertices, from + limit) - 1 << ")";
    std::cout << '\n';
    for (std::size_t i = from; i < vertices && i < from + limit; ++i) {
        std::cout << "    " << i << " id " << c.vertexIds[i] << " at " << point(c.positions[i]);
        if (!c.inBindPose)
            std::cout << " bind " << point(c.bindPositions[i]);
        std::cout << " normal " << point(c.normals[i]) << " weights";
        for (const model::Influence* w = c.weights.begin(i); w != c.weights.end(i); ++w)
            std::cout << ' ' << c.joints[w->joint].name << ' ' << w->weight;
        if (c.neighbourOffsets.size() == vertices + 1 && c.neighbourOffsets[i] < c.neighbourOffsets[i + 1]) {
            std::cout << " neighbours";
            for (std::uint32_t k = c.neighbourOffsets[i]; k < c.neighbourOffsets[i + 1]; ++k)
                std::cout << ' ' << c.neighbours[k];
        }
        std::cout << '\n';
    }
}

} // namespace

int runSkinInfo(const std::vector<std::string>& args)
{
    std::string file, mesh;
    int limit = 10, from = 0;
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& a = args[i];
        const bool hasValue = i + 1 < args.size();
        if (a == "--limit" && hasValue) {
            if (!parseCount(args[++i], 0, 1 << 30, limit))
                return usageError("skin info", "--limit is a whole number of rows, not '" + args[i] + "'");
        } else if (a == "--from" && hasValue) {
            if (!parseCount(args[++i], 0, 1 << 30, from))
                return usageError("skin info", "--from is the first index to print, not '" + args[i] + "'");
        } else if (a == "--mesh" && hasValue) {
            mesh = args[++i];
        } else if (file.empty() && !a.empty() && a[0] != '-') {
            file = a;
        } else {
            return usageError("skin info", "unexpected argument '" + a + "'");
        }
    }
    if (file.empty())
        return usageError("skin info", "expected FILE");
    auto chunks = io::loadSkinChunkFile(file);
    print(chunks.diagnostics());
    if (!chunks)
        return 1;
    std::cout << file << ": " << chunks->size() << (chunks->size() == 1 ? " chunk\n" : " chunks\n");
    bool shown = false;
    for (std::size_t k = 0; k < chunks->size(); ++k)
        if (mesh.empty() || (*chunks)[k].mesh == mesh) {
            printChunk((*chunks)[k], k, std::size_t(from), std::size_t(limit));
            shown = true;
        }
    if (!shown && !mesh.empty()) {
        std::cerr << file << ": error: no chunk of a mesh named '" << mesh << "'\n";
        return 1;
    }
    return 0;
}

} // namespace rs::cli
