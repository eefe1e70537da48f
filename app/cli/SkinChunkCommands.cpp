// rigsmith-cli skin info: what a skin chunk file (issue 20) holds. Export,
// import and transfer are SkinExportCommand.cpp, SkinImportCommand.cpp and
// SkinTransferCommand.cpp.
#include "cli/Commands.h"
#include "cli/SkinCharacter.h"

#include "io/SkinChunkInfo.h"
#include "io/SkinChunks.h"

#include <iostream>

namespace rs::cli {

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
            std::cout << io::describeSkinChunk((*chunks)[k], k, std::size_t(from), std::size_t(limit));
            shown = true;
        }
    if (!shown && !mesh.empty()) {
        std::cerr << file << ": error: no chunk of a mesh named '" << mesh << "'\n";
        return 1;
    }
    return 0;
}

} // namespace rs::cli
