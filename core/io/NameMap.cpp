#include "io/NameMap.h"

#include "io/YamlSupport.h"

#include <cctype>

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

NameMap unityHumanoidMap()
{
    NameMap map;
    auto& m = map.names;
    m["spine::skin.0"] = "Hips";
    m["spine::skin.1"] = "Spine";
    m["spine::skin.2"] = "Chest";
    m["spine::skin.4"] = "UpperChest";
    m["neck::skin.0"] = "Neck";
    m["neck::skin.head"] = "Head";
    for (const auto& [side, word] : {std::pair{"L", "Left"}, std::pair{"R", "Right"}}) {
        const std::string arm = std::string("arm.") + side + "::skin.", leg = std::string("leg.") + side + "::skin.";
        const std::string w(word);
        m[arm + "clavicle"] = w + "Shoulder";
        m[arm + "limb.0"] = w + "UpperArm";
        m[arm + "limb.1"] = w + "LowerArm";
        m[arm + "limb.2"] = w + "Hand";
        m[leg + "limb.0"] = w + "UpperLeg";
        m[leg + "limb.1"] = w + "LowerLeg";
        m[leg + "limb.2"] = w + "Foot";
        m[leg + "ball"] = w + "Toes";
        const char* phalanges[] = {"Proximal", "Intermediate", "Distal"};
        for (int i = 0; i < 3; ++i)
            m[std::string("thumb.") + side + "::skin." + std::to_string(i)] = w + "Thumb" + phalanges[i];
        for (const char* finger : {"index", "middle", "ring", "pinky"}) {
            std::string unity = finger == std::string("pinky") ? "Little" : std::string(finger);
            unity[0] = char(std::toupper(static_cast<unsigned char>(unity[0])));
            for (int i = 0; i < 3; ++i) // skin.0 is the metacarpal, which Unity does not map
                m[std::string(finger) + "." + side + "::skin." + std::to_string(i + 1)] = w + unity + phalanges[i];
        }
    }
    return map;
}

model::Skeleton applyNameMap(const model::Rig& rig, model::Skeleton skeleton, const NameMap& map)
{
    for (auto& joint : skeleton.joints) {
        if (joint.node == model::kNoNode || joint.node >= rig.nodes.size())
            continue;
        if (auto byId = map.names.find(rig.nodes[joint.node].path); byId != map.names.end())
            joint.name = byId->second;
        else if (auto byName = map.names.find(joint.name); byName != map.names.end())
            joint.name = byName->second;
    }
    return skeleton;
}

} // namespace rs::io
