#include "eval/OffsetCarry.h"

#include <cmath>

namespace rs::eval {

bool readCarry(const model::CarryConstraint& s, const model::RigConstraint& rc, const model::Rig& rig, const ChannelLayout& channels,
               CompiledConstraint& c, Diagnostics& diagnostics)
{
    bool ok = true;
    if (s.carried.size() != rc.targets.size()) {
        diagnostics.push_back(makeError({}, "constraint '" + rc.path + "' carries " + std::to_string(s.carried.size()) +
                                                " nodes with " + std::to_string(rc.targets.size()) + " pivots (one pivot each)"));
        ok = false;
    }
    c.carried = s.carried;
    c.carriedChannels.clear();
    for (model::RigNodeIndex node : s.carried) {
        const int first = node < rig.nodes.size() ? channels.transformOf(node) : -1;
        if (first < 0) {
            const std::string what = node < rig.nodes.size() ? "node '" + rig.nodes[node].path + "' has no transform channels"
                                                              : "a carried node is not in the rig";
            diagnostics.push_back(makeError({}, "constraint '" + rc.path + "': " + what + " to carry"));
            ok = false;
        }
        c.carriedChannels.push_back(first);
    }
    return ok;
}

std::string prepareCarry(CompiledConstraint& c, const std::vector<Affine>& rest)
{
    if (c.targets.empty())
        return "carries nothing";
    c.carriedOffsets.clear();
    for (std::size_t k = 0; k < c.targets.size(); ++k) {
        const Affine& pivot = rest[c.targets[k]];
        if (std::abs(glm::determinant(pivot.linear)) < 1e-18)
            return "the rest frame of a pivot it carries about is degenerate";
        c.carriedOffsets.push_back(pivot.inverse() * rest[c.carried[k]]);
    }
    return {};
}

// Outermost first: D_0 (D_1 (... world)). Each D_k = F C F^-1 is applied as
// F (C (F^-1 x)): the carried node's animation about its current zero pose.
void solveCarry(const CompiledConstraint& c, const Pose& pose, std::vector<Affine>& world)
{
    Affine& driven = world[c.driven.front()];
    for (std::size_t k = c.targets.size(); k-- > 0;) {
        const double* v = pose.data() + c.carriedChannels[k];
        if (v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0 && v[3] == 0.0 && v[4] == 0.0 && v[5] == 0.0 && v[6] == 1.0 && v[7] == 1.0 &&
            v[8] == 1.0)
            continue; // at rest: no offset to carry
        const Affine channels = channelAffine(pose, c.carriedChannels[k]);
        const Affine pivot = world[c.targets[k]] * c.carriedOffsets[k];
        driven = pivot * (channels * (pivot.inverse() * driven));
    }
}

} // namespace rs::eval
