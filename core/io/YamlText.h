#pragma once
// The text-level side of io's YAML, for callers outside io: no yaml-cpp type
// appears here (io/YamlSupport.h, which has them, is internal to io/).
#include <optional>
#include <string>

namespace rs::io {

// The whole file as bytes, or nullopt when it cannot be opened.
std::optional<std::string> readTextFile(const std::string& path);
// Quotes text that would otherwise read back as another type or break YAML.
std::string quoteIfNeeded(const std::string& text);
// True when the text parses as YAML: the options editor's check of a YAML
// option (`[a, b]`, `{k: v}`) before it becomes an edit. Empty text is valid.
bool isValidYaml(const std::string& text);

} // namespace rs::io
