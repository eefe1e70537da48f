#include "cli/Commands.h"

#include "base/Paths.h"
#include "build/RigBuilder.h"
#include "eval/PoseTools.h"
#include "io/GltfExport.h"
#include "io/GuideFile.h"
#include "io/RigDump.h"
#include "io/YamlSupport.h"
#include "model/Skeleton.h"
#include "templates/ManifestDump.h"
#include "templates/ShapeIcon.h"

#include <chrono>
#include <filesystem>
#include <cstdio>
#include <iostream>

namespace rs::cli {

namespace {

void print(const Diagnostics& diagnostics)
{
    for (const auto& d : diagnostics)
        std::cerr << d.format() << '\n';
}

} // namespace

std::string usage()
{
    return "usage: rigsmith-cli build GUIDE [--posed] [--dump RIG.yml] [--skeleton SKELETON.json] [-o OUT.glb|OUT.gltf]\n"
           "                          [--names unity|MAP.yml] [--fix-names] [--force]\n"
           "       (--posed: write the rig in the guide's test pose instead of its rest pose;\n"
           "        --names: export names from a name map; the export validator's errors refuse -o unless\n"
           "        --force; --fix-names applies its safe renames)\n"
           "       rigsmith-cli new GUIDE.yml [--name NAME]   (an empty guide)\n"
           "       rigsmith-cli add GUIDE.yml TEMPLATE [--under INSTANCE[:HOOK]] [--name NAME] [--at X,Y,Z] [--set OPTION=VALUE]...\n"
           "       rigsmith-cli check-templates [DIR...]\n"
           "       rigsmith-cli describe-template ID   (what Rigsmith understood of every key)\n"
           "       rigsmith-cli shape-icons [--check] [SHAPES_DIR]   (writes SHAPES_DIR/icons/<shape>.svg)\n";
}

int runBuild(const std::vector<std::string>& args)
{
    std::string guidePath, dumpPath, outPath, skeletonPath;
    bool posed = false;
    io::GltfExportOptions exportOptions;
    std::string namesArgument;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--posed")
            posed = true;
        else if (a == "--force")
            exportOptions.force = true;
        else if (a == "--fix-names")
            exportOptions.fixNames = true;
        else if (a == "--names" && i + 1 < args.size())
            namesArgument = args[++i];
        else if ((a == "--dump" || a == "-o" || a == "--skeleton") && i + 1 < args.size())
            (a == "--dump" ? dumpPath : a == "-o" ? outPath : skeletonPath) = args[++i];
        else if (!a.empty() && a[0] != '-' && guidePath.empty())
            guidePath = a;
        else {
            std::cerr << "rigsmith-cli: unexpected argument '" << a << "'\n" << usage();
            return 2;
        }
    }
    if (guidePath.empty()) {
        std::cerr << usage();
        return 2;
    }
    io::NameMap names;
    if (namesArgument == "unity") {
        names = io::unityHumanoidMap();
    } else if (!namesArgument.empty()) {
        auto read = io::readNameMap(namesArgument);
        print(read.diagnostics());
        if (!read)
            return 1;
        names = read.take();
    }
    if (!namesArgument.empty())
        exportOptions.names = &names;
    Diagnostics templateDiagnostics;
    auto templates = templates::TemplateRegistry::loadDefault(templateDiagnostics);
    print(templateDiagnostics);
    auto guide = io::readGuideFile(guidePath);
    print(guide.diagnostics());
    if (!guide)
        return 1;
    const auto start = std::chrono::steady_clock::now();
    model::Rig rig = build::buildRig(*guide, *templates);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    print(rig.diagnostics);
    if (posed && !hasErrors(rig.diagnostics)) {
        auto withPose = eval::posedRig(rig, guide->pose);
        print(withPose.diagnostics());
        if (!withPose)
            return 1;
        rig = withPose.take();
        std::cerr << "posed with " << guide->pose.size() << " posed nodes from the guide\n";
    }
    std::cerr << "built " << rig.nodes.size() << " nodes (" << rig.count(model::RigNodeKind::Controller)
              << " controllers, " << rig.skinJointCount() << " skin joints) in " << ms << " ms\n";
    int status = hasErrors(rig.diagnostics) ? 1 : 0;
    if (!dumpPath.empty()) {
        const std::string text = io::writeRigDump(rig);
        if (dumpPath == "-")
            std::cout << text;
        else if (auto d = io::writeFileAtomically(dumpPath, text); !d.empty()) {
            print(d);
            status = 1;
        }
    }
    if (!skeletonPath.empty()) {
        auto skeleton = model::extractSkeleton(rig);
        Diagnostics d = skeleton ? io::writeFileAtomically(skeletonPath, io::writeSkeletonJson(*skeleton))
                                 : skeleton.takeDiagnostics();
        print(d);
        if (hasErrors(d))
            status = 1;
    }
    if (!outPath.empty()) {
        const Diagnostics d = io::exportGltf(rig, outPath, exportOptions);
        print(d);
        if (hasErrors(d))
            status = 1;
        else
            std::cerr << "exported " << outPath << '\n';
    }
    return status;
}

