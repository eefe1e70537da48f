#pragma once
// Internal to rs::eval: the curve a bendy limb's twist joints ride
// (model::TwistConstraint with `bendy`, which documents the curve). Two cubic
// Hermite pieces, segment start -> bend control -> segment end, the tweak
// control standing for the middle joint.
#include "eval/Solvers.h"

namespace rs::eval {

// A bendy twist's curve, sampled for its arc length.
struct BendyCurve {
    Vec3 start{0.0}, mid{0.0}, end{0.0};           // positions, world
    Vec3 startTangent{0.0}, midTangent{0.0}, endTangent{0.0}; // unit directions, world
    double first = 0.0, second = 0.0;                         // the pieces' chords (setChords)

    void setChords();

    // Position and derivative at the curve parameter u in [0, 1] (0.5 at the bend control).
    void at(double u, Vec3& position, Vec3& derivative) const;
    // The parameter at `share` (0..1) of the arc length (sampled, 24 steps).
    double parameterAtLength(double share) const;
};

// Index of the first of the six bend targets of a twist constraint:
// [limb start, middle joint, limb end, tweak, tweak's space, bend control].
inline std::size_t bendTargetsBegin(const CompiledConstraint& c) { return c.nonRolling ? 3 : 2; }
// The curve in `world` (targets read from c.targets by bendTargetsBegin).
BendyCurve bendyCurveOf(const CompiledConstraint& c, const std::vector<Affine>& world);
// Checks the targets and stores the rest data: the bend control's rest
// direction of the segment in its frame (c.localTangents[0]) and the angle
// between the bones (c.restKink); returns an error message, empty when usable.
std::string prepareBendy(CompiledConstraint& c, const std::vector<Affine>& rest);
// The place a bendy twist joint takes: the curve point at its fraction (by
// arc length or parameter) and the rotation `twisted` (what the straight
// twist gives, aimed along the start's bone `boneAxis`, world) swung by the
// shortest arc onto the curve's tangent there.
void bendJoint(const CompiledConstraint& c, const std::vector<Affine>& world, const Vec3& boneAxis, Mat3& twisted,
               Vec3& position);

} // namespace rs::eval
