#pragma once
// What the range of motion (io/RangeOfMotion.cpp, internal to it) watches on
// a rig's deform joints while it plans: their extent, where they are, how
// they turn in their skin parents' frames (what an exported track holds) and
// whether a chain folds back on itself; and how far a control carrying aim
// goals reaches. Found once per rig; the queries read an evaluation.
#include "eval/RigProgram.h"
#include "model/Rig.h"

#include <vector>

namespace rs::io {

class JointWatch {
public:
    explicit JointWatch(const model::Rig& rig);

    // The skeleton's bounding box diagonal at rest, metres (1 without deform joints).
    double size() const { return m_size; }
    // The deform joints' world transforms in `state`, in skeleton order.
    std::vector<eval::Affine> positions(const eval::EvalState& state) const;
    // The deform joints' rotations in their skin parents' frames (a root's in
    // the world), columns normalised: a joint may turn little in the world
    // while its parent turns the other way, and its track holds the local turn.
    std::vector<Mat3> rotations(const eval::EvalState& state) const;
    // How many deform joints, in `state`, lie less than `share` of their rest
    // distance ahead of their skin parent along the rest direction, in the
    // parent's frame: a chain folded back on itself (a spline path pulled past
    // a cusp, where the joints sliding on it collapse and turn over).
    int folds(const eval::EvalState& state, double share) const;

private:
    struct Offset { // a deform joint's offset from its skin parent at rest, in the parent's frame (over 1 mm)
        model::RigNodeIndex node, parent;
        Vec3 restDirection;
        double restLength;
    };
    std::vector<model::RigNodeIndex> m_nodes;   // the deform joints' rig nodes
    std::vector<model::RigNodeIndex> m_parents; // each one's skin parent's rig node (kNoNode: a root)
    std::vector<Offset> m_offsets;
    double m_size = 1.0;
};

// Per rig node: for a controller carrying aim goals (an aim constraint's goal
// is it or hangs from it, the aimed node does not: a finger's or an eye's
// target), the farthest rest distance from an aimed node to it, how far the
// aimed chain reaches; 0 for every other node.
std::vector<double> aimReaches(const model::Rig& rig);

} // namespace rs::io
