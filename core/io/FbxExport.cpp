#include "io/FbxExport.h"

#include "io/AtomicFile.h"
#include "io/FbxDocument.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace rs::io {

namespace {

using fbx::Node;

// The header's fixed stamp: readers only display it.
constexpr char kFixedCreationTime[] = "1970-01-01 10:00:00:000";
constexpr unsigned char kFixedFileId[16] = {0x28, 0xb3, 0x2a, 0xeb, 0xb6, 0x24, 0xcc, 0xc2,
                                            0xbf, 0xc8, 0xb0, 0x2a, 0xa9, 0x2b, 0xfc, 0xf1};

struct Stamp {
    std::tm time{};
    std::string text; // "YYYY-MM-DD HH:MM:SS:mmm"
    std::string fileId;
};

Stamp stampOf(const FbxWriteOptions& options)
{
    Stamp s;
    s.fileId.assign(reinterpret_cast<const char*>(kFixedFileId), 16);
    if (!options.creationTime) {
        s.time.tm_year = 70;
        s.time.tm_mday = 1;
        s.time.tm_hour = 10;
        s.text = kFixedCreationTime;
        return s;
    }
    gmtime_r(&*options.creationTime, &s.time);
    char text[64];
    std::snprintf(text, sizeof text, "%04d-%02d-%02d %02d:%02d:%02d:000", s.time.tm_year + 1900, s.time.tm_mon + 1,
                  s.time.tm_mday, s.time.tm_hour, s.time.tm_min, s.time.tm_sec);
    s.text = text;
    for (std::size_t i = 0; i < 8; ++i) // a file id that differs with the time
        s.fileId[i] = char(s.fileId[i] ^ char(std::uint64_t(*options.creationTime) >> (8 * i)));
    return s;
}

void addHeader(std::deque<Node>& top, const FbxWriteOptions& options, const Stamp& stamp)
{
    Node& header = top.emplace_back("FBXHeaderExtension");
    header.child("FBXHeaderVersion").addInt32(1003);
    header.child("FBXVersion").addInt32(std::int32_t(options.version));
    header.child("EncryptionType").addInt32(0);
    Node& time = header.child("CreationTimeStamp");
    time.child("Version").addInt32(1000);
    time.child("Year").addInt32(stamp.time.tm_year + 1900);
    time.child("Month").addInt32(stamp.time.tm_mon + 1);
    time.child("Day").addInt32(stamp.time.tm_mday);
    time.child("Hour").addInt32(stamp.time.tm_hour);
    time.child("Minute").addInt32(stamp.time.tm_min);
    time.child("Second").addInt32(stamp.time.tm_sec);
    time.child("Millisecond").addInt32(0);
    header.child("Creator").addString(options.generator);
    top.emplace_back("FileId").addRaw(stamp.fileId);
    top.emplace_back("CreationTime").addString(stamp.text);
    top.emplace_back("Creator").addString(options.generator);
}

void addGlobalSettings(std::deque<Node>& top, const Convention& convention, std::int64_t timeSpanStop)
{
    Node& settings = top.emplace_back("GlobalSettings");
    settings.child("Version").addInt32(1000);
    Node& p70 = settings.child("Properties70");
    // Y-up: up Y, front +Z, coord +X. Z-up: up Z, front -Y, coord +X (both right-handed).
    const int up = convention.zUp ? 2 : 1, front = convention.zUp ? 1 : 2, frontSign = convention.zUp ? -1 : 1;
    fbx::propertyInt(p70, "UpAxis", "int", up);
    fbx::propertyInt(p70, "UpAxisSign", "int", 1);
    fbx::propertyInt(p70, "FrontAxis", "int", front);
    fbx::propertyInt(p70, "FrontAxisSign", "int", frontSign);
    fbx::propertyInt(p70, "CoordAxis", "int", 0);
    fbx::propertyInt(p70, "CoordAxisSign", "int", 1);
    fbx::propertyInt(p70, "OriginalUpAxis", "int", up);
    fbx::propertyInt(p70, "OriginalUpAxisSign", "int", 1);
    const double unitScale = fbxUnitScaleFactor(convention.unitsPerMetre);
    fbx::propertyDouble(p70, "UnitScaleFactor", unitScale);
    fbx::propertyDouble(p70, "OriginalUnitScaleFactor", unitScale);
    fbx::propertyInt(p70, "TimeMode", "enum", 6); // 30 frames per second
    fbx::propertyDouble(p70, "CustomFrameRate", 30.0);
    fbx::propertyTime(p70, "TimeSpanStart", 0);
    fbx::propertyTime(p70, "TimeSpanStop", timeSpanStop);
}

void addDocuments(std::deque<Node>& top, const ExportScene& scene, std::int64_t id)
{
    Node& documents = top.emplace_back("Documents");
    documents.child("Count").addInt32(1);
    Node& document = documents.child("Document");
    document.addInt64(id).addString("Scene").addString("Scene");
    Node& p70 = document.child("Properties70");
    p70.child("P").addString("SourceObject").addString("object").addString("").addString("");
    fbx::propertyString(p70, "ActiveAnimStackName", scene.clips.empty() ? "" : scene.clips.front().name);
    document.child("RootNode").addInt64(0);
    top.emplace_back("References");
}

void addDefinitions(std::deque<Node>& top, const std::map<std::string, int>& counts)
{
    Node& definitions = top.emplace_back("Definitions");
    definitions.child("Version").addInt32(100);
    int total = 1; // GlobalSettings
    for (const auto& [kind, count] : counts)
        total += count;
    definitions.child("Count").addInt32(total);
    definitions.child("ObjectType").addString("GlobalSettings").child("Count").addInt32(1);
    for (const auto& [kind, count] : counts)
        definitions.child("ObjectType").addString(kind).child("Count").addInt32(count);
}

} // namespace

