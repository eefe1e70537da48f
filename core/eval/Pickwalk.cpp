#include "eval/Pickwalk.h"

#include <algorithm>

namespace rs::eval {

namespace {

bool isWalkable(const model::Rig& rig, model::RigNodeIndex i, const std::vector<std::uint8_t>* shown)
{
    const model::RigNode& node = rig.nodes[i];
    const bool visible = !shown || i >= shown->size() || (*shown)[i] != 0;
    return node.kind == model::RigNodeKind::Controller && !node.hidden && node.isInVirtualHierarchy() && visible;
}

template <class Id>
Id sibling(const std::vector<Id>& siblings, Id from, int step)
{
    const auto it = std::find(siblings.begin(), siblings.end(), from);
    if (it == siblings.end() || siblings.empty())
        return from;
    const auto n = static_cast<long>(siblings.size());
    const long index = ((it - siblings.begin()) + step + n) % n;
    return siblings[static_cast<std::size_t>(index)];
}

} // namespace

model::RigNodeIndex pickwalk(const model::Rig& rig, model::RigNodeIndex from, WalkDirection direction,
                             const std::vector<std::uint8_t>* shown)
{
    if (from >= rig.nodes.size())
        return from;
    const model::RigNode& node = rig.nodes[from];
    auto walkable = [&](std::vector<model::RigNodeIndex> nodes) {
        nodes.erase(std::remove_if(nodes.begin(), nodes.end(), [&](auto i) { return !isWalkable(rig, i, shown); }), nodes.end());
        return nodes;
    };
    switch (direction) {
    case WalkDirection::Up:
        return node.virtualParent != model::kNoNode && isWalkable(rig, node.virtualParent, shown) ? node.virtualParent : from;
    case WalkDirection::Down: {
        const auto children = walkable(rig.virtualChildren(from));
        return children.empty() ? from : children.front();
    }
    case WalkDirection::Left:
    case WalkDirection::Right: {
        const auto siblings = walkable(node.virtualParent == model::kNoNode ? rig.virtualRoots(node.domain())
                                                                             : rig.virtualChildren(node.virtualParent));
        return sibling(siblings, from, direction == WalkDirection::Right ? 1 : -1);
    }
    case WalkDirection::Mirror:
        return node.twin != model::kNoNode && (!shown || node.twin >= shown->size() || (*shown)[node.twin]) ? node.twin : from;
    }
    return from;
}

model::InstanceId pickwalk(const model::GuideDocument& guide, model::InstanceId from, WalkDirection direction)
{
    const model::TemplateInstance* instance = guide.instance(from);
    if (!instance)
        return from;
    switch (direction) {
    case WalkDirection::Up:
        return instance->parent != model::kNoId ? instance->parent : from;
    case WalkDirection::Down: {
        const auto children = guide.childInstances(from);
        return children.empty() ? from : children.front();
    }
    case WalkDirection::Left:
    case WalkDirection::Right: {
        std::vector<model::InstanceId> siblings;
        for (const auto& i : guide.instances())
            if (i.parent == instance->parent)
                siblings.push_back(i.id);
        return sibling(siblings, from, direction == WalkDirection::Right ? 1 : -1);
    }
    case WalkDirection::Mirror: {
        const std::string name = model::mirroredName(instance->name);
        const auto* twin = name.empty() ? nullptr : guide.instanceNamed(name);
        return twin ? twin->id : from;
    }
    }
    return from;
}

} // namespace rs::eval
