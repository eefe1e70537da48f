#pragma once
// A limb's twist options beyond the twist joints themselves (LimbParts.h),
// both Mikan's (arm.limb, leg.limb, quad.leg):
//
// `advanced_twist`: a correction rig for twist artifacts, as attributes on the
// switch control (degrees unless said): `twist_start` rolls the upper
// segment's start (shoulder, hip), `twist_mid` the middle joint (elbow, knee),
// `twist_end` the lower segment's end (wrist, ankle: the lower segment's end
// for a quad leg's hock), each about the bone, spread linearly over the twist
// joints of the segments it bounds: a twist joint at fraction f of the upper
// segment rolls by (1 - f) twist_start + f twist_mid, one of the lower segment
// by (1 - f) twist_mid + f twist_end, and the segments' start skin joints
// (upper arm, forearm) roll by the whole twist_start and twist_mid. `twist_bias`
// (-1..1) shapes how each twist joint shares its segment's own twist: f^(2^bias)
// of it instead of f (0 linear; 1 leaves more to the end, -1 moves it towards
// the start). At the defaults (all 0) nothing moves.
//
// `add_chains`: a list of names; per name an extra chain of skin joints along
// each segment, one per twist joint, each under its own tweak controller
// (translate, rotate, scale) that hangs on the twist joint: at rest they sit
// on the twist joints, they follow them (bendy curves included) and a tweak's
// offset moves its joint alone (muscle bulges, sleeves). Tags "ctrls.up.<name>.<t>",
// "skin.up.<name>.<t>" (and "dn"); names from the token "<name>_up" ("<name>_dn").
// Everything is in authored space, so a mirrored branch gets the mirror image.
#include "rigging/BuildContext.h"
#include "rigging/builders/LimbParts.h"

#include <optional>
#include <string>
#include <vector>

namespace rs::rigging::limb {

struct AdvancedTwist {
    std::optional<model::AttributeRef> start, mid, end, bias; // none when advanced_twist is off
    bool isOn() const { return bias.has_value(); }
};
// Made before the twist joints: the attributes on `settings` (the switch
// control), when the option is on.
AdvancedTwist addAdvancedTwistAttributes(BuildContext& ctx, model::RigNodeIndex settings);
// Made after them: the rolls, as drives on the twist joints and on `skin`'s
// upper and lower segment joints (skin[0], skin[1]).
void addAdvancedTwistRolls(BuildContext& ctx, const AdvancedTwist& twist, const TwistJoints& joints,
                           const std::vector<model::RigNodeIndex>& skin);

// The names of `add_chains` (checked: templates::addChainsProblems, each an
// error naming the option), none when the option is absent or bad.
std::vector<std::string> twistChainNames(const BuildContext& ctx);
// Made after the twist joints: every chain's tweak controls and skin joints;
// `guides` the limb's guide joints (the segments' sources).
void addTwistChains(BuildContext& ctx, const TwistJoints& joints, const std::vector<model::JointId>& guides);

} // namespace rs::rigging::limb
