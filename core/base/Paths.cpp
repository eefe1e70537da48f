#include "base/Paths.h"

#include <cstdlib>
#include <sstream>

#ifndef RIGSMITH_DATA_DIR
#error "RIGSMITH_DATA_DIR must be defined by the build"
#endif

namespace rs {

std::string dataDirectory()
{
    if (const char* env = std::getenv("RIGSMITH_DATA_DIR"); env && *env)
        return env;
    return RIGSMITH_DATA_DIR;
}

std::string builtinTemplatesDirectory() { return dataDirectory() + "/templates"; }
std::string iconsDirectory() { return dataDirectory() + "/resources/icons"; }
std::string samplesDirectory() { return dataDirectory() + "/resources/samples"; }

std::vector<std::string> templateSearchPath()
{
    std::vector<std::string> folders{builtinTemplatesDirectory()};
    if (const char* env = std::getenv("RIGSMITH_TEMPLATE_PATH"); env && *env) {
        std::stringstream list(env);
        std::string folder;
        while (std::getline(list, folder, ':'))
            if (!folder.empty())
                folders.push_back(folder);
    }
    return folders;
}

} // namespace rs
