#pragma once
// What the range-of-motion planner (internal to io/RangeOfMotion.cpp) reads
// off a rig besides its channels: the FK/IK switches (the blend constraints
// sharing one weight channel, with the controllers on each side and the IK
// side's bend plane at rest) and the custom channels that drive motion.
// Found once per rig, from its constraints; a rig without any has none.
#include "eval/RigProgram.h"
#include "model/Rig.h"

#include <vector>

namespace rs::io {

// An FK/IK switch: the blend constraints that share one weight channel.
struct FkIkSwitch {
    int weight = -1;
    double fk = 0.0, ik = 1.0;                    // the channel's FK and IK values
    std::vector<const model::RigConstraint*> blends;
    std::vector<model::RigNodeIndex> fkControls;   // controllers on the FK side
    std::vector<model::RigNodeIndex> ikControls;   // controllers the IK side's solver reads
    Vec3 bendNormal{0.0};                          // world, rest; zero when the IK side is no limb IK
};

// The rig's switches, by weight channel (an IK side is any IK or spline
// solver whose driven nodes a blend reads).
std::vector<FkIkSwitch> switchesOf(const model::Rig& rig, const eval::ChannelLayout& layout);

// Channels that drive motion (a drive's value): the custom channels worth exercising.
std::vector<int> drivingChannels(const model::Rig& rig, const eval::ChannelLayout& layout);

} // namespace rs::io
