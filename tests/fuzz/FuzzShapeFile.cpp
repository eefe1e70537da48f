// libFuzzer target: the shape file reader (io/ShapeFile), and the icon drawn from
// what it accepted.
#include "io/ShapeFile.h"
#include "templates/ShapeIcon.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    rs::Diagnostics diagnostics;
    auto shape = rs::io::readShapeText(std::string(reinterpret_cast<const char*>(data), size), "fuzz/shapes/s.yml", diagnostics);
    if (shape)
        (void)rs::templates::shapeIconSvg(*shape);
    return 0;
}
