#include "io/ShapeFile.h"

#include "io/YamlSupport.h"

#include <algorithm>
#include <filesystem>

namespace rs::io {

namespace fs = std::filesystem;
using templates::Shape;
using templates::ShapeCurve;

std::optional<Shape> readShapeFile(const std::string& file, Diagnostics& diagnostics)
{
    auto text = readTextFile(file);
    if (!text) {
        Diagnostics refused = text.takeDiagnostics();
        diagnostics.insert(diagnostics.end(), refused.begin(), refused.end());
        return std::nullopt;
    }
    return readShapeText(*text, file, diagnostics);
}

std::optional<Shape> readShapeText(const std::string& text, const std::string& file, Diagnostics& diagnostics)
{
    auto yaml = loadYamlText(text, file);
    if (!yaml) {
        auto d = yaml.takeDiagnostics();
        diagnostics.insert(diagnostics.end(), d.begin(), d.end());
        return std::nullopt;
    }
    const std::size_t before = diagnostics.size();
    YamlReader r(file, diagnostics);
    Shape shape;
    shape.name = fs::path(file).stem().string();
    shape.file = file;
    if (!r.expectSequence(*yaml, "a shape file") || yaml->size() == 0) {
        if (yaml->IsSequence()) r.error(*yaml, "a shape needs at least one curve");
        return std::nullopt;
    }
    int index = 0;
    for (const auto& node : *yaml) {
        const std::string what = "curve " + std::to_string(index++);
        if (!r.expectMap(node, what))
            continue;
        ShapeCurve curve;
        bool havePoints = false;
        const std::size_t errorsBefore = diagnostics.size();
        for (const auto& kv : node) {
            const std::string key = kv.first.Scalar();
            if (key == "degree") {
                if (auto d = r.integer(kv.second, what + ".degree")) {
                    if (*d < 1 || *d > 3) r.error(kv.second, what + ".degree must be 1, 2 or 3");
                    curve.degree = static_cast<int>(*d);
                }
            } else if (key == "periodic") {
                if (auto b = r.boolean(kv.second, what + ".periodic")) curve.periodic = *b;
            } else if (key == "points") {
                havePoints = r.expectSequence(kv.second, what + ".points");
                if (havePoints)
                    for (const auto& p : kv.second)
                        if (auto v = r.vec3(p, what + " point")) curve.points.push_back(*v);
            } else if (key == "color") {
                if (auto text = r.string(kv.second, what + ".color")) {
                    curve.color = templates::parseColor(*text);
                    if (!curve.color) r.error(kv.second, "unknown colour '" + *text + "'");
                }
            } else if (key == "ghost") {
                r.boolean(kv.second, what + ".ghost");
            } else {
                r.warning(kv.first, "unknown key '" + key + "' in " + what);
            }
        }
        if (!havePoints) {
            r.error(node, what + " has no 'points'");
            continue;
        }
        if (diagnostics.size() != errorsBefore && hasErrors(Diagnostics(diagnostics.begin() + errorsBefore, diagnostics.end())))
            continue; // one message per mistake: no follow-up complaints about this curve
        const std::size_t minimum = std::size_t(curve.degree) + 1;
        if (curve.points.size() < minimum) {
            r.error(node, what + " of degree " + std::to_string(curve.degree) + " needs at least " +
                              std::to_string(minimum) + " points, has " + std::to_string(curve.points.size()));
            continue;
        }
        shape.curves.push_back(std::move(curve));
    }
    if (hasErrors(Diagnostics(diagnostics.begin() + before, diagnostics.end())))
        return std::nullopt;
    return shape;
}

std::vector<std::string> shapeFilesIn(const std::string& directory)
{
    std::vector<std::string> files;
    std::error_code ec;
    if (!fs::is_directory(directory, ec))
        return files;
    for (const auto& entry : fs::directory_iterator(directory, ec))
        if (entry.is_regular_file() && entry.path().extension() == ".yml")
            files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

void loadShapeDirectory(templates::ShapeLibrary& library, const std::string& directory, Diagnostics& diagnostics)
{
    for (const auto& file : shapeFilesIn(directory))
        if (auto shape = readShapeFile(file, diagnostics))
            library.add(std::move(*shape));
}

} // namespace rs::io
