#pragma once
// What a skin chunk holds, as text people read (the editor's chunk file
// inspector; the same fields as `rigsmith-cli skin info`): the mesh, its model,
// who exported it when with what, the vertex counts, the skinning, then rows
// of influences and of vertices from index `from`, at most `limit` of each.
#include "skin/SkinChunk.h"

#include <cstddef>
#include <string>
#include <vector>

namespace rs::io {

// One chunk (`index`: its place in the file), rows [from, from + limit).
std::string describeSkinChunk(const skin::SkinChunk& chunk, std::size_t index, std::size_t from, std::size_t limit);
// Every chunk of a file, headed by its name and chunk count.
std::string describeSkinChunks(const std::string& file, const std::vector<skin::SkinChunk>& chunks, std::size_t from, std::size_t limit);

} // namespace rs::io
