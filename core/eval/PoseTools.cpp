#include "eval/PoseTools.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace rs::eval {

namespace {

const model::RigConstraint* limbIk(const model::Rig& rig, const CopyKey& instance)
{
    for (const auto& c : rig.constraints)
        if (c.kind() == model::ConstraintKind::Ik && c.key.copy() == instance)
            return &c;
    return nullptr;
}

// The FK/IK blends of a limb (blend joints), parents first (as the builder lists them).
std::vector<const model::RigConstraint*> limbBlends(const model::Rig& rig, const CopyKey& instance)
{
    std::vector<const model::RigConstraint*> out;
    for (const auto& c : rig.constraints)
        if (c.kind() == model::ConstraintKind::Blend && c.key.copy() == instance && c.targets.size() == 2 &&
            rig.nodes[c.driven.front()].kind == model::RigNodeKind::Joint) // not the auto-clavicle's groups
            out.push_back(&c);
    return out;
}

// The FK control blended with IK joint `ik`, kNoNode when none.
model::RigNodeIndex fkFor(const std::vector<const model::RigConstraint*>& blends, model::RigNodeIndex ik)
{
    for (const auto* b : blends)
        if (b->targets[1] == ik)
            return b->targets[0];
    return model::kNoNode;
}

// The limb's own root control (clavicle, pelvis) above its IK chain, kNoNode
// when the chain hangs under another instance's control: a match keeps it in
// place although the switch changes what it follows (the auto-clavicle).
model::RigNodeIndex limbRootControl(const model::Rig& rig, const model::RigConstraint& ik)
{
    model::RigNodeIndex n = rig.nodes[ik.driven.front()].parent;
    while (n != model::kNoNode && rig.nodes[n].kind != model::RigNodeKind::Controller)
        n = rig.nodes[n].parent;
    return n != model::kNoNode && rig.nodes[n].key.copy() == ik.key.copy() ? n : model::kNoNode;
}

// A pose tool refused on `node` (a match on a node that is no limb's).
Result<Pose> refusedAt(const model::RigNode& node, std::string message)
{
    return Result<Pose>::refused(std::move(message), Subject::ofNode(node.key));
}

Result<Pose> noSuchNode(model::RigNodeIndex node) { return Result<Pose>::refused("the rig has no node " + std::to_string(node)); }

} // namespace

const EvalState& Posing::evaluate(const Pose& pose)
{
    if (m_follow)
        m_state.continueFrom(*m_follow);
    m_program.evaluate(pose, m_state);
    return m_state;
}

Pose Posing::reset(const Pose& pose, const std::vector<model::RigNodeIndex>& nodes) const
{
    const ChannelLayout& layout = m_program.channels();
    Pose out = pose;
    auto resetNode = [&](model::RigNodeIndex n) {
        for (int i = layout.firstOf(n); i < layout.firstOf(n) + layout.countOf(n); ++i)
            if (!layout[i].locked)
                out[i] = layout[i].defaultValue;
    };
    if (nodes.empty())
        for (model::RigNodeIndex n = 0; n < m_rig.nodes.size(); ++n) resetNode(n);
    for (auto n : nodes) resetNode(n);
    return out;
}

Pose Posing::reflect(const Pose& from, Pose to, model::RigNodeIndex source, model::RigNodeIndex destination) const
{
    const ChannelLayout& layout = m_program.channels();
    const model::RigNode& a = m_rig.nodes[source];
    const int plane = a.twin == model::kNoNode ? 0 : std::max(a.mirrorPlane, 0);
    Mat3 reflection(1.0);
    reflection[plane][plane] = -1.0;
    // Channels act in each node's rest frame; K takes the source's frame to the
    // destination's through the mirror, so the destination pose is K C K^-1.
    const Mat3 k = glm::inverse(m_program.restWorld(destination).linear) * reflection * m_program.restWorld(source).linear;
    const int ta = layout.transformOf(source), tb = layout.transformOf(destination);
    if (ta >= 0 && tb >= 0) {
        const Vec3 t = k * Vec3(from[ta], from[ta + 1], from[ta + 2]);
        const Mat3 r = k * eulerRotation({from[ta + 3], from[ta + 4], from[ta + 5]}, rotateOrderOf(from, ta)) * glm::inverse(k);
        const Vec3 angles = eulerDegrees(r, rotateOrderOf(to, tb)); // the destination keeps its own order
        Vec3 s(0.0);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                s[i] += k[j][i] * k[j][i] * from[ta + 6 + j];
        const double values[9] = {t.x, t.y, t.z, angles.x, angles.y, angles.z, s.x, s.y, s.z};
        for (int i = 0; i < 9; ++i)
            if (!layout[tb + i].locked)
                to[tb + i] = layout.clamp(tb + i, values[i]);
    }
    for (int i = layout.firstOf(source); i < layout.firstOf(source) + layout.countOf(source); ++i)
        if (layout[i].transform < 0) // custom channels carry over as they are
            if (auto j = layout.find(destination, layout[i].name); j && !layout[*j].locked)
                to[*j] = from[i];
    return to;
}

