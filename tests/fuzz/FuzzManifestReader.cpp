// libFuzzer target: the template manifest reader (io/ManifestReader), with its
// structure addresses and conditions, and the description of what it accepted.
#include "io/ManifestReader.h"
#include "templates/ManifestDump.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string text(reinterpret_cast<const char*>(data), size);
    auto manifest = rs::io::readManifestText(text, "fuzz/arm/limb/template.yml", "arm", "limb");
    if (manifest)
        (void)rs::templates::describeManifest(*manifest);
    return 0;
}
