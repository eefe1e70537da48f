// The mirrored branch copies' curves and twins (buildRig runs it after the
// shape overrides, RigAssembly.h): each copy's nodes paired with their twins
// on the authored side for pose mirroring, and its controllers given their
// twin's curves, reflected, and on a flipped branch with the hue turned.
#include "rigging/RigAssembly.h"
#include "templates/Color.h"

namespace rs::rigging {

// Pairs every node of a mirrored branch copy with its twin, and a mirrored
// branch copy shows its twin's curves reflected (negative scale in the
// controller's space, which is M * p for W' = M W M; none for W' = M W) and, on a flipped branch,
// with the hue turned 120 degrees, as Mikan does.
void mirrorBranchShapes(RigAssembly& a)
{
    const NodesByInstance byInstance = indexNodesByInstance(a.rig);
    for (const InstanceRecord& r : a.records) {
        const BranchCopy& copy = a.copyOf(r.instance->id);
        if (copy.mirror == Mat4(1.0))
            continue;
        const std::string twinBranch = a.copyOf(copy.twin).branch();
        const Mat3 m(copy.mirror);
        auto ownNodes = byInstance.find(copy.key());
        if (ownNodes == byInstance.end())
            continue;
        int plane = -1, reflections = 0;
        for (int axis = 0; axis < 3; ++axis)
            if (copy.mirror[axis][axis] < 0.0) { plane = axis; ++reflections; }
        for (model::RigNodeIndex index : ownNodes->second) {
            auto& node = a.rig.nodes[index];
            auto source = a.rig.find(NodeKey{node.key.instance, twinBranch, node.key.tag});
            if (!source)
                continue;
            if (reflections == 1) { // pose mirroring pairs the two sides
                node.twin = *source;
                node.mirrorPlane = plane;
                a.rig.nodes[*source].twin = index;
                a.rig.nodes[*source].mirrorPlane = plane;
            }
            if (node.kind != model::RigNodeKind::Controller)
                continue;
            const model::RigNode& from = a.rig.nodes[*source];
            node.shape = from.shape;
            node.curves = from.curves;
            node.shapeFromTwin = true;
            // A flip_orient control (builders/ControlNodes.h) is itself the
            // reflection M W of its twin: its curves need no reflecting.
            const bool reflect = (glm::determinant(Mat3(node.worldMatrix)) < 0.0) == (glm::determinant(Mat3(from.worldMatrix)) < 0.0);
            for (auto& curve : node.curves) {
                if (reflect)
                    curve.transform(Mat4(m));
                if (copy.flip) {
                    const auto c = templates::shiftHue({curve.color.x, curve.color.y, curve.color.z}, 120.0);
                    curve.color = Vec3(c.r, c.g, c.b);
                }
            }
        }
    }
}

} // namespace rs::rigging
