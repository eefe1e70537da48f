// rigsmith-cli skin info: what a skin chunk file (issue 20) holds. Export,
// import and transfer are SkinExportCommand.cpp, SkinImportCommand.cpp and
// SkinTransferCommand.cpp.
#include "cli/Commands.h"
#include "cli/SkinCharacter.h"
#include "cli/SkinJson.h"

#include "io/SkinChunkInfo.h"
#include "io/SkinChunks.h"

#include <iostream>

namespace rs::cli {

int runSkinInfo(const std::vector<std::string>& args)
{
    std::string file, mesh, json;
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
        } else if (a == "--json" && hasValue) {
            json = args[++i];
            if (json.empty())
                return usageError("skin info", "--json is a file name (or - for stdout), not ''");
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
    // --json - prints the report alone on stdout (the text would only repeat it); a file beside the text.
    const bool text = json != "-";
    if (text)
        std::cout << file << ": " << chunks->size() << (chunks->size() == 1 ? " chunk\n" : " chunks\n");
    Json shown = Json::array();
    for (std::size_t k = 0; k < chunks->size(); ++k)
        if (mesh.empty() || (*chunks)[k].mesh == mesh) {
            if (text)
                std::cout << io::describeSkinChunk((*chunks)[k], k, std::size_t(from), std::size_t(limit));
            Json chunk{{"chunk", k}};
            chunk.update(chunkJson((*chunks)[k], std::size_t(from), std::size_t(limit)));
            shown.push_back(std::move(chunk));
        }
    if (shown.empty() && !mesh.empty()) {
        std::cerr << file << ": error: no chunk of a mesh named '" << mesh << "'\n";
        return 1;
    }
    return writeJsonReport(json, Json{{"file", file}, {"chunkCount", chunks->size()}, {"from", from}, {"limit", limit}, {"chunks", std::move(shown)}});
}

} // namespace rs::cli