Pose Posing::mirror(const Pose& pose, const std::vector<model::RigNodeIndex>& nodes) const
{
    Pose out = pose;
    for (auto n : nodes)
        if (m_rig.nodes[n].twin != model::kNoNode)
            out = reflect(pose, std::move(out), n, m_rig.nodes[n].twin);
    return out;
}

Pose Posing::flip(const Pose& pose, const std::vector<model::RigNodeIndex>& nodes) const
{
    std::set<model::RigNodeIndex> all(nodes.begin(), nodes.end());
    for (auto n : nodes)
        if (m_rig.nodes[n].twin != model::kNoNode)
            all.insert(m_rig.nodes[n].twin);
    Pose out = pose;
    for (auto n : all) {
        const auto twin = m_rig.nodes[n].twin;
        out = reflect(pose, std::move(out), twin == model::kNoNode ? n : twin, n);
    }
    return out;
}

Pose Posing::placeAt(const Pose& pose, model::RigNodeIndex node, const Mat4& world)
{
    const ChannelLayout& layout = m_program.channels();
    const int first = layout.transformOf(node);
    if (first < 0)
        return pose;
    evaluate(pose);
    const Affine local = m_program.channelFrame(node, m_state).inverse() * Affine::fromMatrix(world);
    Vec3 scale = local.scale();
    const Vec3 angles = eulerDegrees(Mat3(local.linear[0] / scale.x, local.linear[1] / scale.y, local.linear[2] / scale.z),
                                     rotateOrderOf(pose, first));
    const double values[9] = {local.translation.x, local.translation.y, local.translation.z, angles.x, angles.y, angles.z,
                              scale.x, scale.y, scale.z};
    Pose out = pose;
    for (int i = 0; i < 9; ++i)
        if (!layout[first + i].locked)
            out[first + i] = layout.clamp(first + i, values[i]);
    return out;
}

Result<Pose> Posing::ikToFk(const Pose& pose, model::RigNodeIndex node)
{
    if (node >= m_rig.nodes.size())
        return noSuchNode(node);
    const CopyKey instance = m_rig.nodes[node].key.copy();
    const auto blends = limbBlends(m_rig, instance);
    const auto* ik = limbIk(m_rig, instance);
    if (!ik || blends.empty())
        return refusedAt(m_rig.nodes[node], "'" + m_rig.nodes[node].path + "' is not on an FK/IK limb to match");
    // Where the IK chain is now (it does not depend on the FK controls).
    evaluate(pose);
    const auto root = limbRootControl(m_rig, *ik);
    const Mat4 rootWorld = root != model::kNoNode ? m_state.world[root].matrix() : Mat4(1.0);
    std::vector<std::pair<model::RigNodeIndex, Mat4>> targets;
    for (const auto* b : blends) {
        const auto fk = b->targets[0], ik = b->targets[1];
        if (m_rig.nodes[fk].kind == model::RigNodeKind::Controller)
            targets.push_back({fk, (m_state.world[ik] * m_program.restWorld(ik).inverse() * m_program.restWorld(fk)).matrix()});
    }
    Pose out = pose;
    if (auto weight = m_program.channels().find(std::get<model::BlendConstraint>(blends.front()->settings).weight))
        out[*weight] = 0.0;
    if (root != model::kNoNode)
        out = placeAt(out, root, rootWorld);
    for (const auto& [fk, world] : targets) // parents first: each placement sees its parent's new place
        out = placeAt(out, fk, world);
    return out;
}

