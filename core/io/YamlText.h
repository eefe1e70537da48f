#pragma once
// The text-level side of io's YAML, for callers outside io: no yaml-cpp type
// appears here (io/YamlSupport.h, which has them, is internal to io/).
#include "base/Result.h"

#include <cstddef>
#include <string>

namespace rs::io {

// The largest file readTextFile reads (guides, manifests, shapes, name maps).
constexpr std::size_t kMaxTextFileBytes = std::size_t(128) << 20;

// The whole file as bytes. Fails ("path: error: ...") when it cannot be opened,
// is not a regular file (a FIFO, a device, a folder: never blocks waiting on
// one) or is larger than kMaxTextFileBytes.
Result<std::string> readTextFile(const std::string& path);
// Quotes text that would otherwise read back as another type or break YAML.
std::string quoteIfNeeded(const std::string& text);
// True when the text parses as YAML: the options editor's check of a YAML
// option (`[a, b]`, `{k: v}`) before it becomes an edit. Empty text is valid.
bool isValidYaml(const std::string& text);

} // namespace rs::io
