#include "cli/SkinImportOptions.h"

#include "cli/Commands.h"
#include "io/WeightsFile.h"

#include <iostream>

namespace rs::cli {

int parseTransferOption(const std::vector<std::string>& args, std::size_t& i, skin::TransferOptions& o, bool& known,
                        const std::string& command)
{
    const std::string& a = args[i];
    known = i + 1 < args.size();
    if (!known)
        return 0;
    const std::string& value = args[i + 1];
    auto bad = [&](const std::string& what) { return usageError(command, a + " is " + what + ", not '" + value + "'"); };
    if (a == "--method") {
        const auto method = skin::parseTransferMethod(value);
        if (!method)
            return bad("closest, neighbours or inpaint");
        o.method = *method;
    } else if (a == "--normal-filter") {
        if (!parseNumber(value, -1.0, 1.0, o.normalTolerance))
            return bad("a dot product tolerance from -1 to 1 (0.75: within about 41 degrees)");
        o.normalFilter = true;
    } else if (a == "--neighbours") {
        if (!parseCount(value, 1, 32, o.neighbourCount))
            return bad("a whole number from 1 to 32");
    } else if (a == "--distance-multiplier") {
        if (!parseNumber(value, 1.0, 1000.0, o.neighbourDistanceMultiplier))
            return bad("a number from 1 to 1000");
    } else if (a == "--inpaint-distance") {
        if (!parseNumber(value, 0.0, 1000.0, o.inpaintDistance))
            return bad("metres, at least 0 (0: 5% of the mesh's size)");
    } else if (a == "--inpaint-angle") {
        if (!parseNumber(value, 0.0, 180.0, o.inpaintAngleDegrees))
            return bad("degrees from 0 to 180");
    } else if (a == "--smooth") {
        if (!parseCount(value, 0, 100, o.smoothSteps))
            return bad("a whole number of steps from 0 to 100");
    } else if (a == "--smooth-threshold") {
        if (!parseNumber(value, 0.0, 1.0, o.weightDifferenceThreshold))
            return bad("a weight difference from 0 to 1");
    } else if (a == "--max-influences") {
        if (!parseCount(value, 1, 16, o.maxInfluences))
            return bad("a whole number from 1 to 16");
    } else {
        known = false;
        return 0;
    }
    ++i;
    return 0;
}

bool parseTransferFlag(const std::string& arg, skin::TransferOptions& o)
{
    if (arg == "--no-search")
        o.searchByCountAndOrder = false;
    else if (arg == "--uber")
        o.forceUberChunk = true;
    else if (arg == "--export-pose")
        o.usePreDeformed = false;
    else
        return false;
    return true;
}

std::vector<std::string> boneNames(const Character& c)
{
    std::vector<std::string> names;
    for (const skin::SkinBone& bone : c.bones)
        names.push_back(bone.node < c.rig.nodes.size() ? c.rig.nodes[bone.node].name : "");
    return names;
}

void printImportReport(const skin::MeshImportReport& r, const ImportTarget& t)
{
    std::cout << r.mesh << ": " << r.vertices << " vertices, " << skin::importRouteName(r.route) << " from "
              << (r.source == "uber chunk" ? r.source : "chunk '" + r.source + "'") << " (" << r.why << "): " << r.oneToOne << " 1:1, "
              << r.singleInfluence << " single influence, " << r.closestPoint << " closest point (" << r.normalFilterFallbacks
              << " where nothing passed the normal filter), " << r.closestNeighbours << " closest neighbours, " << r.inpainted
              << " inpainted, " << r.smoothed << " smoothed, " << int(r.milliseconds) << " ms";
    if (t.kept > 0)
        std::cout << "; written on " << t.written << " vertices, " << t.kept << " kept their weights";
    std::cout << '\n';
}

namespace {

Json influencesJson(const ImportArguments& m, const skin::InfluenceResolution& r)
{
    using How = skin::InfluenceMatch::How;
    Json moved = Json::array();
    for (const skin::InfluenceMatch& match : r.matches)
        if (match.how == How::Mapped || match.how == How::Created)
            moved.push_back(Json{{"influence", match.name},
                                 {"to", match.target},
                                 {"how", match.how == How::Mapped ? "mapped" : "created"},
                                 {"meshes", match.meshes}});
    return Json{{"missing", skin::missingInfluencesName(m.influences.missing)},
                {"identity", r.count(How::Identity)},
                {"name", r.count(How::Name)},
                {"mapped", r.count(How::Mapped)},
                {"created", r.count(How::Created)},
                {"unused", r.count(How::Unused)},
                {"moved", std::move(moved)}};
}

} // namespace

Json transferOptionsJson(const skin::TransferOptions& o)
{
    return Json{{"method", skin::transferMethodName(o.method)},
                {"search", o.searchByCountAndOrder},
                {"uber", o.forceUberChunk},
                {"preDeformed", o.usePreDeformed},
                {"distanceMultiplier", o.neighbourDistanceMultiplier},
                {"neighbours", o.neighbourCount},
                {"normalFilter", o.normalFilter ? Json(o.normalTolerance) : Json(nullptr)},
                {"smooth", o.smoothSteps},
                {"smoothThreshold", o.weightDifferenceThreshold},
                {"maxInfluences", o.maxInfluences},
                {"inpaintDistance", o.inpaintDistance},
                {"inpaintAngle", o.inpaintAngleDegrees}};
}

int writeImportJson(const ImportArguments& m, const std::vector<skin::SkinChunk>& chunks, const std::vector<ImportTarget>& targets,
                    const std::vector<skin::MeshImportReport>& reports, const skin::InfluenceResolution& influences)
{
    if (m.json.empty())
        return 0;
    Json chunkList = Json::array();
    for (const skin::SkinChunk& chunk : chunks)
        chunkList.push_back(Json{{"mesh", chunk.mesh},
                                 {"vertices", chunk.vertexCount()},
                                 {"exported", skin::formatExportTime(chunk.exportedAtMicroseconds)},
                                 {"user", chunk.user}});
    Json meshes = Json::array();
    for (std::size_t i = 0; i < reports.size(); ++i) {
        Json mesh{{"model", targets[i].mesh.model}, {"mesh", reports[i].mesh}};
        mesh.update(importReportJson(reports[i], m.options.method));
        mesh["written"] = targets[i].written;
        mesh["kept"] = targets[i].kept;
        meshes.push_back(std::move(mesh));
    }
    const Json report{{"guide", m.guide},
                      {"weights", io::weightsPathFor(m.guide)},
                      {"append", m.append},
                      {"options", transferOptionsJson(m.options)},
                      {"influences", influencesJson(m, influences)},
                      {"chunks", std::move(chunkList)},
                      {"meshes", std::move(meshes)}};
    return writeJsonReport(m.json, report);
}

} // namespace rs::cli
