// rigsmith-cli new / add: author guides without a display, one template at a time.
#include "cli/Commands.h"

#include "rigging/RigBuilder.h"
#include "templates/GuideTemplates.h"
#include "templates/HookPoints.h"
#include "edit/GuideEdits.h"
#include "io/GuideFile.h"
#include "io/TemplateFolders.h"

#include "base/TextScalars.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <iostream>

namespace rs::cli {

namespace {

// "on", "3", "0.25", "[L, R]", "chest": the YAML scalar types options use.
// Nullopt (with the reason) for a number that is not finite or does not fit.
std::optional<Value> parseOptionValue(const std::string& text, std::string& error)
{
    if (text == "on" || text == "true" || text == "yes") return true;
    if (text == "off" || text == "false" || text == "no") return false;
    if (auto i = parseInteger(text)) return *i;
    // Digits that do not fit a long long are out of range, not a double.
    const bool integral = text.find_first_not_of("+-0123456789") == std::string::npos &&
                          text.find_first_of("0123456789") != std::string::npos;
    if (auto d = parseNumber(text); d && !integral) {
        if (std::isfinite(*d)) return *d;
        error = "is not a finite number";
        return std::nullopt;
    }
    char* end = nullptr; // parseNumber refuses a double that does not fit: tell that from text
    errno = 0;
    std::strtod(text.c_str(), &end);
    if (integral || (end != text.c_str() && *end == '\0' && errno == ERANGE)) {
        error = "is out of range";
        return std::nullopt;
    }
    return text;
}

// "[X, Y, Z]" or "X,Y,Z": three finite numbers; nullopt for anything else.
std::optional<Vec3> parseVector(std::string text)
{
    if (text.size() >= 2 && text.front() == '[' && text.back() == ']')
        text = text.substr(1, text.size() - 2);
    Vec3 out(0.0);
    int n = 0;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = text.find(',', start);
        std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        item.erase(0, item.find_first_not_of(' '));
        item.erase(item.find_last_not_of(' ') + 1);
        const auto number = parseNumber(item);
        if (n == 3 || !number || !std::isfinite(*number))
            return std::nullopt;
        out[n++] = *number;
        if (comma == std::string::npos)
            break;
        start = comma + 1;
    }
    return n == 3 ? std::optional<Vec3>(out) : std::nullopt;
}

// Names and values go into the guide and from there into exports, which want UTF-8.
bool isUtf8Argument(const std::string& command, const std::string& flag, const std::string& value)
{
    if (invalidUtf8Offset(value) == std::string::npos)
        return true;
    std::cerr << "rigsmith-cli " << command << ": " << flag << " is not valid UTF-8\n";
    return false;
}

} // namespace

int runNew(const std::vector<std::string>& args)
{
    std::string path, name;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--name" && i + 1 < args.size()) { name = args[++i]; if (!isUtf8Argument("new", "--name", name)) return 2; }
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
    if (name.empty() && invalidUtf8Offset(document.name) != std::string::npos) { // the guide would not open again
        std::cerr << "rigsmith-cli new: the file name is not valid UTF-8, so it cannot name the guide; give one with --name\n";
        return 2;
    }
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
        else if (a == "--name" && i + 1 < args.size()) { name = args[++i]; if (!isUtf8Argument("add", "--name", name)) return 2; }
        else if (a == "--at" && i + 1 < args.size()) {
            at = parseTriple("add", "--at", args[++i], kMaxCoordinate, "metres");
            if (!at)
                return 2;
        } else if (a == "--set" && i + 1 < args.size()) {
            const std::string pair = args[++i];
            const auto eq = pair.find('=');
            if (eq == std::string::npos || eq == 0) { std::cerr << "rigsmith-cli add: --set expects OPTION=VALUE, got '" << pair << "'\n"; return 2; }
            if (!isUtf8Argument("add", "--set", pair)) return 2;
            std::string why;
            const auto value = parseOptionValue(pair.substr(eq + 1), why);
            if (!value) { std::cerr << "rigsmith-cli add: --set " << pair.substr(0, eq) << ": '" << pair.substr(eq + 1) << "' " << why << "\n"; return 2; }
            options[pair.substr(0, eq)] = *value;
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
    // A vector option's --set text ("[0, 0, 1]" or "0,0,1") becomes the vector the template takes.
    if (const auto* manifest = templates->find(templateId))
        for (auto& [option, value] : options)
            if (const auto* p = manifest->findOpt(option); p && typeOf(p->value) == ValueType::Vec3)
                if (const auto* text = std::get_if<std::string>(&value))
                    if (const auto vector = parseVector(*text))
                        value = *vector;
    auto instance = rigging::makeInstance(*guide, *templates, templateId, hookJoint, options);
    print(instance.diagnostics());
    if (!instance)
        return 1;
    // A value given with --set that the template cannot take (a word for a
    // number, a label it does not list, out of range) is refused, not replaced.
    for (const Diagnostic& d : instance.diagnostics())
        for (const auto& [option, value] : options)
            if (d.severity != Severity::Note && d.message.find("option '" + option + "'") != std::string::npos) {
                std::cerr << "rigsmith-cli add: --set " << option << " was not taken; nothing was added\n";
                return 1;
            }
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
