#pragma once
// Reads the shapes library's files (templates/shapes/<name>.yml) into
// templates::Shape. Every problem is reported with file:line:col; a shape with
// errors yields no value.
#include "base/Diagnostic.h"
#include "templates/ShapeLibrary.h"

#include <optional>
#include <string>
#include <vector>

namespace rs::io {

std::optional<templates::Shape> readShapeFile(const std::string& file, Diagnostics& diagnostics);
// `file` names the shape (its stem) and the diagnostics.
std::optional<templates::Shape> readShapeText(const std::string& text, const std::string& file,
                                              Diagnostics& diagnostics);

// The *.yml files of a shapes folder, sorted.
std::vector<std::string> shapeFilesIn(const std::string& directory);
// Adds every shape of the folder to `library` (a later name replaces an earlier one).
void loadShapeDirectory(templates::ShapeLibrary& library, const std::string& directory, Diagnostics& diagnostics);

} // namespace rs::io
