#include "io/NameMap.h"

#include "io/YamlSupport.h"

namespace rs::io {

Result<NameMap> readNameMapText(const std::string& text, const std::string& displayName)
{
    auto yaml = loadYamlText(text, displayName);
    if (!yaml)
        return Result<NameMap>::failure(yaml.takeDiagnostics());
    Diagnostics diagnostics;
    YamlReader r(displayName, diagnostics);
    const YAML::Node root = *yaml;
    if (!root.IsMap() || !root["rigsmith_names"]) {
        r.error(root, "not a Rigsmith name map: the file must start with 'rigsmith_names: 1'");
        return Result<NameMap>::failure(diagnostics);
    }
    NameMap map;
    for (const auto& kv : root) {
        const std::string key = kv.first.Scalar();
        if (key == "rigsmith_names")
            continue;
        if (key != "names") {
            r.warning(kv.first, "unknown key '" + key + "' (ignored)");
            continue;
        }
        if (!r.expectMap(kv.second, "names"))
            continue;
        for (const auto& entry : kv.second)
            if (auto name = r.string(entry.second, "export name of '" + entry.first.Scalar() + "'"))
                map.names[entry.first.Scalar()] = *name;
    }
    if (hasErrors(diagnostics))
        return Result<NameMap>::failure(diagnostics);
    return Result<NameMap>(std::move(map), std::move(diagnostics));
}

Result<NameMap> readNameMap(const std::string& path)
{
    auto text = readTextFile(path);
    if (!text)
        return Result<NameMap>::failure(text.takeDiagnostics());
    return readNameMapText(*text, path);
}

model::Skeleton applyNameMap(const model::Rig& rig, model::Skeleton skeleton, const NameMap& map)
{
    for (auto& joint : skeleton.joints) {
        if (joint.node == model::kNoNode || joint.node >= rig.nodes.size())
            continue;
        if (auto byKey = map.byKey.find(rig.nodes[joint.node].key); byKey != map.byKey.end())
            joint.name = byKey->second;
        else if (auto byPath = map.names.find(rig.nodes[joint.node].path); byPath != map.names.end())
            joint.name = byPath->second;
        else if (auto byName = map.names.find(joint.name); byName != map.names.end())
            joint.name = byName->second;
    }
    return skeleton;
}

} // namespace rs::io
