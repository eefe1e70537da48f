#pragma once
// What a live rebuild keeps from the previous build of the same guide: each
// instance copy's generated nodes, constraints, hooks and spaces, together
// with everything its builder read while generating them (its guide joints'
// world matrices, other instances' nodes, named spaces, its hook). The next
// build replays a copy whose instance, options and reads are all unchanged
// instead of generating it again, so dragging a hand's guide joint generates
// the hand and what hangs below it (and its mirrored copy), not the whole rig.
// Gathering, configuring and every finalize stage still run in full, so the
// result is exactly the rig a build without a cache makes, node for node
// (tests/core/IncrementalBuildTest.cpp proves it over every sample and edit).
//
// One cache serves one guide in one thread (the session owns one). It drops
// itself when the template library, the builders or the naming rules change.
#include "base/Result.h"
#include "eval/RigProgram.h"

#include <cstddef>
#include <memory>
#include <optional>

namespace rs::rigging {

class BuildCache {
public:
    BuildCache();
    ~BuildCache();
    BuildCache(BuildCache&&) noexcept;
    BuildCache& operator=(BuildCache&&) noexcept;

    void clear();

    // How the last build used the cache: instance copies replayed from it and
    // generated again (a miss, a changed input, or one that cannot be replayed).
    struct Stats {
        std::size_t replayed = 0;
        std::size_t generated = 0;
    };
    const Stats& lastBuild() const;

    // The last build's rig compiled for evaluation (its evaluation check
    // compiles it): the program, or why it does not compile. Taken once.
    std::optional<Result<eval::RigProgram>> takeProgram();

    struct Impl; // rigging/Fragment.h
    Impl& impl() { return *m_impl; }

private:
    std::unique_ptr<Impl> m_impl;
};

} // namespace rs::rigging
