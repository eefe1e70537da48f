#pragma once
// yaml-cpp helpers shared by the readers in core. Internal to core: only .cpp
// files include this header, so YAML::Node never leaks into a public header.
#include "base/Diagnostic.h"
#include "base/Math.h"
#include "base/Result.h"
#include "model/Value.h"

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <vector>

namespace rs::io {

// The whole file as bytes, or nullopt when it cannot be opened.
std::optional<std::string> readTextFile(const std::string& path);

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
// Items of a flow-YAML list given as text ("[L, R]"); a plain scalar is one item,
// an empty text none. Nested lists and maps are refused.
std::optional<std::vector<std::string>> parseFlowList(const std::string& text, std::string& error);
// Quotes text that would otherwise read back as another type or break YAML.
std::string quoteIfNeeded(const std::string& text);

// Scalar classification following YAML 1.1 as Mikan's manifests use it (on/off, yes/no).
std::optional<bool> parseBool(const std::string& text);
std::optional<long long> parseInteger(const std::string& text);
std::optional<double> parseNumber(const std::string& text);

} // namespace rs::io
