#pragma once
// Controller colours as manifests write them: CSS/X11 names or #rgb / #rrggbb.
// Components are sRGB in [0, 1].
#include <optional>
#include <string>

namespace rs::templates {

struct Color {
    double r = 1.0, g = 1.0, b = 0.0;
    bool operator==(const Color&) const = default;
};

std::optional<Color> parseColor(const std::string& text);
std::string formatColor(const Color& color); // "#rrggbb"
// Rotates the hue by the given degrees (mirrored branches use 120).
Color shiftHue(const Color& color, double degrees);

} // namespace rs::templates