Result<Pose> Posing::fkToIk(const Pose& pose, model::RigNodeIndex node)
{
    if (node >= m_rig.nodes.size())
        return noSuchNode(node);
    const CopyKey instance = m_rig.nodes[node].key.copy();
    const auto* ik = limbIk(m_rig, instance);
    const auto blends = limbBlends(m_rig, instance);
    if (!ik || blends.empty() || ik->targets.size() < 2)
        return refusedAt(m_rig.nodes[node], "'" + m_rig.nodes[node].path + "' is not on an FK/IK limb to match");
    const auto fkRoot = fkFor(blends, ik->driven.front()), fkMid = fkFor(blends, ik->driven[1]),
               fkEnd = fkFor(blends, ik->driven.back());
    model::RigNodeIndex control = ik->targets[0];
    while (control != model::kNoNode && m_rig.nodes[control].kind != model::RigNodeKind::Controller)
        control = m_rig.nodes[control].parent;
    const auto pole = ik->targets[1];
    if (fkRoot == model::kNoNode || fkMid == model::kNoNode || fkEnd == model::kNoNode || control == model::kNoNode)
        return refusedAt(m_rig.nodes[node], "'" + m_rig.nodes[node].path + "': the IK chain has no FK twin or no IK control");
    evaluate(pose);
    const auto& w = m_state.world;
    const Affine effector = w[fkEnd] * m_program.restWorld(fkEnd).inverse() * m_program.restWorld(ik->targets[0]);
    const Affine controlWorld = effector * w[ik->targets[0]].inverse() * w[control];
    // The pole goes in the FK chain's bend plane, at its rest distance from the elbow.
    const Vec3 root = w[fkRoot].translation, elbow = w[fkMid].translation, end = w[fkEnd].translation;
    const Vec3 line = glm::normalize(end - root);
    const Vec3 out = elbow - (root + line * glm::dot(elbow - root, line));
    const double distance = glm::length(m_program.restWorld(pole).translation - m_program.restWorld(fkMid).translation);
    const Vec3 polePosition = glm::length(out) > 1e-6
                                  ? elbow + glm::normalize(out) * distance
                                  : (w[fkMid] * m_program.restWorld(fkMid).inverse()).apply(m_program.restWorld(pole).translation);
    const auto rootControl = limbRootControl(m_rig, *ik);
    const Mat4 rootWorld = rootControl != model::kNoNode ? w[rootControl].matrix() : Mat4(1.0);
    const model::RigNodeIndex pin = ik->targets.size() == 3 ? ik->targets[2] : model::kNoNode;
    Pose result = pose;
    if (auto weight = m_program.channels().find(std::get<model::BlendConstraint>(blends.front()->settings).weight))
        result[*weight] = 1.0;
    result = placeAt(result, control, controlWorld.matrix());
    auto placePosition = [&](model::RigNodeIndex n, const Vec3& position) {
        if (n == model::kNoNode || m_rig.nodes[n].kind != model::RigNodeKind::Controller)
            return;
        evaluate(result);
        Mat4 world = m_state.world[n].matrix();
        world[3] = Vec4(position, 1.0);
        result = placeAt(result, n, world);
    };
    // Soft IK eases the reach, and a pin or an auto-clavicle moves with the
    // control: correct the control until the IK end sits on the FK end, along
    // the chain by the secant method (soft IK flattens the reach near its end)
    // and across it directly.
    double lastX = 0.0, lastReached = 0.0;
    for (int pass = 0; pass < 24; ++pass) {
        if (rootControl != model::kNoNode)
            result = placeAt(result, rootControl, rootWorld);
        placePosition(pole, polePosition);
        placePosition(pin, elbow);
        evaluate(result);
        const Vec3 start = m_state.world[ik->driven.front()].translation;
        const Vec3 reachedEnd = m_state.world[ik->driven.back()].translation;
        const Vec3 miss = end - reachedEnd;
        if (glm::length(miss) < 1e-10 || glm::length(end - start) < 1e-9)
            break;
        const Vec3 dir = glm::normalize(end - start);
        const double x = glm::dot(m_state.world[ik->targets[0]].translation - start, dir);
        const double reached = glm::dot(reachedEnd - start, dir), along = glm::dot(miss, dir);
        double step = along;
        if (pass > 0 && std::abs(reached - lastReached) > 1e-12 && std::abs(x - lastX) > 1e-12)
            step = along * (x - lastX) / (reached - lastReached);
        step = std::clamp(step, -0.5, 0.5);
        lastX = x;
        lastReached = reached;
        Affine moved = m_state.world[control];
        moved.translation += dir * step + (miss - dir * along);
        result = placeAt(result, control, moved.matrix());
    }
    return result;
}

Pose Posing::switchSpace(const Pose& pose, int channel, double value, bool keepPlace)
{
    const ChannelLayout& layout = m_program.channels();
    const model::RigNodeIndex node = layout[channel].node;
    evaluate(pose);
    const Mat4 before = m_state.world[node].matrix();
    Pose out = pose;
    out[channel] = layout.clamp(channel, value);
    if (keepPlace && layout.transformOf(node) >= 0)
        out = placeAt(out, node, before);
    return out;
}

Result<model::Rig> posedRig(const model::Rig& rig, const model::PoseValues& pose)
{
    auto program = RigProgram::compile(rig);
    if (!program)
        return Result<model::Rig>::failure(program.takeDiagnostics());
    EvalState state = program->makeState();
    program->evaluate(poseFromValues(rig, program->channels(), pose), state);
    model::Rig out = rig;
    for (model::RigNodeIndex i = 0; i < out.nodes.size(); ++i) {
        auto& node = out.nodes[i];
        node.worldMatrix = state.worldMatrix(i);
        node.localMatrix = node.parent == model::kNoNode ? node.worldMatrix
                                                         : (state.world[node.parent].inverse() * state.world[i]).matrix();
    }
    return out;
}

} // namespace rs::eval
