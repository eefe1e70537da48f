#pragma once
// The guide document on disk: a readable, diffable YAML file with a schema version.
// Writing is deterministic (fixed key order, shortest round-trip numbers), so a
// file written by Rigsmith loads and saves back byte-identical.
#include "base/Result.h"
#include "base/Status.h"
#include "model/GuideDocument.h"

#include <string>

namespace rs::io {

// The key a guide file starts with, its value the schema version.
inline constexpr const char* kGuideFormatKey = "rigsmith_guide";

// Relative `models:` paths are resolved against the file's folder (an older
// guide's `reference_model:` is read as the first of its models).
Result<model::GuideDocument> readGuideFile(const std::string& path);
Result<model::GuideDocument> readGuideText(const std::string& text, const std::string& displayName);
std::string writeGuideText(const model::GuideDocument& document);
// With `directory` (where the file goes) the reference model's path is written relative to it.
std::string writeGuideText(const model::GuideDocument& document, const std::string& directory);

// Atomic (io/AtomicFile.h): a crash, a full disk or a second writer never damages
// the previous file; saving through a symlink writes its target, keeping its mode.
Status saveGuideFile(const model::GuideDocument& document, const std::string& path);

} // namespace rs::io