Result<std::string> fbxBytes(const ExportScene& scene, const Convention& convention, const FbxWriteOptions& options)
{
    if (options.version != fbx::kVersion74 && options.version != fbx::kVersion75)
        return Result<std::string>::refused("FBX version " + std::to_string(options.version) + " is not written: use 7400 or 7500");
    fbx::Document doc;
    const std::int64_t documentId = doc.newId();
    const fbx::ModelIds ids = fbx::addSceneObjects(doc, scene, options.embedTextures);
    Node takes("Takes");
    fbx::addClips(doc, scene, ids, takes);
    double lastTime = 0.0;
    for (const auto& clip : scene.clips)
        lastTime = std::max(lastTime, clip.times.empty() ? 0.0 : clip.times.back());

    std::deque<Node> top;
    addHeader(top, options, stampOf(options));
    addGlobalSettings(top, convention, std::llround(lastTime * double(fbx::kTicksPerSecond)));
    addDocuments(top, scene, documentId);
    addDefinitions(top, doc.counts);
    top.push_back(std::move(doc.objects));
    top.push_back(std::move(doc.connections));
    top.push_back(std::move(takes));
    return fbx::serialise(top, options.version);
}

Diagnostics writeFbx(const ExportScene& scene, const std::string& path, const Convention& convention,
                     const FbxWriteOptions& options)
{
    auto bytes = fbxBytes(scene, convention, options);
    if (!bytes) {
        Diagnostics report = bytes.takeDiagnostics();
        for (auto& d : report)
            d.where.file = path;
        return report;
    }
    if (!options.embedTextures) {
        // The images first, so a written FBX never names a missing file.
        const std::filesystem::path folder = std::filesystem::path(path).parent_path();
        const std::vector<std::string> files = fbx::imageFileNames(scene);
        for (std::size_t m = 0; m < files.size(); ++m) {
            if (files[m].empty())
                continue;
            const std::filesystem::path name(files[m]);
            if (name.filename() != name || name == "." || name == "..")
                return {makeError({path, 0, 0}, "texture '" + files[m] + "' of material '" + scene.materials[m].name +
                                                     "' is not a plain file name: it cannot be written beside the FBX")};
            Diagnostics written = writeFileAtomically((folder / name).string(), scene.materials[m].image).takeDiagnostics();
            if (hasErrors(written))
                return written;
        }
    }
    return writeFileAtomically(path, *bytes).takeDiagnostics();
}

} // namespace rs::io
