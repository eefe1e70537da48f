#include "rigging/TemplateBuilder.h"

#include "rigging/builders/Builders.h"

namespace rs::rigging {

namespace {
constexpr const char* kFallbackBuilder = "core.joints";
}

void BuilderRegistry::add(const std::string& templateId, std::unique_ptr<TemplateBuilder> builder)
{
    m_builders[templateId] = std::move(builder);
}

const TemplateBuilder* BuilderRegistry::find(const std::string& templateId) const
{
    auto it = m_builders.find(templateId);
    return it == m_builders.end() ? nullptr : it->second.get();
}

const TemplateBuilder& BuilderRegistry::resolve(const templates::TemplateManifest& manifest, Diagnostics& diagnostics) const
{
    if (const TemplateBuilder* own = find(manifest.id))
        return *own;
    if (!manifest.base.empty()) {
        if (const TemplateBuilder* base = find(manifest.base))
            return *base;
        diagnostics.push_back(makeWarning({manifest.file, 0, 0}, "base '" + manifest.base + "' has no builder; using the generic joint-chain builder"));
    } else {
        diagnostics.push_back(makeWarning({manifest.file, 0, 0}, "no builder for " + manifest.id + "; using the generic joint-chain builder"));
    }
    if (const TemplateBuilder* fallback = find(kFallbackBuilder))
        return *fallback;
    return *builtin().find(kFallbackBuilder); // a registry of a few builders (tests, plugins) still builds the rest
}

const BuilderRegistry& BuilderRegistry::builtin()
{
    static const BuilderRegistry registry = [] {
        BuilderRegistry r;
        r.add("world.character", makeWorldBuilder());
        r.add("world.prop", makeWorldBuilder());
        r.add("world.default", makeWorldDefaultBuilder());
        r.add("wheel.legacy", makeWheelBuilder());
        r.add("rig.slide", makeSlideBuilder());
        r.add("util.camera", makeCameraBuilder());
        r.add("core.xform", makeXformBuilder());
        r.add("core.bones", makeBoneChainBuilder());
        r.add("spine.torso", makeSpineBuilder());
        r.add("neck.head", makeNeckBuilder());
        r.add("arm.limb", makeLimbBuilder(LimbKind::Arm));
        r.add("leg.limb", makeLimbBuilder(LimbKind::Leg));
        r.add("quad.leg", makeLimbBuilder(LimbKind::Quad));
        r.add("digit.finger", makeDigitBuilder());
        r.add("digit.hand", makeHandBuilder());
        r.add("rig.spline", makeSplineBuilder());
        r.add("face.jaw", makeJawBuilder());
        r.add("face.eye", makeEyeBuilder());
        r.add("face.brow", makeBrowBuilder());
        r.add("face.mouth", makeMouthBuilder());
        r.add(kFallbackBuilder, makeJointChainBuilder());
        return r;
    }();
    return registry;
}

} // namespace rs::rigging
