#pragma once
// Repairs binary FBX from Debian's Assimp 5.2.5, which never writes the
// "null records" (all-zero record headers: 13 bytes before FBX 7.5, 25 from 7.5)
// that must close every nested record list (assimp#4686, fixed in 5.3.0; see
// ../shared/reference/export-facts.md §5.1). Blender and Assimp refuse such files.
//
// The repair parses the record tree by the records' end offsets (which are
// right), then writes it again with a null record after every record that has
// children or no properties, and after the top-level list, recomputing every
// end offset and the footer's 16-byte alignment. It is idempotent: a correct
// file comes out unchanged in content.
#include "base/Result.h"

#include <string>

namespace rs::io {

Result<std::string> repairFbxNullRecords(const std::string& binaryFbx);

} // namespace rs::io
