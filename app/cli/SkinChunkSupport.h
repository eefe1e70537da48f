#pragma once
// What the skin chunk commands (export, import, transfer) share: vertex
// selections, the weight depot's layout, progress on stderr,
// reading and merging chunk files, who exports when.
#include "base/Result.h"
#include "skin/SkinChunk.h"

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace rs::cli {

std::string userName();
std::int64_t nowMicroseconds();

// `--vertices MESH:0-99,120`: a mesh's vertex ids as inclusive ranges (the
// mesh name is everything before the last ':').
struct VertexSelection {
    std::string mesh;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ranges;
};
bool parseVertexSelection(const std::string& text, VertexSelection& out);
// Ascending, unique ids; fails naming the mesh when one is not below `vertexCount`.
Result<std::vector<std::uint32_t>> selectedVertices(const VertexSelection& selection, std::size_t vertexCount);

// The weight depot: one chunk file per mesh, DIR/<asset>/<mesh>.rschunks.
// Names become safe file names (letters, digits, '.', '_', '-'; anything else
// '_'; no leading '.'); clashing meshes (same safe name, any case) get "~2",
// "~3"... in the order given.
std::string safeFileName(const std::string& name);
std::vector<std::string> depotPaths(const std::string& dir, const std::string& asset, const std::vector<std::string>& meshes);
// Every .rschunks file in DIR/<asset>/, sorted; an error when there is none.
Result<std::vector<std::string>> depotFiles(const std::string& dir, const std::string& asset);
// The asset a guide's depot folder is named by: the guide file's stem.
std::string assetOf(const std::string& guidePath);

// Percent on stderr, at most every 0.2 s: a terminal gets one updating line
// once the work has taken a second; with `forced` (--progress) a line per 10%
// from the start. Null when stderr is no terminal and not forced.
std::function<bool(double)> progressPrinter(const std::string& what, bool forced);

// Every file's chunks in the order given, merged (the newest of a name wins);
// problems printed. Nothing on an error.
std::optional<std::vector<skin::SkinChunk>> readChunkFiles(const std::vector<std::string>& files);

} // namespace rs::cli
