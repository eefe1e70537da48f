#pragma once
// The skin commands' machine-readable reports (--json), built with
// nlohmann-json (ordered: members read in the order a report adds them) and
// written to a file atomically, or to stdout for "-". Chunk headers and rows
// are shared by `skin export --json` and `skin info --json`.
#include "skin/SkinChunk.h"
#include "skin/Transfer.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <iosfwd>
#include <string>

namespace rs::cli {

using Json = nlohmann::ordered_json;

// A float as the shortest decimal that reads back as it (0.1f is 0.1, not 0.10000000149011612).
double jsonNumber(float value);
Json jsonPoint(const glm::vec3& p);

// The text of a report: indented one space per level, or on one line when
// `compact` (bulk data); text that is not UTF-8 is replaced, never thrown on.
std::string jsonText(const Json& report, bool compact = false);
// --json PATH: "" writes nothing, "-" prints on stdout, else the file,
// atomically. 0, or 1 when it cannot be written (printed).
int writeJsonReport(const std::string& path, const Json& report, bool compact = false);

// With --json - stdout holds the report alone: while one of these lives, the
// lines a command prints for people (std::cout) go to stderr. Nothing for
// any other path.
class HumanLinesAside {
public:
    explicit HumanLinesAside(const std::string& jsonPath);
    ~HumanLinesAside();
    HumanLinesAside(const HumanLinesAside&) = delete;
    HumanLinesAside& operator=(const HumanLinesAside&) = delete;

private:
    std::streambuf* m_stdout = nullptr;
};

// A chunk's header: mesh, model, who exported it when with what, vertex counts, skinning.
Json chunkHeaderJson(const skin::SkinChunk& chunk);
// A chunk's header with its influences and vertices [from, from + limit) (as `skin info` prints them).
Json chunkJson(const skin::SkinChunk& chunk, std::size_t from, std::size_t limit);

// A mesh's import report: route, source, why, method and the per-step counts.
Json importReportJson(const skin::MeshImportReport& report, skin::TransferMethod method);

} // namespace rs::cli
