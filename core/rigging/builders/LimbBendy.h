#pragma once
// Bendy limb segments (option `bendy` of arm.limb, leg.limb and quad.leg):
// a bend control at the middle of the upper and lower segments and a tweak
// control at the elbow or knee between them. The segments' twist skin joints
// then ride a curve through the segment's start, its bend control and its
// end instead of the straight bone (model::TwistConstraint's bendy curve):
// moving a bend control bows its segment, moving the tweak moves the bend
// point both segments share (the middle of both follows). The tangents at
// the elbow never open wider than at rest (a limb built straight stays
// smooth there) and turn with the tweak, which is oriented halfway between
// the two bones. The controls ride the blend chain, so they are shown in IK
// and FK.
// A quadruped hind leg bends its upper two segments (the cannon has no twist
// joints). Everything is in authored space, so a mirrored branch gets the
// mirror image.
#include "rigging/BuildContext.h"

#include <vector>

namespace rs::rigging::limb {

struct BendControls {
    // Per segment (0 upper, 1 lower): what its twist joints' curve reads,
    // model::TwistConstraint's six bend targets. Empty when `bendy` is off
    // or the instance has no skin joints (nothing would bend).
    std::vector<std::vector<model::RigNodeIndex>> curveTargets;
    bool isOn() const { return !curveTargets.empty(); }
};

// Made once the blend chain exists: `blend` the blend joints (limb1..), their
// rest `frames` at the guide `points`, `limbRoot` the limb's group.
BendControls addBendControls(BuildContext& ctx, const std::vector<Vec3>& points, const std::vector<Mat4>& frames,
                             const std::vector<model::JointId>& guides, const std::vector<model::RigNodeIndex>& blend,
                             model::RigNodeIndex limbRoot);

} // namespace rs::rigging::limb