int runCheckTemplates(const std::vector<std::string>& args)
{
    // The built-in folder always loads first, so user templates can use its shapes
    // and bases; only the folders asked for are listed.
    std::vector<std::string> folders = templateSearchPath();
    if (!args.empty())
        folders = {builtinTemplatesDirectory()};
    folders.insert(folders.end(), args.begin(), args.end());
    templates::TemplateRegistry registry;
    const Diagnostics diagnostics = registry.scan(folders, iconsDirectory());
    auto listed = [&](const templates::TemplateManifest& m) {
        if (args.empty())
            return true;
        for (const std::string& folder : args)
            if (m.file.rfind(folder, 0) == 0)
                return true;
        return false;
    };
    for (const auto* m : registry.all()) {
        if (!listed(*m))
            continue;
        std::cout << m->id << ": structure [";
        for (std::size_t i = 0; i < m->structure.size(); ++i)
            std::cout << (i ? ", " : "") << m->structure[i].first;
        std::cout << "] hooks [";
        for (std::size_t i = 0; i < m->hooks.size(); ++i)
            std::cout << (i ? ", " : "") << m->hooks[i].label;
        std::cout << "] opts " << m->opts.size() << '\n';
    }
    std::cout << registry.shapes().size() << " shapes\n";
    for (const auto& d : diagnostics)
        std::cout << d.format() << '\n';
    return hasErrors(diagnostics) ? 1 : 0;
}

int runDescribeTemplate(const std::vector<std::string>& args)
{
    if (args.size() != 1) {
        std::cerr << usage();
        return 2;
    }
    Diagnostics diagnostics;
    auto registry = templates::TemplateRegistry::loadDefault(diagnostics);
    print(diagnostics);
    const templates::TemplateManifest* m = registry->find(args[0]);
    if (!m) {
        std::cerr << "rigsmith-cli: no template '" << args[0] << "'\n";
        return 1;
    }
    std::cout << templates::describeManifest(*m);
    return 0;
}

int runShapeIcons(const std::vector<std::string>& args)
{
    bool check = false;
    std::string directory;
    for (const std::string& a : args) {
        if (a == "--check") check = true;
        else if (!a.empty() && a[0] != '-' && directory.empty()) directory = a;
        else {
            std::cerr << "rigsmith-cli: unexpected argument '" << a << "'\n" << usage();
            return 2;
        }
    }
    if (directory.empty())
        directory = (std::filesystem::path(dataDirectory()) / "templates" / "shapes").string();
    templates::ShapeLibrary library;
    Diagnostics diagnostics;
    library.loadDirectory(directory, diagnostics);
    print(diagnostics);
    int status = hasErrors(diagnostics) ? 1 : 0;
    const std::filesystem::path icons = std::filesystem::path(directory) / "icons";
    std::error_code ec;
    if (!check)
        std::filesystem::create_directories(icons, ec);
    for (const std::string& name : library.names()) {
        const std::string svg = templates::shapeIconSvg(*library.find(name));
        const std::string file = (icons / (name + ".svg")).string();
        if (check) {
            auto existing = io::readTextFile(file);
            if (!existing || *existing != svg) {
                std::cerr << file << ": " << (existing ? "out of date" : "missing")
                          << " (run rigsmith-cli shape-icons " << directory << ")\n";
                status = 1;
            }
        } else if (auto d = io::writeFileAtomically(file, svg); !d.empty()) {
            print(d);
            status = 1;
        }
    }
    std::cout << library.size() << " shapes" << (check ? " checked" : " drawn") << '\n';
    return status;
}

} // namespace rs::cli
