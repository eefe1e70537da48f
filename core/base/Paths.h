#pragma once
// Where Rigsmith finds its data (templates, icons, samples). The data directory is
// $RIGSMITH_DATA_DIR when set, else the source tree the binaries were built from.
#include <string>
#include <vector>

namespace rs {

std::string dataDirectory();
std::string builtinTemplatesDirectory();
std::string iconsDirectory();
std::string samplesDirectory();
// The built-in templates folder followed by the folders of $RIGSMITH_TEMPLATE_PATH
// (':'-separated). Later folders override templates with the same id.
std::vector<std::string> templateSearchPath();

} // namespace rs
