#pragma once
// The attach points a template instance offers to child templates (manifest
// `ui.hooks`), resolved to its guide joints. Used by the outliner's Add
// template menu and the CLI; needs only the manifest and the instance.
#include "model/GuideDocument.h"
#include "templates/Manifest.h"

#include <string>
#include <vector>

namespace rs::templates {

// A hook whose address spans several joints expands to "label[i]".
struct HookPoint {
    std::string label;
    model::JointId joint = model::kNoId;
};
// Hooks that do not resolve are left out; an instance without any offers its
// root joint as "default" (an instance without joints offers nothing).
std::vector<HookPoint> hookPoints(const TemplateManifest& manifest, const model::TemplateInstance& instance);

} // namespace rs::templates
