#include "core/TestSupport.h"
#include "templates/Color.h"
#include "templates/ShapeIcon.h"
#include "templates/ShapeLibrary.h"
#include "io/ShapeFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace rs;
using namespace rs::templates;

TEST(ShapeLibrary, LoadsTheBuiltinShapes)
{
    const auto& shapes = test::builtinTemplates().shapes();
    for (const char* name : {"circle", "square", "cube", "sphere", "cross", "diamond", "move", "world", "axis"})
        EXPECT_NE(shapes.find(name), nullptr) << name;
    ASSERT_EQ(shapes.find("axis")->curves.size(), 3u);
    EXPECT_EQ(shapes.find("axis")->curves[0].color, parseColor("red"));
}

TEST(ShapeLibrary, EvaluatesAPeriodicCubicAsAClosedCurve)
{
    const Shape* circle = test::builtinTemplates().shapes().find("circle");
    ASSERT_NE(circle, nullptr);
    const auto points = evaluateCurve(circle->curves[0], 8);
    ASSERT_EQ(points.size(), 8u * 8u + 1u);
    EXPECT_EQ(points.front(), points.back());
    // A uniform periodic cubic through 8 evenly spaced CVs stays round.
    double lo = 1e9, hi = 0;
    for (const Vec3& p : points) {
        lo = std::min(lo, glm::length(p));
        hi = std::max(hi, glm::length(p));
        EXPECT_NEAR(p.y, 0.0, 1e-12);
    }
    EXPECT_LT(hi - lo, 0.01 * hi);
}

TEST(ShapeLibrary, ClampsOpenCurvesToTheirEndPoints)
{
    ShapeCurve c;
    c.degree = 3;
    c.points = {{0, 0, 0}, {1, 1, 0}, {2, -1, 0}, {3, 1, 0}, {4, 0, 0}};
    const auto points = evaluateCurve(c, 4);
    EXPECT_EQ(points.front(), Vec3(0, 0, 0));
    EXPECT_LT(glm::length(points.back() - Vec3(4, 0, 0)), 1e-12);
}

TEST(ShapeLibrary, ReportsBadShapeFilesWithPositions)
{
    const std::string path = test::temporaryPath("bad.yml");
    std::ofstream(path) << "- degree: 5\n  points: [[0, 0, 0], [1, 0, 0]]\n- points: [[0, 0], [1, 0, 0]]\n  color: blurple\n";
    Diagnostics d;
    EXPECT_FALSE(io::readShapeFile(path, d));
    ASSERT_EQ(d.size(), 3u) << formatAll(d);
    EXPECT_EQ(d[0].format(), path + ":1:11: error: curve 0.degree must be 1, 2 or 3");
    EXPECT_EQ(d[1].format(), path + ":3:12: error: curve 1 point must be a list of 3 numbers, got a list of 2 items");
    EXPECT_EQ(d[2].format(), path + ":4:10: error: unknown colour 'blurple'");
}

TEST(Color, ParsesCssNamesAndHex)
{
    EXPECT_EQ(formatColor(*parseColor("dodgerblue")), "#1e90ff");
    EXPECT_EQ(formatColor(*parseColor("RebeccaPurple")), "#663399");
    EXPECT_EQ(formatColor(*parseColor("#F00")), "#ff0000");
    EXPECT_EQ(formatColor(*parseColor("#12abEF")), "#12abef");
    EXPECT_FALSE(parseColor("#12345"));
    EXPECT_FALSE(parseColor("notacolour"));
    EXPECT_EQ(formatColor(shiftHue(*parseColor("red"), 120.0)), "#00ff00");
}

TEST(Color, ConvertsBetweenSrgbAndLinearByTheSrgbTransferFunction)
{
    EXPECT_DOUBLE_EQ(srgbToLinear(0.0), 0.0);
    EXPECT_DOUBLE_EQ(srgbToLinear(1.0), 1.0);
    EXPECT_NEAR(srgbToLinear(0.5), 0.2140, 1e-4);     // the sRGB curve, not a 2.2 gamma (0.2176)
    EXPECT_NEAR(srgbToLinear(0.04045), 0.04045 / 12.92, 1e-12); // the linear toe
    EXPECT_NEAR(linearToSrgb(0.2140), 0.5, 1e-4);
    for (double v : {0.001, 0.02, 0.3, 0.7, 0.99})
        EXPECT_NEAR(linearToSrgb(srgbToLinear(v)), v, 1e-12) << v;
    EXPECT_DOUBLE_EQ(linearToSrgb(1.5), 1.0) << "clamped";
}

TEST(ShapeLibrary, ShipsAtLeastFortyShapesEachWithAnUpToDateIcon)
{
    const auto& shapes = test::builtinTemplates().shapes();
    EXPECT_GE(shapes.size(), 40u);
    for (const char* name : {"arrow", "pyramid", "cylinder", "gear", "foot", "hand", "eye", "torus", "cone"})
        EXPECT_NE(shapes.find(name), nullptr) << name;
    for (const std::string& name : shapes.names()) {
        const Shape& shape = *shapes.find(name);
        const auto icon = std::filesystem::path(shape.file).parent_path() / "icons" / (name + ".svg");
        ASSERT_TRUE(std::filesystem::exists(icon)) << icon << " (run rigsmith-cli shape-icons)";
        EXPECT_EQ(test::readText(icon.string()), shapeIconSvg(shape)) << icon << " is out of date (run rigsmith-cli shape-icons)";
    }
}

TEST(ShapeIcon, DrawsFlatShapesFaceOnAndKeepsCurveColours)
{
    Shape shape;
    shape.name = "test";
    ShapeCurve line;
    line.points = {{-0.5, 0, -0.5}, {0.5, 0, 0.5}};
    line.color = parseColor("red");
    shape.curves.push_back(line);
    const std::string svg = shapeIconSvg(shape, 64);
    // Top view, +Z up the icon: (-0.5,-0.5) maps to the bottom-left corner inside the margin.
    EXPECT_NE(svg.find("points=\"5.1,58.9 58.9,5.1\""), std::string::npos) << svg;
    EXPECT_NE(svg.find("stroke=\"#ff0000\""), std::string::npos) << svg;
}
