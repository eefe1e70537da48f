#pragma once
// Skin chunk files (`.rschunks`, issue 20): one file holds the skin chunks
// (skin/SkinChunk.h) of any number of meshes, for a later import onto the same
// meshes or changed ones (skin/Transfer.h). Binary, little-endian, versioned
// and checksummed; written atomically. Never a language's pickle: every field
// is listed here, so a script in any language can read it.
//
//   "RSCHUNKS"  8 bytes
//   u32 version (1), u32 chunk count
//   per chunk:
//     str mesh, str model, str tool, str user
//     i64 exported at (microseconds since 1970-01-01 UTC)
//     u32 total vertex count (the mesh's), u64 topology fingerprint (model::topologyFingerprint)
//     u8 skinning method (0 linear, 1 dual quaternion), u8 in bind pose (0/1), u16 reserved (0)
//     u32 influence count J, per influence:
//       u32 instance, str branch, str tag (the skin joint's NodeKey), str name (its export name),
//       i32 parent (index of its parent influence, -1 for a root),
//       f64[16] world (pose at export), f64[16] local (to the parent), f64[16] bind (world at bind);
//       matrices column-major, metres
//     u32 exported vertex count N, u32 ids[N] (strictly ascending, < total vertex count)
//     f32[3] positions[N], f32[3] normals[N]            (world, in the pose at export)
//     unless in bind pose: f32[3] bind positions[N], f32[3] bind normals[N]   (pre-deformed)
//     u32 weight count W, u32 offsets[N + 1] (vertex i's weights: [offsets[i], offsets[i + 1])),
//       per weight {u32 influence, f32 weight in [0, 1]}
//     u32 triangle count T, u32 corners[3T] (indices into the exported vertices)
//     u32 neighbour count M, u32 offsets[N + 1], u32 neighbours[M] (mesh vertex ids, a sample along edges)
//   u64 FNV-1a checksum of every byte before it
//   (str: u32 byte length, then UTF-8 bytes)
//
// Reading checks the checksum, then every count against the bytes left, every
// offset, index, parent (no cycle), weight and coordinate (finite); a damaged
// or truncated file is an error naming the file and the byte where it breaks.
// Nothing is returned from a file with an error.
#include "base/Result.h"
#include "base/Status.h"
#include "skin/SkinChunk.h"

#include <string>
#include <vector>

namespace rs::io {

std::string writeSkinChunks(const std::vector<skin::SkinChunk>& chunks);
std::uint64_t skinChunksChecksum(const char* data, std::size_t size); // FNV-1a, 64 bits
Result<std::vector<skin::SkinChunk>> readSkinChunks(const std::string& bytes, const std::string& path);

// Regular files only, at most 2 GB.
Status saveSkinChunkFile(const std::string& path, const std::vector<skin::SkinChunk>& chunks);
Result<std::vector<skin::SkinChunk>> loadSkinChunkFile(const std::string& path);

} // namespace rs::io
