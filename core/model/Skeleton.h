#pragma once
// The deform skeleton of a rig: its skin joints arranged by the skin virtual
// hierarchy, parents first, in bind (rest) pose. This is what exporters write.
#include "base/Result.h"
#include "model/Rig.h"

#include <string>
#include <vector>

namespace rs::model {

struct SkeletonJoint {
    std::string name;
    int parent = -1;        // index into Skeleton::joints; -1 for the root
    RigNodeIndex node = kNoNode;
    Mat4 bindWorld{1.0};    // metres, Y-up
    Mat4 bindLocal{1.0};    // relative to the parent joint
};

struct Skeleton {
    std::vector<SkeletonJoint> joints;
};

// Fails when the rig has no skin joints or when the skin hierarchy has more than
// one root (each root is named, so the rigger can see which template is loose).
Result<Skeleton> extractSkeleton(const Rig& rig);

} // namespace rs::model
