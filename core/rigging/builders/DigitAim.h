#pragma once
// digit.finger's aim rig (Mikan's digit.legacy `target_weights` and
// `target_parent`): a target control at the finger's tip, under the node
// `target_parent` names, and on each phalanx after the base an aim
// (model::AimConstraint) of its offset group towards where the next joint sits
// under the target, weighted by an `aim` attribute (0..1) on the phalanx's
// controller whose default is the phalanx's entry of `target_weights`. The
// aim's up is the phalanx's bend axis as its parent carries it, so the aim
// only bends the finger where its FK pose would not: at weight 0 the rig is
// the FK rig. Curl, fist and spread land after the aim (on the pose group, or
// on the offset after the aim in constraint order), so they still turn the
// phalanges from where the aim left them. Frames are in authored space.
#include "rigging/builders/ControlNodes.h"

#include <optional>
#include <string>
#include <vector>

namespace rs::rigging {

struct DigitAimOptions {
    std::vector<double> weights; // one per aimed phalanx; empty: no aim rig
    std::string space;           // target_parent: a named space of the rig; empty: the finger's hook
};

// Reads target_weights and target_parent for `aimed` phalanges. Reports every
// problem as an error naming its option (it lands on the guide's line) and
// returns nullopt: a list that is no flow list, an item that is no number in
// 0..1, a count that is neither one nor `aimed`, a target_parent that names
// no node ("*::hooks.digits" or hook, "*::space.NAME" or NAME).
std::optional<DigitAimOptions> readDigitAim(const BuildContext& ctx, std::size_t aimed);

// The chain of one digit as its builder made it: one control per phalanx
// (the base first when there is one), the guide joints and their positions
// (the tip's last), the frames per joint and the local axes a phalanx aims
// along (at the next joint) and curls about.
struct DigitChain {
    const std::vector<ControlStack>& controls;
    const std::vector<model::JointId>& joints;
    const std::vector<Vec3>& points;
    const std::vector<Mat4>& frames;
    Vec3 aimAxis;
    Vec3 curlAxis;
};

// Builds the aim rig on the phalanges from `first` (nothing when the weights
// are empty). Call it before any drive lands on the controls' offsets.
void addDigitAim(BuildContext& ctx, const DigitAimOptions& options, const DigitChain& chain, std::size_t first);

} // namespace rs::rigging
