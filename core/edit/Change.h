#pragma once
// A typed change event: what an edit (or its undo) changed, so views refresh
// only that. Commands say what they change; the session adds what follows from
// it (a rebuilt rig, a new evaluation, the selection).
#include "base/Identity.h"

#include <cstdint>
#include <vector>

namespace rs::edit {

enum class ChangeKind : std::uint32_t {
    Document = 1u << 0,   // replaced wholesale (open, new, recover): everything
    Instances = 1u << 1,  // instances added, removed, re-hung or renamed
    Joints = 1u << 2,     // guide joint transforms
    Options = 1u << 3,    // option values (a guide parameter regenerates joints: Joints too)
    Shapes = 1u << 4,     // controller shape overrides
    Names = 1u << 5,      // name overrides
    Pose = 1u << 6,       // the test pose
    Overrides = 1u << 7,  // override records other than shapes and the pose (defaults, limits, locks, post, names)
    History = 1u << 8,    // the undo stack or its clean state
    Selection = 1u << 9,  // session: the selection
    Rig = 1u << 10,       // session: the rig was rebuilt (node indices may have moved)
    Evaluation = 1u << 11, // session: the posed rig was evaluated again
    Templates = 1u << 12, // session: the template library was reloaded
    Mode = 1u << 13,      // session: guide / rig mode, CV mode
    Models = 1u << 14,    // the character's models (added, removed, reloaded)
    Weights = 1u << 15,   // skin weights (the bindings named in Change::bindings; all when empty)
    Mods = 1u << 16,      // the guide's mods (added, edited, removed)
    Build = 1u << 17,     // the guide's build settings (restore toggles, cleanup)
};

constexpr std::uint32_t operator|(ChangeKind a, ChangeKind b) { return std::uint32_t(a) | std::uint32_t(b); }
constexpr std::uint32_t operator|(std::uint32_t a, ChangeKind b) { return a | std::uint32_t(b); }

struct Change {
    std::uint32_t kinds = 0;
    std::vector<InstanceId> instances; // the instances touched; empty with Document or when unknown
    std::vector<JointId> joints;       // the guide joints moved (Joints)
    bool preview = false;              // inside an open transaction (a drag in progress)
    std::vector<std::size_t> bindings; // Weights: the changed records of GuideDocument::bindings; empty: all

    static Change of(std::uint32_t kinds, std::vector<InstanceId> instances = {}, std::vector<JointId> joints = {})
    {
        return {kinds, std::move(instances), std::move(joints), false, {}};
    }
    static Change of(ChangeKind kind, std::vector<InstanceId> instances = {}, std::vector<JointId> joints = {})
    {
        return of(std::uint32_t(kind), std::move(instances), std::move(joints));
    }
    bool has(ChangeKind kind) const { return (kinds & std::uint32_t(kind)) != 0; }
    bool hasAny(std::uint32_t mask) const { return (kinds & mask) != 0; }
    bool empty() const { return kinds == 0; }
    // Anything a rig build depends on (the pose and the reference model are not).
    bool touchesGuide() const;
    void add(ChangeKind kind) { kinds |= std::uint32_t(kind); }
    void merge(const Change& other);
};

} // namespace rs::edit
