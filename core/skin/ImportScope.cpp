#include "skin/ImportScope.h"

#include <algorithm>

namespace rs::skin {

std::vector<bool> writtenVertices(const std::vector<SkinChunk>& chunks, const MeshImportReport& report, std::size_t vertexCount,
                                  const ImportScope& scope)
{
    std::vector<bool> write(vertexCount, scope.selection == nullptr);
    if (scope.selection)
        for (const std::uint32_t v : *scope.selection)
            if (v < vertexCount)
                write[v] = true;
    if (!scope.append || report.route != ImportRoute::OneToOne)
        return write;
    auto chunk = std::find_if(chunks.begin(), chunks.end(), [&](const SkinChunk& c) { return c.mesh == report.source; });
    if (chunk == chunks.end())
        return write;
    std::vector<bool> covered(vertexCount, false);
    for (const std::uint32_t v : chunk->vertexIds)
        if (v < vertexCount)
            covered[v] = true;
    for (std::size_t v = 0; v < vertexCount; ++v)
        write[v] = write[v] && covered[v];
    return write;
}

std::optional<model::MeshWeights> keepUnwritten(const model::MeshWeights& existing, const model::MeshWeights& imported,
                                                const std::vector<bool>& write)
{
    if (existing.joints != imported.joints || existing.parents != imported.parents || existing.vertexCount() != imported.vertexCount() ||
        write.size() != imported.vertexCount())
        return std::nullopt;
    if (std::all_of(write.begin(), write.end(), [](bool w) { return w; }))
        return imported;
    model::MeshWeights out;
    out.joints = imported.joints;
    out.parents = imported.parents;
    out.offsets.push_back(0);
    for (std::size_t v = 0; v < write.size(); ++v) {
        const model::MeshWeights& from = write[v] ? imported : existing;
        out.influences.insert(out.influences.end(), from.begin(v), from.end(v));
        out.offsets.push_back(std::uint32_t(out.influences.size()));
    }
    return out;
}

} // namespace rs::skin
