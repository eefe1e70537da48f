#pragma once
// How far a pose stretches a rig (internal to io/RangeOfMotion.cpp, which
// keeps every range-of-motion peak within it): the largest relative
// lengthening, over the skin joints, of a joint's distance to its skin parent
// against the rest, and, over IK constraints whose chain is blended in, of the
// goal's distance from the chain's root against the chain's reach (the rest
// bone lengths summed), plus kReachMargin: a goal at full reach measures
// 0.005, so keeping the measure at 0.005 keeps every goal within reach.
// Found once per rig; measure() reads an evaluation.
#include "eval/RigProgram.h"
#include "model/Rig.h"

#include <vector>

namespace rs::io {

class StretchGauge {
public:
    static constexpr double kReachMargin = 0.005;
    StretchGauge(const model::Rig& rig, const eval::RigProgram& program);
    // `state` is the evaluation of `pose`; 0.01: something is 1% longer than at rest (at most 0 when nothing is).
    double measure(const eval::Pose& pose, const eval::EvalState& state) const;

private:
    struct Bone {
        model::RigNodeIndex node, parent;
        double rest;
    };
    struct Reach {
        model::RigNodeIndex effector, root;
        Vec3 endInEffector;
        double length;
        int weight; // the blend weight that shows the chain, -1: always shown
    };
    std::vector<Bone> m_bones;
    std::vector<Reach> m_reaches;
};

} // namespace rs::io
