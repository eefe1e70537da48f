// The FK/IK switches and driving channels of a rig (RigSwitches.h).
#include "io/RigSwitches.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <map>
#include <variant>

namespace rs::io {

namespace {

// The controller a node follows: itself or its nearest controller ancestor.
model::RigNodeIndex controllerOf(const model::Rig& rig, model::RigNodeIndex node)
{
    while (node != model::kNoNode && rig.nodes[node].kind != model::RigNodeKind::Controller)
        node = rig.nodes[node].parent;
    return node;
}

void addOnce(std::vector<model::RigNodeIndex>& list, model::RigNodeIndex node)
{
    if (node != model::kNoNode && std::find(list.begin(), list.end(), node) == list.end())
        list.push_back(node);
}

} // namespace

std::vector<FkIkSwitch> switchesOf(const model::Rig& rig, const eval::ChannelLayout& layout)
{
    std::map<int, FkIkSwitch> byWeight;
    for (const auto& c : rig.constraints) {
        const auto* blend = std::get_if<model::BlendConstraint>(&c.settings);
        const auto weight = blend ? layout.find(blend->weight) : std::nullopt;
        if (!weight || c.targets.size() != 2)
            continue;
        FkIkSwitch& s = byWeight[*weight];
        s.weight = *weight;
        s.fk = layout[std::size_t(*weight)].limited ? layout[std::size_t(*weight)].min : 0.0;
        s.ik = layout[std::size_t(*weight)].limited ? layout[std::size_t(*weight)].max : 1.0;
        s.blends.push_back(&c);
        if (rig.nodes[c.targets[0]].kind == model::RigNodeKind::Controller)
            addOnce(s.fkControls, c.targets[0]);
    }
    for (auto& [weight, s] : byWeight)
        for (const auto& c : rig.constraints) {
            const bool solver = std::holds_alternative<model::IkConstraint>(c.settings) ||
                                std::holds_alternative<model::SplineConstraint>(c.settings);
            if (!solver)
                continue;
            const bool feeds = std::any_of(s.blends.begin(), s.blends.end(), [&](const model::RigConstraint* b) {
                return std::find(c.driven.begin(), c.driven.end(), b->targets[1]) != c.driven.end();
            });
            if (!feeds)
                continue;
            for (auto target : c.targets)
                addOnce(s.ikControls, controllerOf(rig, target));
            if (std::holds_alternative<model::IkConstraint>(c.settings) && c.driven.size() >= 3) {
                const Vec3 a = translationOf(rig.nodes[c.driven[0]].worldMatrix);
                const Vec3 b = translationOf(rig.nodes[c.driven[1]].worldMatrix);
                const Vec3 e = translationOf(rig.nodes[c.driven[2]].worldMatrix);
                const Vec3 n = glm::cross(b - a, e - b);
                if (glm::length(n) > 1e-9)
                    s.bendNormal = glm::normalize(n);
            }
        }
    std::vector<FkIkSwitch> out;
    for (auto& [weight, s] : byWeight)
        out.push_back(std::move(s));
    return out;
}

// Channels that drive motion (a drive's value): the custom channels worth exercising.
std::vector<int> drivingChannels(const model::Rig& rig, const eval::ChannelLayout& layout)
{
    std::vector<int> out;
    for (const auto& c : rig.constraints)
        if (const auto* drive = std::get_if<model::DriveConstraint>(&c.settings))
            if (auto channel = layout.find(drive->value); channel && !layout[std::size_t(*channel)].locked)
                if (std::find(out.begin(), out.end(), *channel) == out.end())
                    out.push_back(*channel);
    return out;
}

} // namespace rs::io
