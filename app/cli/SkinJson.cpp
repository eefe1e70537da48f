#include "cli/SkinJson.h"

#include "cli/Commands.h"
#include "io/AtomicFile.h"

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace rs::cli {

double jsonNumber(float value)
{
    // nlohmann prints the double nearest the float in full; the float's own
    // shortest decimal, read back as a double, prints as people wrote it.
    char text[32];
    const auto end = std::to_chars(text, text + sizeof(text) - 1, value).ptr;
    *end = '\0';
    return std::strtod(text, nullptr);
}

Json jsonPoint(const glm::vec3& p)
{
    return Json::array({jsonNumber(p.x), jsonNumber(p.y), jsonNumber(p.z)});
}

std::string jsonText(const Json& report, bool compact)
{
    return report.dump(compact ? -1 : 1, ' ', false, Json::error_handler_t::replace) + "\n";
}

int writeJsonReport(const std::string& path, const Json& report, bool compact)
{
    if (path.empty())
        return 0;
    if (path == "-") {
        // C's stdout: std::cout may be set aside for stderr (HumanLinesAside).
        std::cout.flush();
        std::fputs(jsonText(report, compact).c_str(), stdout);
        std::fflush(stdout);
        return 0;
    }
    const Status written = io::writeFileAtomically(path, jsonText(report, compact));
    print(written.diagnostics());
    return written.failed() ? 1 : 0;
}

HumanLinesAside::HumanLinesAside(const std::string& jsonPath)
{
    if (jsonPath == "-")
        m_stdout = std::cout.rdbuf(std::cerr.rdbuf());
}

HumanLinesAside::~HumanLinesAside()
{
    if (m_stdout)
        std::cout.rdbuf(m_stdout);
}

namespace {

std::string keyText(const NodeKey& key)
{
    std::ostringstream out; // as `skin info` prints it
    out << '#' << key.instance << (key.branch.empty() ? "" : ".") << key.branch << "::" << key.tag;
    return out.str();
}

std::string hex(std::uint64_t value)
{
    std::ostringstream out;
    out << std::hex << value;
    return out.str();
}

} // namespace

Json chunkHeaderJson(const skin::SkinChunk& c)
{
    return Json{{"mesh", c.mesh},
                {"model", c.model},
                {"tool", c.tool},
                {"user", c.user},
                {"exported", skin::formatExportTime(c.exportedAtMicroseconds)},
                {"exportedMicroseconds", c.exportedAtMicroseconds},
                {"totalVertices", c.totalVertexCount},
                {"fingerprint", hex(c.fingerprint)},
                {"vertices", c.vertexCount()},
                {"all", c.vertexCount() == c.totalVertexCount},
                {"triangles", c.triangles.size() / 3},
                {"neighbours", c.neighbours.size()},
                {"influences", c.joints.size()},
                {"skinning", c.method == skin::SkinningMethod::DualQuaternion ? "dual-quaternion" : "linear"},
                {"bindPose", c.inBindPose}};
}

Json chunkJson(const skin::SkinChunk& c, std::size_t from, std::size_t limit)
{
    Json out = chunkHeaderJson(c);
    out["from"] = from;
    Json influences = Json::array();
    for (std::size_t j = from; j < c.joints.size() && j - from < limit; ++j) {
        const std::int32_t parent = j < c.weights.parents.size() ? c.weights.parents[j] : -1;
        influences.push_back(Json{{"index", j},
                                  {"name", c.joints[j].name},
                                  {"key", keyText(c.joints[j].key)},
                                  {"parent", parent < 0 ? Json(nullptr) : Json(c.joints[std::size_t(parent)].name)},
                                  {"bindAt", jsonPoint(glm::vec3(c.joints[j].bind[3]))},
                                  {"at", jsonPoint(glm::vec3(c.joints[j].world[3]))}});
    }
    out["influenceRows"] = std::move(influences);
    Json vertices = Json::array();
    const bool sampled = c.neighbourOffsets.size() == c.vertexCount() + 1;
    for (std::size_t i = from; i < c.vertexCount() && i - from < limit; ++i) {
        Json row{{"index", i}, {"id", c.vertexIds[i]}, {"at", jsonPoint(c.positions[i])}};
        if (!c.inBindPose)
            row["bindAt"] = jsonPoint(c.bindPositions[i]);
        row["normal"] = jsonPoint(c.normals[i]);
        Json weights = Json::array();
        for (const model::Influence* w = c.weights.begin(i); w != c.weights.end(i); ++w)
            weights.push_back(Json::array({c.joints[w->joint].name, jsonNumber(w->weight)}));
        row["weights"] = std::move(weights);
        Json neighbours = Json::array();
        for (std::uint32_t k = sampled ? c.neighbourOffsets[i] : 0; sampled && k < c.neighbourOffsets[i + 1]; ++k)
            neighbours.push_back(c.neighbours[k]);
        row["neighbours"] = std::move(neighbours);
        vertices.push_back(std::move(row));
    }
    out["vertexRows"] = std::move(vertices);
    return out;
}

Json importReportJson(const skin::MeshImportReport& r, skin::TransferMethod method)
{
    return Json{{"vertices", r.vertices},
                {"route", skin::importRouteName(r.route)},
                {"source", r.source},
                {"why", r.why},
                {"method", skin::transferMethodName(method)},
                {"oneToOne", r.oneToOne},
                {"singleInfluence", r.singleInfluence},
                {"closestPoint", r.closestPoint},
                {"closestNeighbours", r.closestNeighbours},
                {"normalFilterFallbacks", r.normalFilterFallbacks},
                {"inpainted", r.inpainted},
                {"smoothed", r.smoothed},
                {"milliseconds", r.milliseconds}};
}

} // namespace rs::cli
