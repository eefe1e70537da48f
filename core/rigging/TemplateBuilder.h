#pragma once
// The C++ logic of a template, registered under its template id ("core.joints").
// Guide phase: createGuide() proposes the default guide joints of a new instance.
// Rig phase (as in Rigify's generator): gather() inspects the guide without
// creating anything; generate() then creates the instance's rig nodes through
// its BuildContext. Builders never touch nodes of other instances, except to
// parent under the hook node they are given.
#include "rigging/BuildContext.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rs::rigging {

// One proposed guide joint; `parent` indexes the returned list (-1: the root).
// The root's transform is local to the joint the instance hangs under.
struct GuideJointSpec {
    int parent = -1;
    Transform local;
    std::vector<std::string> tags;
    std::string name; // optional; "_name" marks a helper outside the chain
};

class TemplateBuilder {
public:
    virtual ~TemplateBuilder() = default;
    // `guideValues` holds every `guides` parameter (defaults merged with overrides).
    virtual std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest& manifest,
                                                    const std::map<std::string, Value>& guideValues) const = 0;
    // Read-only checks before anything is generated; report through ctx and
    // return false to skip the instance (its children then hang on the nearest
    // built ancestor).
    virtual bool gather(const BuildContext& ctx) const { return true; }
    // Creates the instance's nodes, hooks, attributes and its own constraints.
    virtual void generate(BuildContext& ctx) const = 0;
    // Runs after every instance has generated, root to leaf: wiring that needs
    // other instances' nodes (space switches). A failure drops only what it added.
    virtual void configure(BuildContext& ctx) const {}
};

class BuilderRegistry {
public:
    void add(const std::string& templateId, std::unique_ptr<TemplateBuilder> builder);
    const TemplateBuilder* find(const std::string& templateId) const;
    // The builder for a manifest: its own id, else its `base`, else the generic
    // joint-chain builder (with a warning in `diagnostics`).
    const TemplateBuilder& resolve(const templates::TemplateManifest& manifest, Diagnostics& diagnostics) const;

    // world.character, world.prop, core.joints...
    static const BuilderRegistry& builtin();

private:
    std::map<std::string, std::unique_ptr<TemplateBuilder>> m_builders;
};

} // namespace rs::rigging
