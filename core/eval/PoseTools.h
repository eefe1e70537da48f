#pragma once
// Pose tools an animator expects: reset to defaults, mirror and flip across
// L/R twins, FK/IK matching on limbs, space switching that keeps the control
// where it is, and placing a control at a world transform (what a gizmo drag
// does). Each takes a pose and returns a new one, so the caller records the
// change as one undoable edit (rs::edit::SetPose). Locked channels never change.
#include "base/Result.h"
#include "eval/RigProgram.h"

#include <optional>
#include <string>
#include <vector>

namespace rs::eval {

// A rig, its program and a scratch evaluation state, for tools that evaluate.
class Posing {
public:
    Posing(const model::Rig& rig, const RigProgram& program) : m_rig(rig), m_program(program), m_state(program.makeState()) {}

    const model::Rig& rig() const { return m_rig; }
    const RigProgram& program() const { return m_program; }
    // Evaluates `pose` into the scratch state. Rolling wheels (model::RollMode::Path)
    // continue from the followed state when there is one (each trial pose a
    // step after the one it shows, so a tool sees the wheels as displayed),
    // else from this object's previous evaluation.
    const EvalState& evaluate(const Pose& pose);
    // The state the session displays (kept alive by the caller); nullptr: none.
    void follow(const EvalState* displayed) { m_follow = displayed; }
    const EvalState& state() const { return m_state; } // the last evaluation (tools evaluate too)

    // Channels of `nodes` (every channel when empty) back to their defaults.
    Pose reset(const Pose& pose, const std::vector<model::RigNodeIndex>& nodes) const;
    // Copies the pose of `nodes` onto their twins, reflected (centre nodes are
    // left alone): the other side then mirrors the chosen one exactly.
    Pose mirror(const Pose& pose, const std::vector<model::RigNodeIndex>& nodes) const;
    // Swaps the poses of `nodes` and their twins, reflected; centre nodes are
    // reflected in place.
    Pose flip(const Pose& pose, const std::vector<model::RigNodeIndex>& nodes) const;
    // The channels that put `node` at `world` given the rest of the pose
    // (translate/rotate/scale decomposed in its rotate order; locked channels kept).
    Pose placeAt(const Pose& pose, model::RigNodeIndex node, const Mat4& world);
    // Snaps the FK controls of the limb `node` belongs to onto its IK chain and
    // switches the limb to FK (ik_blend 0); the other way round for fkToIk.
    // Fails, naming the node, when its instance has no IK limb (or the node is
    // not in the rig).
    Result<Pose> ikToFk(const Pose& pose, model::RigNodeIndex node);
    Result<Pose> fkToIk(const Pose& pose, model::RigNodeIndex node);
    // Sets `channel` (a space enum) to `value`; with `keepPlace` the controls it
    // moves are placed back where they were, so nothing jumps.
    Pose switchSpace(const Pose& pose, int channel, double value, bool keepPlace);

private:
    Pose reflect(const Pose& from, Pose to, model::RigNodeIndex source, model::RigNodeIndex destination) const;

    const model::Rig& m_rig;
    const RigProgram& m_program;
    EvalState m_state;
    const EvalState* m_follow = nullptr;
};

// A copy of `rig` whose world and local matrices are the evaluation of `pose`
// (the document's test pose): what a posed dump or export writes. Fails with
// the compile diagnostics when the rig cannot be evaluated.
Result<model::Rig> posedRig(const model::Rig& rig, const model::PoseValues& pose);

} // namespace rs::eval
