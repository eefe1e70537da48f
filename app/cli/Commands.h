#pragma once
// rigsmith-cli sub-commands. Each returns the process exit code: 0 success,
// 1 the input had errors, 2 bad usage.
#include "base/Diagnostic.h"
#include "base/Math.h"

#include <optional>

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
// Coordinates of --at / --move, in metres: finite and within a kilometre of the origin.
constexpr double kMaxCoordinate = 1000.0;
// "X,Y,Z" (the value of `flag` of `command`) with each number finite and
// within +-limit, in `unit`; nullopt after printing why on stderr.
std::optional<Vec3> parseTriple(const std::string& command, const std::string& flag, const std::string& text, double limit,
                                const char* unit);
// Diagnostics on stderr, one "file:line: severity: message" line each.
void print(const Diagnostics& diagnostics);

} // namespace rs::cli
