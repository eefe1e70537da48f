#include "templates/ShapeIcon.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace rs::templates {

namespace {

enum class View { Top, Front, Side, ThreeQuarter };

// Image-plane coordinates (x right, y up) of a point for a view.
glm::dvec2 project(const Vec3& p, View view)
{
    switch (view) {
    case View::Top: return {p.x, p.z};
    case View::Front: return {p.x, p.y};
    case View::Side: return {p.z, p.y};
    case View::ThreeQuarter: {
        const double yaw = glm::radians(-35.0), pitch = glm::radians(25.0);
        const double x = p.x * std::cos(yaw) + p.z * std::sin(yaw);
        const double z = -p.x * std::sin(yaw) + p.z * std::cos(yaw);
        return {x, p.y * std::cos(pitch) - z * std::sin(pitch)};
    }
    }
    return {};
}

std::string hexColor(const Color& c)
{
    char text[8];
    auto byte = [](double v) { return int(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
    std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
    return text;
}

std::string number(double v)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", v);
    return text;
}

} // namespace

std::string shapeIconSvg(const Shape& shape, int pixels)
{
    std::vector<std::vector<Vec3>> curves;
    Vec3 lo(1e300), hi(-1e300);
    for (const ShapeCurve& c : shape.curves) {
        curves.push_back(evaluateCurve(c, 12));
        for (const Vec3& p : curves.back()) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    }
    const Vec3 extent = hi - lo;
    const double largest = std::max({extent.x, extent.y, extent.z, 1e-9});
    View view = View::ThreeQuarter;
    if (extent.y <= largest * 1e-3) view = View::Top;
    else if (extent.z <= largest * 1e-3) view = View::Front;
    else if (extent.x <= largest * 1e-3) view = View::Side;

    glm::dvec2 min(1e300), max(-1e300);
    for (const auto& c : curves)
        for (const Vec3& p : c) {
            min = glm::min(min, project(p, view));
            max = glm::max(max, project(p, view));
        }
    const double margin = pixels * 0.08;
    const double span = std::max({max.x - min.x, max.y - min.y, 1e-9});
    const double scale = (pixels - 2.0 * margin) / span;
    const glm::dvec2 centre = (min + max) * 0.5;

    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << pixels << "\" height=\"" << pixels
        << "\" viewBox=\"0 0 " << pixels << ' ' << pixels << "\">\n";
    svg << "  <title>" << shape.name << "</title>\n";
    const Color fallback{0.93, 0.78, 0.35};
    for (std::size_t k = 0; k < curves.size(); ++k) {
        svg << "  <polyline fill=\"none\" stroke=\"" << hexColor(shape.curves[k].color.value_or(fallback))
            << "\" stroke-width=\"" << number(pixels / 24.0) << "\" stroke-linejoin=\"round\" stroke-linecap=\"round\" points=\"";
        for (std::size_t i = 0; i < curves[k].size(); ++i) {
            const glm::dvec2 q = project(curves[k][i], view) - centre;
            svg << (i ? " " : "") << number(pixels * 0.5 + q.x * scale) << ',' << number(pixels * 0.5 - q.y * scale);
        }
        svg << "\"/>\n";
    }
    svg << "</svg>\n";
    return svg.str();
}

} // namespace rs::templates
