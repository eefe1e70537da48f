#pragma once
// SVG icons for the shapes library, drawn from the shape's own curves so an icon
// can never disagree with its data. Flat shapes are drawn face-on (top view for
// XZ shapes with +Z up the icon, front view for XY, side view for YZ); 3D shapes
// in a three-quarter view.
#include "templates/ShapeLibrary.h"

#include <string>

namespace rs::templates {

std::string shapeIconSvg(const Shape& shape, int pixels = 64);

} // namespace rs::templates
