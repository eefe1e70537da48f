// rigsmith-cli new / add: author guides without a display, one template at a time.
#include "cli/Commands.h"

#include "rigging/RigBuilder.h"
#include "templates/GuideTemplates.h"
#include "templates/HookPoints.h"
#include "edit/GuideEdits.h"
#include "io/GuideFile.h"
#include "io/TemplateFolders.h"

#include <cstdio>
#include <filesystem>
#include <optional>
#include <iostream>

namespace rs::cli {

namespace {

void print(const Diagnostics& diagnostics)
{
    for (const auto& d : diagnostics)
        std::cerr << d.format() << '\n';
}

// "on", "3", "0.25", "[L, R]", "chest": the YAML scalar types options use.
Value parseOptionValue(const std::string& text)
{
    if (text == "on" || text == "true" || text == "yes") return true;
    if (text == "off" || text == "false" || text == "no") return false;
    char* end = nullptr;
    const long long i = std::strtoll(text.c_str(), &end, 10);
    if (!text.empty() && end && *end == '\0') return i;
    const double d = std::strtod(text.c_str(), &end);
    if (!text.empty() && end && *end == '\0') return d;
    return text;
}

} // namespace

int runNew(const std::vector<std::string>& args)
{
    std::string path, name;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--name" && i + 1 < args.size()) name = args[++i];
        else if (path.empty() && !args[i].empty() && args[i][0] != '-') path = args[i];
        else { std::cerr << "rigsmith-cli new: unexpected argument '" << args[i] << "'\n" << usage(); return 2; }
    }
    if (path.empty()) { std::cerr << usage(); return 2; }
    if (std::filesystem::exists(path)) {
        std::cerr << path << ": already exists; new never overwrites a guide\n";
        return 1;
    }
    model::GuideDocument document;
    document.name = name.empty() ? std::filesystem::path(path).stem().string() : name;
    const Status saved = io::saveGuideFile(document, path);
    print(saved.diagnostics());
    return saved.failed() ? 1 : 0;
}

int runAdd(const std::vector<std::string>& args)
{
    std::string path, templateId, under, name;
    std::map<std::string, Value> options;
    std::optional<Vec3> at; // root joint position, local to the hook joint
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--under" && i + 1 < args.size()) under = args[++i];
        else if (a == "--name" && i + 1 < args.size()) name = args[++i];
        else if (a == "--at" && i + 1 < args.size()) {
            double x, y, z;
            char tail;
            if (std::sscanf(args[++i].c_str(), "%lf,%lf,%lf%c", &x, &y, &z, &tail) != 3) {
                std::cerr << "rigsmith-cli add: --at expects X,Y,Z, got '" << args[i] << "'\n";
                return 2;
            }
            at = Vec3(x, y, z);
        } else if (a == "--set" && i + 1 < args.size()) {
            const std::string pair = args[++i];
            const auto eq = pair.find('=');
            if (eq == std::string::npos || eq == 0) { std::cerr << "rigsmith-cli add: --set expects OPTION=VALUE, got '" << pair << "'\n"; return 2; }
            options[pair.substr(0, eq)] = parseOptionValue(pair.substr(eq + 1));
        } else if (path.empty() && !a.empty() && a[0] != '-') path = a;
        else if (templateId.empty() && !a.empty() && a[0] != '-') templateId = a;
        else { std::cerr << "rigsmith-cli add: unexpected argument '" << a << "'\n" << usage(); return 2; }
    }
    if (path.empty() || templateId.empty()) { std::cerr << usage(); return 2; }

    Diagnostics templateDiagnostics;
    auto templates = io::loadDefaultTemplates(templateDiagnostics);
    auto guide = io::readGuideFile(path);
    print(guide.diagnostics());
    if (!guide)
        return 1;
    print(templates::checkGuideTemplates(*guide, *templates, path));

    // --under INSTANCE[:HOOK]: a hook label of the parent's template (ui.hooks), default "default".
    model::JointId hookJoint = model::kNoId;
    if (!under.empty()) {
        const auto colon = under.find(':');
        const std::string parentName = under.substr(0, colon);
        const std::string label = colon == std::string::npos ? "default" : under.substr(colon + 1);
        const model::TemplateInstance* parent = guide->instanceNamed(parentName);
        if (!parent) { std::cerr << path << ": no instance named '" << parentName << "'\n"; return 1; }
        const auto* manifest = templates->find(parent->templateId);
        std::string labels;
        if (manifest)
            for (const auto& hook : templates::hookPoints(*manifest, *parent)) {
                labels += (labels.empty() ? "" : ", ") + hook.label;
                if (hook.label == label) hookJoint = hook.joint;
            }
        if (hookJoint == model::kNoId) {
            std::cerr << path << ": instance '" << parentName << "' has no hook '" << label << "' (hooks: " << labels << ")\n";
            return 1;
        }
    }
    auto instance = rigging::makeInstance(*guide, *templates, templateId, hookJoint, options);
    print(instance.diagnostics());
    if (!instance)
        return 1;
    if (!name.empty())
        instance->name = name;
    if (at && !instance->joints.empty())
        instance->joints.front().local.translate = *at;
    model::GuideDocument document = std::move(*guide);
    edit::History history(document);
    if (Status added = edit::addInstance(history, std::move(*instance)); added.failed()) {
        Diagnostics refusal = added.takeDiagnostics();
        for (Diagnostic& d : refusal)
            if (d.where.file.empty()) d.where.file = path; // "biped.yml: error: an instance named 'arm' already exists"
        print(refusal);
        return 1;
    }
    const Status saved = io::saveGuideFile(document, path);
    print(saved.diagnostics());
    return saved.failed() ? 1 : 0;
}

} // namespace rs::cli
