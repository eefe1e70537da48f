#pragma once
// Turns a guide into a rig. Stages: resolve every instance (manifest, builder,
// typed options) and let builders gather without creating anything; generate
// root to leaf (an instance that fails is rolled back, never half-built); apply
// controller shapes; build the virtual hierarchy per domain; check names.
// Deterministic: the same guide gives the same rig, node for node.
#include "base/Result.h"
#include "rigging/BuildCache.h"
#include "rigging/TemplateBuilder.h"
#include "model/Rig.h"
#include "templates/TemplateRegistry.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace rs::rigging {

model::Rig buildRig(const model::GuideDocument& guide, const templates::TemplateRegistry& templates,
                    const BuilderRegistry& builders = BuilderRegistry::builtin());

// Told how far a build is: the fraction done (0 to 1, never going back) and
// the stage ("gather", "generate arm.L", "configure", "finalize", "done").
using BuildProgress = std::function<void(double fraction, const std::string& stage)>;
model::Rig buildRig(const model::GuideDocument& guide, const templates::TemplateRegistry& templates,
                    const BuilderRegistry& builders, const BuildProgress& progress);
// The same, replaying from `cache` every instance copy whose inputs did not
// change since the cache's last build, and keeping what this build generates
// for the next (BuildCache.h). The rig is the same as without a cache.
model::Rig buildRig(const model::GuideDocument& guide, const templates::TemplateRegistry& templates,
                    const BuilderRegistry& builders, const BuildProgress& progress, BuildCache* cache);

// Defaults of `guides` and `opts` with the instance's overrides, coerced to the
// manifest types (an int given for a float is accepted). Mismatches are reported
// and fall back to the default.
std::map<std::string, Value> resolveOptions(const templates::TemplateManifest& manifest,
                                            const model::TemplateInstance& instance, Diagnostics& diagnostics);

// Guide phase: a new instance of `templateId` hanging under `parentJoint` (or at
// the top level with kNoId), with fresh ids and a unique name, ready for
// rs::edit::addInstance.
Result<model::TemplateInstance> makeInstance(const model::GuideDocument& guide,
                                             const templates::TemplateRegistry& templates,
                                             const std::string& templateId, model::JointId parentJoint,
                                             const BuilderRegistry& builders = BuilderRegistry::builtin());
// The same with option values given up front (guide parameters such as
// `number` shape the default joints); unknown options are refused.
Result<model::TemplateInstance> makeInstance(const model::GuideDocument& guide,
                                             const templates::TemplateRegistry& templates,
                                             const std::string& templateId, model::JointId parentJoint,
                                             const std::map<std::string, Value>& options,
                                             const BuilderRegistry& builders = BuilderRegistry::builtin());

// The instance `id` with its guide joints proposed again for `options` (a
// guide parameter such as `number` changed): joints that still exist keep
// their ids, rotations, scales and world positions (named or tagged joints
// match by name and tags, chain joints in order with the last kept last, so
// children hung on a chain's tip stay on it); new joints get fresh ids at the
// proposed places; name, parent, structure and name overrides are kept.
Result<model::TemplateInstance> regenerateGuide(const model::GuideDocument& guide,
                                                const templates::TemplateRegistry& templates, model::InstanceId id,
                                                const std::map<std::string, Value>& options,
                                                const BuilderRegistry& builders = BuilderRegistry::builtin());

} // namespace rs::rigging
