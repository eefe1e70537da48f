#pragma once
// An incremental rebuild must make exactly what a full build makes: builds
// `guide` with `cache` and without one, and expects the same rig dump and the
// same diagnostics (`what` names the step in a failure).
#include "core/TestSupport.h"
#include "io/RigDump.h"
#include "rigging/BuildCache.h"
#include "rigging/RigBuilder.h"

#include <string>

namespace rs::test {

inline rigging::BuildCache::Stats buildAndCompare(const model::GuideDocument& guide, rigging::BuildCache& cache,
                                                  const std::string& what,
                                                  const rigging::BuilderRegistry& builders = rigging::BuilderRegistry::builtin())
{
    const model::Rig incremental = rigging::buildRig(guide, builtinTemplates(), builders, {}, &cache);
    const model::Rig full = rigging::buildRig(guide, builtinTemplates(), builders);
    EXPECT_EQ(io::writeRigDump(incremental), io::writeRigDump(full)) << what;
    EXPECT_EQ(formatAll(incremental.diagnostics), formatAll(full.diagnostics)) << what;
    return cache.lastBuild();
}

} // namespace rs::test
