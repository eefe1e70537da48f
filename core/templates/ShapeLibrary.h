#pragma once
// The controller shapes library: templates/shapes/<name>.yml, each a list of
// NURBS curves (degree 1-3, optionally periodic, optional per-curve colour),
// unit-sized and Y-up (a circle lies in the XZ plane). The data only: the files
// are read by io/ShapeFile.
#include "base/Math.h"
#include "templates/Color.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rs::templates {

struct ShapeCurve {
    int degree = 1;
    bool periodic = false;
    std::vector<Vec3> points; // control points
    std::optional<Color> color;
};

struct Shape {
    std::string name;
    std::string file;
    std::vector<ShapeCurve> curves;
};

class ShapeLibrary {
public:
    void add(Shape shape); // replaces a shape of the same name
    const Shape* find(const std::string& name) const;
    std::vector<std::string> names() const;
    std::size_t size() const { return m_shapes.size(); }
    void clear() { m_shapes.clear(); }

private:
    std::map<std::string, Shape> m_shapes;
};

// Samples a curve into a polyline. Periodic curves use uniform knots over the
// control points wrapped by `degree`; open curves of degree > 1 use clamped knots.
// A periodic result repeats its first point at the end.
std::vector<Vec3> evaluateCurve(const ShapeCurve& curve, int samplesPerSpan = 8);

} // namespace rs::templates
