// Writing a guide document (readers are in GuideFile.cpp): the readable,
// diffable YAML a rigger reviews, written atomically.
#include "io/GuideFile.h"

#include "base/TextScalars.h"
#include "io/AtomicFile.h"
#include "io/BuildSettingsFile.h"
#include "io/GuidePose.h"
#include "io/ModFile.h"
#include "io/OverrideFile.h"
#include "io/YamlSupport.h"

#include <filesystem>
#include <sstream>

namespace rs::io {

using model::GuideDocument;
using model::GuideJoint;
using model::TemplateInstance;
namespace fs = std::filesystem;

namespace {

std::string vec3Text(const Vec3& v) { return formatValue(Value(v)); }

} // namespace

std::string writeGuideText(const GuideDocument& doc) { return writeGuideText(doc, {}); }

std::string writeGuideText(const GuideDocument& doc, const std::string& directory)
{
    std::ostringstream out;
    out << "# Rigsmith guide: template instances and their guide joints (metres, degrees).\n";
    out << kGuideFormatKey << ": " << GuideDocument::kSchemaVersion << "\n";
    if (!doc.name.empty())
        out << "name: " << quoteIfNeeded(doc.name) << "\n";
    if (doc.naming != model::NamingRules{}) {
        const auto preset = model::namingPreset(doc.naming.preset);
        if (preset && *preset == doc.naming) {
            out << "naming: " << doc.naming.preset << "\n";
        } else {
            const auto& n = doc.naming;
            out << "naming: {preset: " << n.preset << ", offset: " << quoteIfNeeded(n.offset) << ", controller: "
                << quoteIfNeeded(n.controller) << ", skin: " << quoteIfNeeded(n.skin) << ", group: " << quoteIfNeeded(n.group)
                << ", side: " << quoteIfNeeded(n.side) << ", suffixes: " << (n.suffixes ? "on" : "off")
                << ", lowercase: " << (n.lowercase ? "on" : "off") << "}\n";
        }
    }
    writeBuildSettings(out, doc.build);
    if (!doc.models.empty()) {
        out << "models:\n";
        for (const std::string& model : doc.models) {
            std::string relative = model;
            if (!directory.empty() && fs::path(model).is_absolute())
                relative = fs::path(model).lexically_relative(fs::absolute(directory)).string();
            out << "  - " << quoteIfNeeded(relative.empty() ? model : relative) << "\n";
        }
    }
    out << "instances:" << (doc.instances().empty() ? " []\n" : "\n");
    for (const TemplateInstance& i : doc.instances()) {
        out << "  - id: " << i.id << "\n";
        out << "    template: " << quoteIfNeeded(i.templateId) << "\n";
        out << "    name: " << quoteIfNeeded(i.name) << "\n";
        if (i.parent != model::kNoId) {
            const TemplateInstance* parent = doc.instance(i.parent);
            out << "    parent: " << i.parent;
            if (parent)
                out << "  # " << parent->name;
            out << "\n    hook: " << i.parentJoint << "\n";
        }
        if (!i.options.empty()) {
            out << "    options:\n";
            for (const auto& [name, value] : i.options) {
                const std::string text = formatValue(value);
                out << "      " << quoteIfNeeded(name) << ": "
                    << (std::holds_alternative<std::string>(value) ? quoteIfNeeded(text) : text) << "\n";
            }
        }
        for (const auto* section : {&i.structure, &i.names}) {
            if (section->empty())
                continue;
            out << "    " << (section == &i.structure ? "structure" : "names") << ":\n";
            for (const auto& [key, text] : *section)
                out << "      " << quoteIfNeeded(key) << ": " << quoteIfNeeded(text) << "\n";
        }
        out << "    joints:\n";
        for (const GuideJoint& j : i.joints) {
            out << "      - {id: " << j.id;
            if (j.parent != model::kNoId)
                out << ", parent: " << j.parent;
            if (!j.name.empty())
                out << ", name: " << quoteIfNeeded(j.name);
            out << ", t: " << vec3Text(j.local.translate);
            if (j.local.rotateDegrees != Vec3(0.0))
                out << ", r: " << vec3Text(j.local.rotateDegrees);
            if (j.local.scale != Vec3(1.0))
                out << ", s: " << vec3Text(j.local.scale);
            if (!j.tags.empty()) {
                out << ", tags: [";
                for (std::size_t k = 0; k < j.tags.size(); ++k)
                    out << (k ? ", " : "") << quoteIfNeeded(j.tags[k]);
                out << "]";
            }
            out << "}\n";
        }
    }
    writeOverrides(out, doc);
    writeMods(out, doc);
    writeLegacyPose(out, doc);
    return out.str();
}

Status saveGuideFile(const GuideDocument& document, const std::string& path)
{
    return writeFileAtomically(path, writeGuideText(document, fs::absolute(path).parent_path().string()));
}

} // namespace rs::io
