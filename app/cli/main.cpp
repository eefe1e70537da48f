// rigsmith-cli: builds and exports rigs without a display (pipelines, CI).
#include "cli/Commands.h"

#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help" || args[0] == "-h") {
        std::cout << rs::cli::usage();
        return args.empty() ? 2 : 0;
    }
    const std::string command = args.front();
    args.erase(args.begin());
    if (command == "build")
        return rs::cli::runBuild(args);
    if (command == "check-templates")
        return rs::cli::runCheckTemplates(args);
    if (command == "describe-template")
        return rs::cli::runDescribeTemplate(args);
    if (command == "new")
        return rs::cli::runNew(args);
    if (command == "add")
        return rs::cli::runAdd(args);
    if (command == "joint")
        return rs::cli::runJoint(args);
    if (command == "shape-icons")
        return rs::cli::runShapeIcons(args);
    if (command == "skin")
        return rs::cli::runSkin(args);
    if (command == "model")
        return rs::cli::runModel(args);
    std::cerr << "rigsmith-cli: unknown command '" << command << "'\n" << rs::cli::usage();
    return 2;
}
