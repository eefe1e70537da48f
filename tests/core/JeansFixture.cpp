// The skinny jeans and parachute pants fixture (JeansFixture.h).
#include "JeansFixture.h"
#include "skin/Refit.h"

#include "skin/SkinChunk.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace rs::test {

namespace {

constexpr float kHipHeight = 1.0f, kAnkleHeight = 0.1f;
constexpr float kHipX = 0.08f, kAnkleX = 0.13f;
constexpr float kJeansRadius = 0.065f, kPantsRadius = 0.11f;
constexpr float kBlend = 0.15f; // the top 15% of a leg blends from the hip into the leg joint

glm::vec3 legTop(int side) { return {float(side) * kHipX, kHipHeight, 0.0f}; }
glm::vec3 legBottom(int side) { return {float(side) * kAnkleX, kAnkleHeight, 0.0f}; }

// An open tube around a leg's axis (side +1 left, -1 right), wound so its
// triangles face out; `along` gets each new vertex's place on the axis (0 at
// the joint, 1 at the ankle).
void addTube(model::Mesh& mesh, std::vector<float>& along, int side, float radius, int rings, int segments)
{
    const glm::vec3 top = legTop(side), axis = legBottom(side) - top, d = glm::normalize(axis);
    const glm::vec3 e1 = glm::normalize(glm::cross(d, glm::vec3(0.0f, 0.0f, 1.0f))), e2 = glm::cross(d, e1);
    const auto first = std::uint32_t(mesh.positions.size());
    for (int i = 0; i < rings; ++i) {
        const float t = float(i) / float(rings - 1);
        for (int k = 0; k < segments; ++k) {
            const float phi = 2.0f * 3.14159265f * float(k) / float(segments);
            mesh.positions.push_back(top + t * axis + radius * (std::cos(phi) * e1 + std::sin(phi) * e2));
            along.push_back(t);
        }
    }
    for (int i = 0; i + 1 < rings; ++i)
        for (int k = 0; k < segments; ++k) {
            const std::uint32_t a = first + std::uint32_t(i * segments + k), b = first + std::uint32_t(i * segments + (k + 1) % segments);
            const std::uint32_t c = a + std::uint32_t(segments), e = b + std::uint32_t(segments);
            mesh.indices.insert(mesh.indices.end(), {a, b, c, b, e, c});
        }
}

// The jeans' weights at `t` along a leg: the hip fading into the leg joint.
void addLegWeights(model::MeshWeights& w, float t, std::uint32_t leg)
{
    const float s = std::min(t / kBlend, 1.0f);
    if (s < 1.0f)
        w.influences.push_back({JeansFixture::kHip, 1.0f - s});
    if (s > 0.0f)
        w.influences.push_back({leg, s});
    w.offsets.push_back(std::uint32_t(w.influences.size()));
}

model::MeshWeights legWeights(const std::vector<float>& along, std::size_t leftCount)
{
    model::MeshWeights w;
    w.joints = {{1, "", "skin.hip"}, {1, "", "skin.leg_L"}, {1, "", "skin.leg_R"}};
    w.parents = {-1, 0, 0};
    w.offsets.push_back(0);
    for (std::size_t v = 0; v < along.size(); ++v)
        addLegWeights(w, along[v], v < leftCount ? JeansFixture::kLeftLeg : JeansFixture::kRightLeg);
    return w;
}

skin::SkinChunk chunkOf(const model::Mesh& mesh, const model::MeshWeights& weights)
{
    return skin::bindingChunk({"", mesh.name, mesh.vertexCount(), model::topologyFingerprint(mesh), weights}, mesh, nullptr);
}

} // namespace

JeansFixture makeJeansFixture()
{
    JeansFixture f;
    std::vector<float> jeansAlong, pantsAlong;
    f.jeans.name = "jeans";
    addTube(f.jeans, jeansAlong, +1, kJeansRadius, 46, 24); // rings 2 cm apart
    const std::size_t jeansLeft = f.jeans.vertexCount();
    addTube(f.jeans, jeansAlong, -1, kJeansRadius, 46, 24);
    f.pants.name = "pants";
    addTube(f.pants, pantsAlong, +1, kPantsRadius, 61, 32); // a finer, different tessellation
    const std::size_t pantsLeft = f.pants.vertexCount();
    addTube(f.pants, pantsAlong, -1, kPantsRadius, 61, 32);
    f.jeansChunk = chunkOf(f.jeans, legWeights(jeansAlong, jeansLeft));
    f.idealPants = legWeights(pantsAlong, pantsLeft);
    f.jointPositions = {glm::vec3(0.0f, kHipHeight, 0.0f), legTop(+1), legTop(-1)};
    return f;
}

std::vector<glm::vec3> skinWithLeftLegForward(const JeansFixture& fixture, const model::Mesh& mesh, const model::MeshWeights& weights,
                                              float angleDegrees)
{
    // Forward is +z: a leg hanging down (-y) swings there under a negative turn about +x.
    const glm::vec3 joint = fixture.jointPositions[JeansFixture::kLeftLeg];
    const glm::mat4 left = glm::translate(glm::mat4(1.0f), joint) *
                           glm::rotate(glm::mat4(1.0f), -glm::radians(angleDegrees), glm::vec3(1.0f, 0.0f, 0.0f)) *
                           glm::translate(glm::mat4(1.0f), -joint);
    const glm::mat4 matrices[3] = {glm::mat4(1.0f), left, glm::mat4(1.0f)};
    std::vector<glm::vec3> out;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        glm::vec3 p(0.0f);
        for (auto* i = weights.begin(v); i != weights.end(v); ++i)
            p += i->weight * glm::vec3(matrices[i->joint] * glm::vec4(mesh.positions[v], 1.0f));
        out.push_back(p);
    }
    return out;
}

} // namespace rs::test
