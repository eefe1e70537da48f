#include "io/ClipFile.h"

#include "io/GuidePose.h"
#include "io/YamlSupport.h"

namespace rs::io {

Result<KeyedClip> readClipText(const std::string& text, const std::string& displayName)
{
    auto yaml = loadYamlText(text, displayName);
    if (!yaml)
        return Result<KeyedClip>::failure(yaml.takeDiagnostics());
    Diagnostics diagnostics;
    YamlReader r(displayName, diagnostics);
    const YAML::Node root = *yaml;
    if (!root.IsMap() || !root["rigsmith_clip"]) {
        r.error(root, "not a Rigsmith clip: the file must start with 'rigsmith_clip: 1'");
        return Result<KeyedClip>::failure(diagnostics);
    }
    KeyedClip clip;
    for (const auto& kv : root) {
        const std::string key = kv.first.Scalar();
        if (key == "rigsmith_clip")
            continue;
        if (key == "name") {
            if (auto name = r.string(kv.second, "name"))
                clip.name = *name;
        } else if (key == "keys") {
            if (!r.expectSequence(kv.second, "keys"))
                continue;
            for (const auto& entry : kv.second) {
                if (!r.expectMap(entry, "a key"))
                    continue;
                const auto time = entry["time"] ? r.number(entry["time"], "time") : std::nullopt;
                if (!entry["time"])
                    r.error(entry, "a key needs a time (seconds)");
                if (!time)
                    continue;
                if (*time < 0.0 || (!clip.times.empty() && *time <= clip.times.back())) {
                    r.error(entry["time"], "key times must increase from 0 s (" + std::to_string(*time) + " s after " +
                                               (clip.times.empty() ? std::string("the start") : std::to_string(clip.times.back()) + " s") + ")");
                    continue;
                }
                model::PoseValues pose;
                std::vector<LegacyPoseRecord> legacy;
                if (entry["pose"])
                    readPose(r, entry["pose"], pose, legacy);
                if (!legacy.empty())
                    r.error(entry["pose"], "a key's pose is a list of {instance, branch, node, values} records");
                clip.times.push_back(*time);
                clip.poses.push_back(std::move(pose));
            }
        } else {
            r.warning(kv.first, "unknown key '" + key + "' (ignored)");
        }
    }
    if (clip.name.empty())
        r.error(root, "a clip needs a name");
    if (!hasErrors(diagnostics) && clip.times.size() < 2)
        r.error(root["keys"] ? root["keys"] : root, "a clip needs at least two keys");
    if (hasErrors(diagnostics))
        return Result<KeyedClip>::failure(diagnostics);
    return Result<KeyedClip>(std::move(clip), std::move(diagnostics));
}

Result<KeyedClip> readClipFile(const std::string& path)
{
    auto text = readTextFile(path);
    if (!text)
        return Result<KeyedClip>::failure(text.takeDiagnostics());
    return readClipText(*text, path);
}

} // namespace rs::io
