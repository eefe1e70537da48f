#include "io/BuildSettingsFile.h"

namespace rs::io {

namespace {

std::string kindList()
{
    std::string out;
    for (int k = 0; k < model::kOverrideKindCount; ++k)
        out += std::string(k ? ", " : "") + model::overrideKindName(model::OverrideKind(k));
    return out;
}

void readNoRestore(YamlReader& r, const YAML::Node& node, model::RestoreToggles& restore)
{
    if (node.IsNull())
        return;
    if (!r.expectSequence(node, "build: no_restore"))
        return;
    for (const auto& item : node) {
        const auto name = r.string(item, "build: no_restore");
        if (!name)
            continue;
        if (const auto kind = model::parseOverrideKind(*name))
            restore.set(*kind, false);
        else
            r.error(item, "unknown override kind '" + *name + "' in build: no_restore (known: " + kindList() + ")");
    }
}

} // namespace

void readBuildSettings(YamlReader& r, const YAML::Node& node, model::BuildSettings& settings)
{
    if (node.IsNull())
        return;
    if (!r.expectMap(node, "build"))
        return;
    for (const auto& kv : node) {
        const std::string key = kv.first.Scalar();
        if (key == "cleanup") {
            if (const auto on = r.boolean(kv.second, "build: cleanup"))
                settings.cleanup = *on;
        } else if (key == "no_restore") {
            readNoRestore(r, kv.second, settings.restore);
        } else {
            r.warning(kv.first, "unknown key '" + key + "' in build (known: cleanup, no_restore; ignored)");
        }
    }
}

void writeBuildSettings(std::ostream& out, const model::BuildSettings& settings)
{
    if (settings.isDefault())
        return;
    out << "build:\n";
    if (settings.cleanup)
        out << "  cleanup: on\n";
    std::string off;
    for (int k = 0; k < model::kOverrideKindCount; ++k)
        if (!settings.restore.restores(model::OverrideKind(k)))
            off += std::string(off.empty() ? "" : ", ") + model::overrideKindName(model::OverrideKind(k));
    if (!off.empty())
        out << "  no_restore: [" << off << "]\n";
}

} // namespace rs::io
