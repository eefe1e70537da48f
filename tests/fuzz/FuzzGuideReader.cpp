// libFuzzer target: the guide reader (io/GuideFile), and the writer on what it accepted.
#include "io/GuideFile.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string text(reinterpret_cast<const char*>(data), size);
    auto guide = rs::io::readGuideText(text, "fuzz/guide.yml");
    if (guide) // what was read must also write and read back without crashing
        (void)rs::io::readGuideText(rs::io::writeGuideText(*guide), "fuzz/written.yml");
    return 0;
}
