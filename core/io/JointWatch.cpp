#include "io/JointWatch.h"

#include "model/Skeleton.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <variant>

namespace rs::io {

namespace {

Mat3 unitAxes(Mat3 m)
{
    for (int c = 0; c < 3; ++c)
        m[c] = glm::length(m[c]) > 1e-12 ? glm::normalize(m[c]) : m[c];
    return m;
}

bool descends(const model::Rig& rig, model::RigNodeIndex node, model::RigNodeIndex ancestor)
{
    for (; node != model::kNoNode; node = rig.nodes[node].parent)
        if (node == ancestor)
            return true;
    return false;
}

} // namespace

JointWatch::JointWatch(const model::Rig& rig)
{
    const auto skeleton = model::extractSkeleton(rig);
    if (!skeleton)
        return;
    Vec3 low(1e300), high(-1e300);
    for (const auto& j : skeleton->joints)
        if (j.node != model::kNoNode) {
            m_nodes.push_back(j.node);
            m_parents.push_back(j.parent < 0 ? model::kNoNode : skeleton->joints[std::size_t(j.parent)].node);
            low = glm::min(low, translationOf(j.bindWorld));
            high = glm::max(high, translationOf(j.bindWorld));
        }
    if (!m_nodes.empty())
        m_size = std::max(glm::length(high - low), 1e-3);
    for (const auto& j : skeleton->joints) {
        const Vec3 rest = translationOf(j.bindLocal);
        if (j.parent >= 0 && j.node != model::kNoNode && glm::length(rest) > 1e-3 &&
            skeleton->joints[std::size_t(j.parent)].node != model::kNoNode)
            m_offsets.push_back({j.node, skeleton->joints[std::size_t(j.parent)].node, glm::normalize(rest), glm::length(rest)});
    }
}

std::vector<eval::Affine> JointWatch::positions(const eval::EvalState& state) const
{
    std::vector<eval::Affine> out;
    for (auto node : m_nodes)
        out.push_back(state.world[node]);
    return out;
}

std::vector<Mat3> JointWatch::rotations(const eval::EvalState& state) const
{
    std::vector<Mat3> out;
    for (std::size_t j = 0; j < m_nodes.size(); ++j) {
        const Mat3 world = unitAxes(state.world[m_nodes[j]].linear);
        out.push_back(m_parents[j] == model::kNoNode ? world : glm::transpose(unitAxes(state.world[m_parents[j]].linear)) * world);
    }
    return out;
}

int JointWatch::folds(const eval::EvalState& state, double share) const
{
    int folded = 0;
    for (const auto& o : m_offsets) {
        const eval::Affine& parent = state.world[o.parent];
        const Vec3 local = glm::inverse(parent.linear) * (state.world[o.node].translation - parent.translation);
        if (glm::dot(local, o.restDirection) < share * o.restLength)
            ++folded;
    }
    return folded;
}

std::vector<double> aimReaches(const model::Rig& rig)
{
    std::vector<double> reach(rig.nodes.size(), 0.0);
    for (const auto& c : rig.constraints) {
        if (!std::holds_alternative<model::AimConstraint>(c.settings) || c.targets.empty() || c.driven.empty())
            continue;
        model::RigNodeIndex carrier = c.targets[0];
        while (carrier != model::kNoNode && rig.nodes[carrier].kind != model::RigNodeKind::Controller)
            carrier = rig.nodes[carrier].parent;
        if (carrier == model::kNoNode || descends(rig, c.driven[0], carrier))
            continue;
        reach[carrier] = std::max(reach[carrier], glm::length(translationOf(rig.nodes[carrier].worldMatrix) -
                                                              translationOf(rig.nodes[c.driven[0]].worldMatrix)));
    }
    return reach;
}

} // namespace rs::io
