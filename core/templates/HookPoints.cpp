#include "templates/HookPoints.h"

#include "templates/Structure.h"

namespace rs::templates {

std::vector<HookPoint> hookPoints(const TemplateManifest& manifest, const model::TemplateInstance& instance)
{
    std::vector<HookPoint> out;
    StructureResolver resolver(manifest, instance);
    for (const UiHook& hook : manifest.hooks) {
        auto joints = resolver.address(hook.structure);
        if (!joints)
            continue;
        if (joints->size() == 1)
            out.push_back({hook.label, joints->front()});
        else
            for (std::size_t i = 0; i < joints->size(); ++i)
                out.push_back({hook.label + "[" + std::to_string(i) + "]", (*joints)[i]});
    }
    if (out.empty() && !instance.joints.empty()) // every joint is a hook; offer the root at least
        out.push_back({"default", instance.joints.front().id});
    return out;
}

} // namespace rs::templates
