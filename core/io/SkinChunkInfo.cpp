#include "io/SkinChunkInfo.h"

#include <algorithm>
#include <sstream>

namespace rs::io {

namespace {

std::string point(const glm::vec3& p)
{
    std::ostringstream out;
    out.precision(5);
    out << '(' << p.x << ' ' << p.y << ' ' << p.z << ')';
    return out.str();
}

std::string keyText(const NodeKey& key)
{
    std::ostringstream out;
    out << '#' << key.instance << (key.branch.empty() ? "" : ".") << key.branch << "::" << key.tag;
    return out.str();
}

// "  influences: 87 (0 to 9)"
void rangeLine(std::ostream& out, const char* what, std::size_t count, std::size_t from, std::size_t limit)
{
    out << "  " << what << ": " << count;
    if (from < count && limit > 0)
        out << " (" << from << " to " << std::min(count, from + limit) - 1 << ")";
    out << '\n';
}

void header(std::ostream& out, const skin::SkinChunk& c, std::size_t index)
{
    out << "chunk " << index << ": " << c.mesh << "\n  model: " << c.model << "\n  exported: " << skin::formatExportTime(c.exportedAtMicroseconds)
        << " by " << (c.user.empty() ? "(unknown)" : c.user) << " with " << c.tool << "\n  mesh: " << c.totalVertexCount
        << " vertices, topology fingerprint " << std::hex << c.fingerprint << std::dec << "\n  exported vertices: " << c.vertexCount()
        << (c.vertexCount() == c.totalVertexCount ? " (all)" : " (a subset)") << ", " << c.triangles.size() / 3 << " triangles among them, "
        << c.neighbours.size() << " neighbours sampled\n  skinning: "
        << (c.method == skin::SkinningMethod::DualQuaternion ? "dual quaternion" : "linear blend") << "; "
        << (c.inBindPose ? "exported in bind pose" : "exported posed (bind positions and normals kept too)") << '\n';
}

void vertexRow(std::ostream& out, const skin::SkinChunk& c, std::size_t i)
{
    out << "    " << i << " id " << c.vertexIds[i] << " at " << point(c.positions[i]);
    if (!c.inBindPose)
        out << " bind " << point(c.bindPositions[i]);
    out << " normal " << point(c.normals[i]) << " weights";
    for (const model::Influence* w = c.weights.begin(i); w != c.weights.end(i); ++w)
        out << ' ' << c.joints[w->joint].name << ' ' << w->weight;
    if (c.neighbourOffsets.size() == c.vertexCount() + 1 && c.neighbourOffsets[i] < c.neighbourOffsets[i + 1]) {
        out << " neighbours";
        for (std::uint32_t k = c.neighbourOffsets[i]; k < c.neighbourOffsets[i + 1]; ++k)
            out << ' ' << c.neighbours[k];
    }
    out << '\n';
}

} // namespace

std::string describeSkinChunk(const skin::SkinChunk& c, std::size_t index, std::size_t from, std::size_t limit)
{
    std::ostringstream out;
    header(out, c, index);
    const std::size_t joints = c.joints.size(), vertices = c.vertexCount();
    rangeLine(out, "influences", joints, from, limit);
    for (std::size_t j = from; j < joints && j < from + limit; ++j) {
        const std::int32_t parent = j < c.weights.parents.size() ? c.weights.parents[j] : -1;
        out << "    " << j << ' ' << c.joints[j].name << ' ' << keyText(c.joints[j].key) << " parent "
            << (parent < 0 ? std::string("-") : c.joints[std::size_t(parent)].name) << " bind at " << point(glm::vec3(c.joints[j].bind[3]))
            << " now at " << point(glm::vec3(c.joints[j].world[3])) << '\n';
    }
    rangeLine(out, "vertices", vertices, from, limit);
    for (std::size_t i = from; i < vertices && i < from + limit; ++i)
        vertexRow(out, c, i);
    return out.str();
}

std::string describeSkinChunks(const std::string& file, const std::vector<skin::SkinChunk>& chunks, std::size_t from, std::size_t limit)
{
    std::string out = file + ": " + std::to_string(chunks.size()) + (chunks.size() == 1 ? " chunk\n" : " chunks\n");
    for (std::size_t k = 0; k < chunks.size(); ++k)
        out += describeSkinChunk(chunks[k], k, from, limit);
    return out;
}

} // namespace rs::io
