#pragma once
// The evaluation engine: a built rig compiled into a flat program of steps in
// dependency order (ozz-style jobs: compile validates once, evaluate runs). A
// step either places one node (parent world * rest local * channels, with the
// parent's channel scale removed on segment-scale-compensated nodes) or solves
// one constraint (model/Constraint.h documents each kind's settings). Attribute
// references are resolved to channel indices at compile time; evaluate() does
// no name lookup and no allocation once the state is made.
//
// Compile fails with a diagnostic when the constraints form a cycle (a node
// that, through its targets, depends on itself) or reference attributes their
// nodes do not have (every such reference is reported). A constraint whose rest setup is degenerate (IK joints on one
// spot) is skipped with a warning. Units: metres, degrees in channels, radians inside.
#include "base/Result.h"
#include "eval/Affine.h"
#include "eval/Channels.h"
#include "model/Rig.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace rs::eval {

struct CompiledConstraint; // RigProgram.cpp / Solvers

// What a wheel rolling along its path (model::RollMode::Path) remembers
// between evaluations.
struct RollMemory {
    Vec3 centre{0.0};          // the wheel's centre at the previous evaluation, in its reference's frame (metres)
    Vec3 rolling{0.0};         // its rolling direction then (unit, same frame; zero: none)
    double angleRadians = 0.0; // the roll so far (auto_rotate included), unwrapped
    bool anchored = false;     // false: no previous evaluation, the next one only records the centre
};

// Everything an evaluation writes: one world transform per rig node, plus the
// scratch the spline solver reuses, plus what stateful constraints remember
// (the rolls). Make it with RigProgram::makeState(): a new state has rolled
// nothing. Evaluations are steps in time for the rolls: evaluate a clip's
// samples in time order from a new state, so the result depends on the clip
// alone (exports do, io/ExportMotion.h).
struct EvalState {
    std::vector<Affine> world;
    std::vector<double> arcLengths;
    std::vector<double> twistAngles; // per constraint: the twist a segment's twist joints share
    // Per node: 1 shown, 0 hidden by a visibility constraint (model::VisibilityConstraint)
    // in this pose. Nodes no visibility constraint drives stay 1.
    std::vector<std::uint8_t> visible;
    bool isVisible(model::RigNodeIndex node) const { return node >= visible.size() || visible[node] != 0; }
    // The pose evaluated last with its driven channels computed (driven keys,
    // model::DrivenKeyConstraint); empty when the rig has none.
    Pose channels;
    // Per path-mode roll constraint (RigProgram::pathKeys names them).
    std::vector<RollMemory> rolls;
    // Continues from `other`, a state of the same program: the next evaluation
    // rolls the wheels from where `other` left them (a tool's trial pose after
    // the displayed one). No allocation; nothing when the programs differ.
    void continueFrom(const EvalState& other)
    {
        if (other.rolls.size() == rolls.size())
            std::copy(other.rolls.begin(), other.rolls.end(), rolls.begin());
    }
    Mat4 worldMatrix(model::RigNodeIndex node) const { return world[node].matrix(); }
};

class RigProgram {
public:
    RigProgram();
    RigProgram(RigProgram&&) noexcept;
    RigProgram& operator=(RigProgram&&) noexcept;
    ~RigProgram();

    static Result<RigProgram> compile(const model::Rig& rig);

    const ChannelLayout& channels() const { return m_channels; }
    std::size_t nodeCount() const { return m_nodes.size(); }
    std::size_t stepCount() const { return m_steps.size(); }
    EvalState makeState() const;
    // The path-mode roll constraints (EvalState::rolls, in this order), by key.
    const std::vector<NodeKey>& pathKeys() const { return m_pathKeys; }
    bool hasPaths() const { return !m_pathKeys.empty(); } // an evaluation depends on the ones before
    // How far each path-mode roll of `state` (a state of this program) has
    // turned, by key: what a rebuild carries over, kept as plain values so it
    // outlives the program (a rig edit that fails to compile keeps it for the
    // next good one).
    std::vector<std::pair<NodeKey, double>> rolledPaths(const EvalState& state) const;
    // After a rebuild: each roll of `state` (a new state of this program)
    // whose constraint `rolled` names, by key, takes that angle, unanchored, so
    // the rebuilt wheels keep their turn and the rebuild itself (a guide edit
    // moving them) rolls nothing.
    void carryPaths(const std::vector<std::pair<NodeKey, double>>& rolled, EvalState& state) const;
    void carryPaths(const RigProgram& previous, const EvalState& from, EvalState& state) const
    {
        carryPaths(previous.rolledPaths(from), state);
    }
    // Evaluates every node's world transform for `pose` (m_channels.size() values).
    // Driven channels (driven keys) are computed from it first: their values in `pose` are ignored.
    void evaluate(const Pose& pose, EvalState& state) const;
    // `pose` with its driven channels computed (into state.channels), or `pose`
    // itself when the rig has no driven keys: what evaluate() places the nodes with.
    const Pose& driveChannels(const Pose& pose, EvalState& state) const;
    bool hasDrivenKeys() const { return !m_drivenKeys.empty(); }

    // What pose tools need to invert a node's placement: the world transform
    // the node's channels act in (parent world * rest local, compensated), so
    // that world = frame * channelMatrix.
    Affine channelFrame(model::RigNodeIndex node, const EvalState& state) const;
    const Affine& restWorld(model::RigNodeIndex node) const { return m_restWorld[node]; }

    struct NodeStep {
        model::RigNodeIndex parent = model::kNoNode;
        Affine restLocal;
        int channels = -1;          // first transform channel, -1 when none
        int parentChannels = -1;    // the parent's, for segment scale compensation
        bool scaleCompensate = false;
        bool identityLocal = false;  // at its parent's place (controllers under their offset groups): one product less
    };

private:
    struct Step {
        bool isNode = true;
        std::uint32_t index = 0;
    };

    ChannelLayout m_channels;
    std::vector<NodeStep> m_nodes;
    std::vector<Affine> m_restWorld; // apart from the steps: the hot loop never reads it
    std::vector<CompiledConstraint> m_constraints;
    std::vector<Step> m_steps;
    std::vector<std::uint32_t> m_visibility; // visibility constraints: evaluated after the steps, ordering nothing
    std::vector<std::uint32_t> m_drivenKeys; // driven keys, drivers first: computed on the pose before the steps
    static bool orderDrivenKeys(RigProgram& p, const model::Rig& rig, const std::vector<std::uint32_t>& drives,
                                Diagnostics& diagnostics);
    std::size_t m_maxSamples = 0;
    std::vector<NodeKey> m_pathKeys;
};

} // namespace rs::eval
