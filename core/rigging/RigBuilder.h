#pragma once
// Turns a guide into a rig. Stages: resolve every instance (manifest, builder,
// typed options) and let builders gather without creating anything; generate
// root to leaf (an instance that fails is rolled back, never half-built); apply
// controller shapes, then the guide's overrides (one stage: OverrideStage.cpp); build the virtual hierarchy per domain; check names.
// Deterministic: the same guide gives the same rig, node for node.
#include "base/Result.h"
#include "rigging/BuildCache.h"
#include "rigging/TemplateBuilder.h"
#include "model/Rig.h"
#include "templates/TemplateRegistry.h"

#include <functional>
#include <map>
#include <set>
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
// The same, restoring only the override kinds `restore` keeps on (the rest are
// built as the templates make them; their records stay in the guide); the
// overloads above restore what the guide's build settings say
// (guide.build.restore). The guide's cleanup setting applies to every overload
// (rigging/CleanupStage.h). The test pose is not part of the rig:
// `restoredPose` gives what a build restores.
model::Rig buildRig(const model::GuideDocument& guide, const templates::TemplateRegistry& templates,
                    const BuilderRegistry& builders, const BuildProgress& progress, BuildCache* cache,
                    const model::RestoreToggles& restore);
// The build's override stage on its own, for a rig already built from `guide`
// without overrides (tools, benchmarks): shape edits skip `mirroredCopies` (the
// build passes its mirrored branch copies), then `afterShapes` runs (the build
// mirrors the edited curves onto those copies), then channels, names and the
// post transform; orphans are reported in rig.diagnostics. Applying it twice
// applies shape transforms and the post transform twice.
void applyOverrides(model::Rig& rig, const model::GuideDocument& guide, const model::RestoreToggles& restore,
                    const std::set<CopyKey>& mirroredCopies = {}, const std::function<void()>& afterShapes = {});
// The test pose a build with `restore` starts from (empty with the pose kind off).
model::PoseValues restoredPose(const model::GuideDocument& guide, const model::RestoreToggles& restore);

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
