#pragma once
// The bones automatic weights bind to: one per skin joint of a rig, from the
// joint's bind position to each of its skin children (a leaf joint continues
// its parent's direction for half the parent's length). A root with a single
// skin child is where the rig stands (the world template's root on the ground),
// not a bone of the body: it is its head point only. A vertex's distance to a
// bone is its distance to the nearest of those segments (or to the point).
#include "base/Result.h"
#include "model/Rig.h"

#include <vector>

namespace rs::skin {

struct SkinBone {
    NodeKey key;                    // the skin joint
    model::RigNodeIndex node = model::kNoNode;
    int parent = -1;                // the parent skin joint's bone, -1 for the root
    Vec3 head{0.0};
    std::vector<Vec3> tails;        // segment ends; none: the bone is its head point
};

// Fails when the rig has no skin joint (or no single skin root).
Result<std::vector<SkinBone>> skinBones(const model::Rig& rig);

// The point of `bone` nearest to `p`, and its distance.
Vec3 nearestPointOn(const SkinBone& bone, const Vec3& p);

} // namespace rs::skin
