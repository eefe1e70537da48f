// The template library's commands: check-templates (list the templates of
// the built-in folder and of the folders named, fail on their errors),
// describe-template (one manifest as text) and shape-icons (draw, or with
// --check verify, the shapes library's SVG icons).
#include "cli/Commands.h"

#include "base/Paths.h"
#include "io/AtomicFile.h"
#include "io/ShapeFile.h"
#include "io/TemplateFolders.h"
#include "io/YamlText.h"
#include "templates/ManifestDump.h"
#include "templates/ShapeIcon.h"

#include <filesystem>
#include <iostream>

namespace rs::cli {

int runCheckTemplates(const std::vector<std::string>& args)
{
    // The built-in folder always loads first, so user templates can use its shapes
    // and bases; only the folders asked for are listed.
    std::vector<std::string> folders = templateSearchPath();
    if (!args.empty())
        folders = {builtinTemplatesDirectory()};
    folders.insert(folders.end(), args.begin(), args.end());
    templates::TemplateRegistry registry;
    const Diagnostics diagnostics = io::scanTemplates(registry, folders, iconsDirectory());
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
    auto registry = io::loadDefaultTemplates(diagnostics);
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
    io::loadShapeDirectory(library, directory, diagnostics);
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
        } else if (const Status written = io::writeFileAtomically(file, svg); written.failed()) {
            print(written.diagnostics());
            status = 1;
        }
    }
    std::cout << library.size() << " shapes" << (check ? " checked" : " drawn") << '\n';
    return status;
}

} // namespace rs::cli
