#pragma once
// yaml-cpp helpers shared by the readers in io/. Internal to io: only io/ .cpp
// files include this header, so YAML::Node never leaks out of io (the layering
// test checks it). The scalars (parseBool, parseNumber...) come from base/TextScalars.h.
#include "base/Diagnostic.h"
#include "base/Math.h"
#include "base/Result.h"
#include "base/TextScalars.h"
#include "io/YamlText.h"
#include "model/Value.h"

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <vector>

namespace rs::io {

// Parses a whole file; syntax errors become "file:line:col: error: ...".
Result<YAML::Node> loadYamlFile(const std::string& path);
Result<YAML::Node> loadYamlText(const std::string& text, const std::string& displayName);

SourceLocation locationOf(const YAML::Node& node, const std::string& file);

// Typed readers that report a diagnostic naming the key and the expected type.
// They return nullopt (and append an error) when the node has the wrong type.
class YamlReader {
public:
    YamlReader(std::string file, Diagnostics& diagnostics)
        : m_file(std::move(file)), m_diagnostics(diagnostics) {}

    std::optional<std::string> string(const YAML::Node& node, const std::string& what);
    std::optional<bool> boolean(const YAML::Node& node, const std::string& what);
    std::optional<long long> integer(const YAML::Node& node, const std::string& what);
    std::optional<double> number(const YAML::Node& node, const std::string& what);
    std::optional<Vec3> vec3(const YAML::Node& node, const std::string& what);
    bool expectMap(const YAML::Node& node, const std::string& what);
    bool expectSequence(const YAML::Node& node, const std::string& what);

    void error(const YAML::Node& node, const std::string& message);
    void warning(const YAML::Node& node, const std::string& message);
    const std::string& file() const { return m_file; }
    Diagnostics& diagnostics() { return m_diagnostics; }

private:
    std::string m_file;
    Diagnostics& m_diagnostics;
};

// Infers a value's type from a plain scalar (on/off, int, float, else text) or a
// 3-number list; quoted scalars are always text.
std::optional<Value> readValue(YamlReader& r, const YAML::Node& node, const std::string& what);

} // namespace rs::io
