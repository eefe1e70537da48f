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
// One component between sRGB (what colour pickers and manifests show) and
// linear light (what the renderer shades with), by the sRGB transfer
// function (IEC 61966-2-1), both in [0, 1]; values outside are clamped.
double srgbToLinear(double srgb);
double linearToSrgb(double linear);

} // namespace rs::templates
