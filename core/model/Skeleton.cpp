#include "model/Skeleton.h"

namespace rs::model {

Result<Skeleton> extractSkeleton(const Rig& rig)
{
    std::vector<RigNodeIndex> roots;
    for (RigNodeIndex i : rig.virtualRoots("skin"))
        if (rig.nodes[i].kind == RigNodeKind::Joint)
            roots.push_back(i);
    if (roots.empty())
        return Result<Skeleton>::failure(makeError({}, "the rig has no skin joints to export"));
    if (roots.size() > 1) {
        std::string list;
        for (RigNodeIndex r : roots)
            list += (list.empty() ? "" : ", ") + rig.nodes[r].name + " (" + rig.nodes[r].path + ")";
        return Result<Skeleton>::failure(makeError({}, "the skin hierarchy has " + std::to_string(roots.size()) +
                                                           " roots, an export skeleton needs one: " + list));
    }
    Skeleton skeleton;
    const auto childTable = rig.virtualChildTable();
    // Depth-first from the root; children in build order, so the output is stable.
    std::vector<std::pair<RigNodeIndex, int>> stack{{roots.front(), -1}};
    while (!stack.empty()) {
        auto [node, parent] = stack.back();
        stack.pop_back();
        const RigNode& n = rig.nodes[node];
        SkeletonJoint joint;
        joint.name = n.name;
        joint.parent = parent;
        joint.node = node;
        joint.bindWorld = n.worldMatrix;
        joint.bindLocal = parent < 0 ? n.worldMatrix : glm::inverse(skeleton.joints[std::size_t(parent)].bindWorld) * n.worldMatrix;
        const int index = static_cast<int>(skeleton.joints.size());
        skeleton.joints.push_back(joint);
        const auto& children = childTable[node];
        for (auto it = children.rbegin(); it != children.rend(); ++it)
            if (rig.nodes[*it].kind == RigNodeKind::Joint)
                stack.emplace_back(*it, index);
    }
    return skeleton;
}

} // namespace rs::model
