#pragma once
// rigsmith-cli sub-commands. Each returns the process exit code: 0 success,
// 1 the input had errors, 2 bad usage.
#include "base/Diagnostic.h"

#include <string>
#include <vector>

namespace rs::cli {

int runBuild(const std::vector<std::string>& args);
int runCheckTemplates(const std::vector<std::string>& args);
int runDescribeTemplate(const std::vector<std::string>& args);
int runNew(const std::vector<std::string>& args);
int runAdd(const std::vector<std::string>& args);
int runJoint(const std::vector<std::string>& args);
int runShapeIcons(const std::vector<std::string>& args);
int runSkin(const std::vector<std::string>& args);
// skin export / import / transfer / info (args[0] is the sub-command).
int runSkinExport(const std::vector<std::string>& args);
int runSkinImport(const std::vector<std::string>& args);
int runSkinInfo(const std::vector<std::string>& args);
int runSkinTransfer(const std::vector<std::string>& args);
int runModel(const std::vector<std::string>& args);
std::string usage();
// Diagnostics on stderr, one "file:line: severity: message" line each.
void print(const Diagnostics& diagnostics);

} // namespace rs::cli
