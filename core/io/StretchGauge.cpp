#include "io/StretchGauge.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <variant>

namespace rs::io {

StretchGauge::StretchGauge(const model::Rig& rig, const eval::RigProgram& program)
{
    const auto& layout = program.channels();
    // Deform joints: the skin hierarchy's distance to the parent joint.
    for (model::RigNodeIndex i = 0; i < rig.nodes.size(); ++i) {
        const auto& node = rig.nodes[i];
        if (node.kind != model::RigNodeKind::Joint || node.domain() != "skin" || node.virtualParent == model::kNoNode)
            continue;
        const double rest = glm::length(program.restWorld(i).translation - program.restWorld(node.virtualParent).translation);
        if (rest >= 1e-4)
            m_bones.push_back({i, node.virtualParent, rest});
    }
    // IK goals: within the chain's reach while the chain is blended in.
    for (const auto& c : rig.constraints) {
        if (!std::holds_alternative<model::IkConstraint>(c.settings) || c.driven.size() < 2 || c.targets.empty())
            continue;
        Reach r{c.targets[0], c.driven.front(), {}, 0.0, -1};
        for (std::size_t k = 1; k < c.driven.size(); ++k)
            r.length += glm::length(program.restWorld(c.driven[k]).translation - program.restWorld(c.driven[k - 1]).translation);
        // The goal: where the effector asks the chain's end to be (its rest offset kept).
        r.endInEffector = program.restWorld(c.targets[0]).inverse().apply(program.restWorld(c.driven.back()).translation);
        for (const auto& b : rig.constraints)
            if (const auto* blend = std::get_if<model::BlendConstraint>(&b.settings))
                if (b.targets.size() == 2 && std::find(c.driven.begin(), c.driven.end(), b.targets[1]) != c.driven.end())
                    if (auto w = layout.find(blend->weight))
                        r.weight = *w;
        if (r.length >= 1e-6)
            m_reaches.push_back(r);
    }
}


double StretchGauge::measure(const eval::Pose& pose, const eval::EvalState& state) const
{
    double worst = -1.0;
    for (const auto& b : m_bones)
        worst = std::max(worst, glm::length(state.world[b.node].translation - state.world[b.parent].translation) / b.rest - 1.0);
    for (const auto& r : m_reaches) {
        if (r.weight >= 0 && pose[std::size_t(r.weight)] <= 1e-6)
            continue;
        const Vec3 goal = state.world[r.effector].apply(r.endInEffector);
        worst = std::max(worst, glm::length(goal - state.world[r.root].translation) / r.length - 1.0 + kReachMargin);
    }
    return worst;
}


} // namespace rs::io
