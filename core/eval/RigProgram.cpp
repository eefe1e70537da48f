#include "eval/RigProgram.h"

#include "eval/DrivenKeys.h"
#include "eval/OffsetCarry.h"
#include "eval/Solvers.h"

#include <algorithm>
#include <deque>

namespace rs::eval {

namespace {

// Attribute references resolved, then the rest data of the constraint's solver.
// A constraint that cannot be evaluated keeps its slot (indices stay aligned
// with rig.constraints) with no driven node, so it never runs.
CompiledConstraint compileConstraint(const model::RigConstraint& rc, const model::Rig& rig, const ChannelLayout& channels,
                                     const std::vector<Affine>& rest, const std::vector<CompiledConstraint>& before,
                                     Diagnostics& diagnostics)
{
    CompiledConstraint c;
    c.kind = rc.kind();
    c.driven = rc.driven;
    c.targets = rc.targets;
    c.slot = int(before.size());
    const std::size_t reported = diagnostics.size();
    bool ok = !c.driven.empty();
    if (!ok)
        diagnostics.push_back(makeError({}, "constraint '" + rc.path + "' drives no node"));
    ok = readSettings(rc, rig, channels, rest, c, diagnostics) && ok;
    // A degenerate setup (overlapping guides, already warned about by the
    // builder) leaves the driven nodes where their parents put them.
    if (ok) {
        if (std::string error = prepareConstraint(c, rig, rest); !error.empty()) {
            diagnostics.push_back(makeWarning({}, "constraint '" + rc.path + "': " + error + "; it is not evaluated"));
            ok = false;
        }
    }
    for (std::size_t i = reported; i < diagnostics.size(); ++i) // the log selects the constraint's node
        if (diagnostics[i].subject.isNone())
            diagnostics[i].subject = Subject::ofNode(rc.key);
    if (!ok) {
        c.driven.clear();
        return c;
    }
    if (c.kind == model::ConstraintKind::Twist && !before.empty()) {
        const CompiledConstraint& previous = before.back();
        if (previous.kind == model::ConstraintKind::Twist && previous.targets == c.targets && !previous.driven.empty() &&
            previous.nonRolling == c.nonRolling)
            c.shareTwistOf = previous.shareTwistOf >= 0 ? previous.shareTwistOf : previous.slot;
    }
    return c;
}

} // namespace

// Driven keys run before the steps, drivers first; a loop is a compile error.
bool RigProgram::orderDrivenKeys(RigProgram& p, const model::Rig& rig, const std::vector<std::uint32_t>& drives,
                                 Diagnostics& diagnostics)
{
    std::vector<ChannelDrive> channels;
    for (std::uint32_t k : drives)
        channels.push_back({p.m_constraints[k].valueChannel, p.m_constraints[k].drivenChannel});
    int loop = -1;
    const std::vector<std::uint32_t> order = orderChannelDrives(channels, loop);
    if (loop >= 0) {
        Diagnostic d = makeError({}, "driven key '" + rig.constraints[drives[loop]].path +
                                         "' is part of a loop of driven keys (a channel drives itself); the rig cannot be evaluated");
        d.subject = Subject::ofNode(rig.constraints[drives[loop]].key);
        diagnostics.push_back(std::move(d));
        return false;
    }
    for (std::uint32_t i : order)
        p.m_drivenKeys.push_back(drives[i]);
    return true;
}

RigProgram::RigProgram() = default;
RigProgram::RigProgram(RigProgram&&) noexcept = default;
RigProgram& RigProgram::operator=(RigProgram&&) noexcept = default;
RigProgram::~RigProgram() = default;

Result<RigProgram> RigProgram::compile(const model::Rig& rig)
{
    RigProgram p;
    Diagnostics diagnostics;
    p.m_channels = ChannelLayout(rig);
    const std::size_t n = rig.nodes.size();
    std::vector<Affine> rest(n);
    p.m_nodes.resize(n);
    for (model::RigNodeIndex i = 0; i < n; ++i) {
        const model::RigNode& node = rig.nodes[i];
        NodeStep& s = p.m_nodes[i];
        rest[i] = Affine::fromMatrix(node.worldMatrix);
        s.parent = node.parent;
        s.restLocal = node.parent == model::kNoNode ? rest[i] : rest[node.parent].inverse() * rest[i];
        s.identityLocal = maxAbsDifference(s.restLocal.matrix(), Mat4(1.0)) < 1e-12;
        if (s.identityLocal)
            s.restLocal = Affine{};
        s.channels = p.m_channels.transformOf(i);
        s.scaleCompensate = node.scaleCompensate && node.parent != model::kNoNode;
        if (s.scaleCompensate)
            s.parentChannels = p.m_channels.transformOf(node.parent);
    }

    p.m_constraints.reserve(rig.constraints.size());
    for (const model::RigConstraint& rc : rig.constraints) {
        p.m_constraints.push_back(compileConstraint(rc, rig, p.m_channels, rest, p.m_constraints, diagnostics));
        CompiledConstraint& c = p.m_constraints.back();
        if (c.kind == model::ConstraintKind::Roll && c.pathSlot >= 0 && !c.driven.empty()) {
            c.pathSlot = int(p.m_pathKeys.size());
            p.m_pathKeys.push_back(rc.key);
        }
        if (c.kind == model::ConstraintKind::Spline)
            p.m_maxSamples = std::max(p.m_maxSamples, std::size_t(c.samplesPerSegment) * c.targets.size() + 1);
    }
    if (hasErrors(diagnostics))
        return Result<RigProgram>::failure(diagnostics);
    p.m_restWorld = rest;

    // Writers of each node, in order: its own placement (unless a chain solver
    // replaces it), then every constraint that drives it.
    const std::size_t ops = n + p.m_constraints.size();
    std::vector<std::vector<std::uint32_t>> writers(n);
    std::vector<bool> placed(n, true);
    for (const CompiledConstraint& c : p.m_constraints)
        if (c.kind == model::ConstraintKind::Ik || c.kind == model::ConstraintKind::Spline)
            for (std::size_t k = 1; k < c.driven.size(); ++k)
                if (rig.nodes[c.driven[k]].parent == c.driven[k - 1])
                    placed[c.driven[k]] = false;
    for (model::RigNodeIndex i = 0; i < n; ++i)
        if (placed[i]) writers[i].push_back(i);
    // Visibility constraints and driven keys place nothing: no writer, no step, no dependency.
    auto isStep = [&](std::uint32_t k) {
        const model::ConstraintKind kind = p.m_constraints[k].kind;
        return !p.m_constraints[k].driven.empty() && kind != model::ConstraintKind::Visibility &&
               kind != model::ConstraintKind::DrivenKey;
    };
    std::vector<std::uint32_t> drives;
    for (std::uint32_t k = 0; k < p.m_constraints.size(); ++k) {
        if (!p.m_constraints[k].driven.empty() && !isStep(k))
            (p.m_constraints[k].kind == model::ConstraintKind::DrivenKey ? drives : p.m_visibility).push_back(k);
        else
            for (model::RigNodeIndex d : p.m_constraints[k].driven)
                writers[d].push_back(std::uint32_t(n + k));
    }
    if (!orderDrivenKeys(p, rig, drives, diagnostics))
        return Result<RigProgram>::failure(diagnostics);
    std::vector<std::vector<std::uint32_t>> dependents(ops);
    std::vector<int> pending(ops, 0);
    auto depend = [&](std::uint32_t op, std::uint32_t on) {
        dependents[on].push_back(op);
        ++pending[op];
    };
    for (model::RigNodeIndex i = 0; i < n; ++i)
        if (placed[i] && rig.nodes[i].parent != model::kNoNode && !writers[rig.nodes[i].parent].empty())
            depend(i, writers[rig.nodes[i].parent].back());
    for (model::RigNodeIndex i = 0; i < n; ++i)
        for (std::size_t w = 1; w < writers[i].size(); ++w)
            depend(writers[i][w], writers[i][w - 1]);
    for (std::uint32_t k = 0; k < p.m_constraints.size(); ++k) {
        const CompiledConstraint& c = p.m_constraints[k];
        if (!isStep(k))
            continue;
        if (!placed[c.driven.front()] && writers[c.driven.front()].front() == n + k) {
            const auto parent = rig.nodes[c.driven.front()].parent;
            if (parent != model::kNoNode) depend(n + k, writers[parent].back());
        }
        if (c.chainParent != model::kNoNode && !writers[c.chainParent].empty())
            depend(n + k, writers[c.chainParent].back());
        for (model::RigNodeIndex target : c.targets)
            if (!writers[target].empty() && writers[target].back() != n + k)
                depend(n + k, writers[target].back());
        if (c.shareTwistOf >= 0) // it reads the angle its segment's first twist computes
            depend(n + k, std::uint32_t(n + c.shareTwistOf));
    }
    std::deque<std::uint32_t> ready;
    for (std::uint32_t op = 0; op < ops; ++op)
        if (pending[op] == 0 && (op >= n ? isStep(std::uint32_t(op - n)) : placed[op]))
            ready.push_back(op);
    while (!ready.empty()) {
        const std::uint32_t op = ready.front();
        ready.pop_front();
        p.m_steps.push_back({op < n, op < n ? op : std::uint32_t(op - n)});
        for (std::uint32_t next : dependents[op])
            if (--pending[next] == 0)
                ready.push_back(next);
    }
    std::size_t expected = 0;
    for (model::RigNodeIndex i = 0; i < n; ++i) expected += placed[i] ? 1 : 0;
    for (std::uint32_t k = 0; k < p.m_constraints.size(); ++k) expected += isStep(k) ? 1 : 0;
    if (p.m_steps.size() != expected) {
        // Peel off what merely waits on the cycle (nothing stuck depends on
        // it), so the message names the constraints that form it.
        std::vector<bool> stuck(ops);
        for (std::uint32_t op = 0; op < ops; ++op) stuck[op] = pending[op] > 0;
        for (bool peeled = true; peeled;) {
            peeled = false;
            for (std::uint32_t op = 0; op < ops; ++op)
                if (stuck[op] && std::none_of(dependents[op].begin(), dependents[op].end(), [&](std::uint32_t d) { return bool(stuck[d]); }))
                    stuck[op] = false, peeled = true;
        }
        std::string list;
        int shown = 0;
        for (std::uint32_t k = 0; k < p.m_constraints.size(); ++k)
            if (stuck[n + k] && shown++ < 6)
                list += (list.empty() ? "" : ", ") + rig.constraints[k].path;
        diagnostics.push_back(makeError({}, "the rig's constraints form a cycle (a node depends on itself through " + list +
                                                "); the rig cannot be evaluated"));
        return Result<RigProgram>::failure(diagnostics);
    }
    return Result<RigProgram>(std::move(p), std::move(diagnostics));
}

EvalState RigProgram::makeState() const
{
    EvalState state;
    state.world = m_restWorld;
    state.arcLengths.resize(m_maxSamples);
    state.twistAngles.resize(m_constraints.size());
    state.visible.assign(m_nodes.size(), 1);
    state.rolls.resize(m_pathKeys.size());
    if (!m_drivenKeys.empty())
        state.channels.resize(m_channels.size());
    return state;
}

std::vector<std::pair<NodeKey, double>> RigProgram::rolledPaths(const EvalState& state) const
{
    std::vector<std::pair<NodeKey, double>> rolled;
    if (state.rolls.size() != m_pathKeys.size())
        return rolled;
    rolled.reserve(m_pathKeys.size());
    for (std::size_t i = 0; i < m_pathKeys.size(); ++i)
        rolled.emplace_back(m_pathKeys[i], state.rolls[i].angleRadians);
    return rolled;
}

void RigProgram::carryPaths(const std::vector<std::pair<NodeKey, double>>& rolled, EvalState& state) const
{
    if (state.rolls.size() != m_pathKeys.size())
        return;
    for (std::size_t i = 0; i < m_pathKeys.size(); ++i) {
        const auto it = std::find_if(rolled.begin(), rolled.end(), [&](const auto& r) { return r.first == m_pathKeys[i]; });
        if (it != rolled.end())
            state.rolls[i] = {Vec3(0.0), Vec3(0.0), it->second, false};
    }
}

const Pose& RigProgram::driveChannels(const Pose& given, EvalState& state) const
{
    if (m_drivenKeys.empty())
        return given;
    state.channels.assign(given.begin(), given.end()); // the state's capacity: no allocation
    for (std::uint32_t k : m_drivenKeys) {
        const CompiledConstraint& c = m_constraints[k];
        const double x = state.channels[c.valueChannel];
        state.channels[c.drivenChannel] = m_channels.clamp(c.drivenChannel, evaluateCurve(c.keys, c.tangents, c.pre, c.post, x));
    }
    return state.channels;
}

void RigProgram::evaluate(const Pose& given, EvalState& state) const
{
    const Pose& pose = driveChannels(given, state);
    std::vector<Affine>& world = state.world;
    for (const Step& step : m_steps) {
        if (!step.isNode) {
            solveConstraint(m_constraints[step.index], pose, state);
            continue;
        }
        const NodeStep& s = m_nodes[step.index];
        if (s.parent != model::kNoNode && s.identityLocal && s.channels < 0 && !s.scaleCompensate) {
            world[step.index] = world[s.parent];
            continue;
        }
        const Affine local = s.channels < 0 ? s.restLocal
                             : s.identityLocal ? channelAffine(pose, s.channels)
                                               : s.restLocal * channelAffine(pose, s.channels);
        if (s.parent == model::kNoNode) {
            world[step.index] = local;
        } else if (s.scaleCompensate && s.parentChannels >= 0) {
            // The parent's channel scale is the last factor of its world: divide it
            // out of the orientation, keep it on the position.
            const Affine& parent = world[s.parent];
            const double* sp = pose.data() + s.parentChannels + 6;
            const Mat3 unscaled(parent.linear[0] / sp[0], parent.linear[1] / sp[1], parent.linear[2] / sp[2]);
            world[step.index] = {unscaled * local.linear, parent.linear * local.translation + parent.translation};
        } else {
            world[step.index] = world[s.parent] * local;
        }
    }
    if (state.visible.size() != m_nodes.size())
        state.visible.assign(m_nodes.size(), 1);
    for (std::uint32_t k : m_visibility) // shown unless one of its conditions fails
        for (model::RigNodeIndex d : m_constraints[k].driven)
            state.visible[d] = 1;
    for (std::uint32_t k : m_visibility) {
        const CompiledConstraint& c = m_constraints[k];
        const double v = c.valueChannel >= 0 ? pose[c.valueChannel] : 0.0;
        const bool shown = c.showAbove ? v > c.threshold : v < c.threshold;
        if (!shown)
            for (model::RigNodeIndex d : c.driven)
                state.visible[d] = 0;
    }
}

Affine RigProgram::channelFrame(model::RigNodeIndex node, const EvalState& state) const
{
    const NodeStep& s = m_nodes[node];
    return s.parent == model::kNoNode ? s.restLocal : state.world[s.parent] * s.restLocal;
}

} // namespace rs::eval
