#pragma once
// The seed's "skinny jeans onto parachute pants" case (issue 20), built
// procedurally: a source garment of two skinny legs (tubes) weighted to a hip
// and a left and a right leg joint, and a wide target garment whose legs
// overlap at the crotch, so that the closest source point of a pants vertex
// on the inside of one leg lies on the other leg's jeans.
//
// Metres, y up, legs hanging down and spread outward (A stance): each leg's
// axis runs from its joint at hip height (y = 1, x = +-0.08) to its ankle
// (y = 0.1, x = +-0.13). Jeans: radius 6.5 cm. Pants: radius 11 cm, so over
// the upper 60% of the legs the inside of a pants leg is nearer the other
// leg's jeans than its own (at the crotch it passes through them): closest
// point takes the wrong leg there, and near the crotch the normal filter's 16
// nearest source vertices are all on the wrong leg too (so it falls back to
// closest point). Towards the ankles the legs part and the overlap fades out.
#include "model/Mesh.h"
#include "skin/SkinChunk.h"

#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace rs::test {

struct JeansFixture {
    enum Joint : std::uint32_t { kHip = 0, kLeftLeg = 1, kRightLeg = 2 };
    model::Mesh jeans;                 // both legs, one mesh
    skin::SkinChunk jeansChunk;        // the jeans in bind pose with their weights
    model::Mesh pants;                 // both legs, one mesh (two connected parts)
    model::MeshWeights idealPants;     // each pants vertex: the jeans' weights at its own leg's height
    std::array<glm::vec3, 3> jointPositions; // bind pose, world
};

JeansFixture makeJeansFixture();

// Linear blend skinning of `mesh` with `weights` when the left leg joint
// swings `angleDegrees` forward (about the x axis through it), the hip and
// the right leg staying in bind pose.
std::vector<glm::vec3> skinWithLeftLegForward(const JeansFixture& fixture, const model::Mesh& mesh, const model::MeshWeights& weights,
                                              float angleDegrees);

} // namespace rs::test
