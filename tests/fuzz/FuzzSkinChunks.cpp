// libFuzzer target: the skin chunk file reader (io/SkinChunks). The input's
// last 8 bytes are replaced by its checksum, so mutations reach the structure
// checks instead of stopping at the checksum; what is accepted must be written
// back byte for byte.
#include "io/SkinChunks.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    std::string bytes(reinterpret_cast<const char*>(data), size);
    if (bytes.size() >= 8) {
        const std::uint64_t sum = rs::io::skinChunksChecksum(bytes.data(), bytes.size() - 8);
        std::memcpy(bytes.data() + bytes.size() - 8, &sum, 8);
    }
    auto chunks = rs::io::readSkinChunks(bytes, "fuzz/hero.rschunks");
    if (chunks && rs::io::writeSkinChunks(*chunks) != bytes)
        std::abort(); // a file read back must be the file written
    return 0;
}
