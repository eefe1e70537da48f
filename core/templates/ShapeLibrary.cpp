#include "templates/ShapeLibrary.h"

#include "base/Nurbs.h"

namespace rs::templates {

void ShapeLibrary::add(Shape shape)
{
    const std::string name = shape.name;
    m_shapes[name] = std::move(shape);
}

const Shape* ShapeLibrary::find(const std::string& name) const
{
    auto it = m_shapes.find(name);
    return it == m_shapes.end() ? nullptr : &it->second;
}

std::vector<std::string> ShapeLibrary::names() const
{
    std::vector<std::string> out;
    for (const auto& [name, shape] : m_shapes)
        out.push_back(name);
    return out;
}

std::vector<Vec3> evaluateCurve(const ShapeCurve& curve, int samplesPerSpan)
{
    return evaluateNurbs(curve.points, curve.degree, curve.periodic, samplesPerSpan);
}

} // namespace rs::templates
