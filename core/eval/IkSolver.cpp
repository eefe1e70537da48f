#include "eval/IkSolver.h"

#include <algorithm>
#include <cmath>

namespace rs::eval {

namespace {

// The unit direction from the chain towards the pole, perpendicular to `dir`;
// nullopt when the pole lies on the line.
std::optional<Vec3> poleSide(const Vec3& root, const Vec3& dir, const Vec3& pole)
{
    const Vec3 toPole = pole - root;
    const Vec3 perpendicular = toPole - dir * glm::dot(toPole, dir);
    const double length = glm::length(perpendicular);
    if (length < 1e-9)
        return std::nullopt;
    return perpendicular / length;
}

} // namespace

double softReach(double distance, double reach, double softness)
{
    const double start = reach - softness;
    if (softness <= 0.0 || distance <= start)
        return distance;
    return reach - softness * std::exp(-(distance - start) / softness);
}

std::string prepareIk(CompiledConstraint& c, const std::vector<Affine>& rest)
{
    const std::size_t joints = c.driven.size();
    if (joints != 3 && joints != 4)
        return "IK drives " + std::to_string(joints) + " joints; it solves chains of 3 or 4";
    if (c.targets.size() != 2 && c.targets.size() != 3)
        return "IK needs two targets (effector, pole) or three (effector, pole, pin)";
    if (c.pinChannel >= 0 && c.targets.size() != 3)
        return "an IK with a pin attribute needs a third target, the pin";
    for (auto d : c.driven) {
        c.restPositions.push_back(rest[d].translation);
        c.restRotations.push_back(rest[d].rotation());
    }
    for (std::size_t i = 0; i + 1 < joints; ++i) {
        c.lengths.push_back(glm::length(c.restPositions[i + 1] - c.restPositions[i]));
        if (c.lengths.back() < 1e-9)
            return "IK joints " + std::to_string(i) + " and " + std::to_string(i + 1) + " are at the same place";
    }
    c.restPole = rest[c.targets[1]].translation;
    c.restEffectorRotation = rest[c.targets[0]].rotation();
    const Vec3 root = c.restPositions.front(), end = c.restPositions.back();
    if (glm::length(end - root) < 1e-9)
        return "the IK chain ends where it starts";
    const Vec3 dir = glm::normalize(end - root);
    const auto side = poleSide(root, dir, c.restPole);
    if (!side)
        return "the pole lies on the line from the chain's root to its end, so the bend plane is unknown";
    const Vec3 normal = glm::normalize(glm::cross(dir, *side));
    for (std::size_t i = 0; i + 1 < joints; ++i) {
        c.restBoneFrames.push_back(frameFromAxes(c.restPositions[i + 1] - c.restPositions[i], normal));
        // The joint's local axis closest to its bone: volume scales the other two.
        const Vec3 along = glm::transpose(c.restRotations[i]) * c.restBoneFrames.back()[0];
        int axis = 0;
        for (int k = 1; k < 3; ++k)
            if (std::abs(along[k]) > std::abs(along[axis]))
                axis = k;
        c.boneAxes.push_back(axis);
    }
    if (joints == 4) {
        const Mat3 virtualBone = frameFromAxes(end - c.restPositions[1], normal);
        c.midOffset = glm::transpose(virtualBone) * (c.restPositions[2] - c.restPositions[1]);
        c.lengths.push_back(glm::length(end - c.restPositions[1])); // lengths[3]: the virtual bone
    }
    return {};
}

void solveIk(const CompiledConstraint& c, const Pose& pose, std::vector<Affine>& world)
{
    const std::size_t joints = c.driven.size();
    const Affine* parent = c.chainParent != model::kNoNode ? &world[c.chainParent] : nullptr;
    const double scale = parent ? parent->scale().x / c.restParentScale : 1.0;
    const Vec3 root = world[c.driven.front()].translation;
    const Vec3 target = world[c.targets[0]].translation;
    const Vec3 pole = world[c.targets[1]].translation;

    double a = c.lengths[0] * scale;
    double b = (joints == 3 ? c.lengths[1] : c.lengths[3]) * scale;
    const double distance = glm::length(target - root);
    Vec3 dir = distance > 1e-12 ? (target - root) / distance : c.restBoneFrames[0][0];
    // The soft zone is in metres at the rest scale, never more than the whole reach.
    const double softness =
        c.softChannel >= 0 ? std::min(std::clamp(pose[c.softChannel], 0.0, 1.0) * scale, a + b) : 0.0;
    double reach = softness > 0.0 ? softReach(distance, a + b, softness) : std::min(distance, a + b);
    double stretch = 1.0;
    if (c.stretchChannel >= 0 && distance > reach && reach > 1e-12) {
        stretch = 1.0 + std::clamp(pose[c.stretchChannel], 0.0, 1.0) * (distance / reach - 1.0);
        a *= stretch;
        b *= stretch;
        reach *= stretch;
    }
    reach = std::clamp(reach, std::abs(a - b) + 1e-12, a + b);

    // Bend plane from the pole; a pole on the line keeps the rest plane turned with the parent.
    Vec3 side;
    if (auto s = poleSide(root, dir, pole)) {
        side = *s;
    } else {
        const Mat3 turn = parent ? parent->rotation() * glm::transpose(c.restParentRotation) : Mat3(1.0);
        const Vec3 normal = turn * c.restBoneFrames[0][2];
        side = glm::normalize(glm::cross(normal, dir));
    }
    Vec3 normal = glm::normalize(glm::cross(dir, side));
    const double cosA = std::clamp((a * a + reach * reach - b * b) / (2.0 * a * reach), -1.0, 1.0);
    const double sinA = std::sqrt(std::max(0.0, 1.0 - cosA * cosA));

    Vec3 positions[4];
    positions[0] = root;
    positions[1] = root + dir * (a * cosA) + side * (a * sinA);
    positions[joints - 1] = root + dir * reach;
    // Pin: the middle joint goes to the pin by its share; the bones reach from
    // it (lengthening or shortening), in the plane through the pinned joint.
    const double pin = c.pinChannel >= 0 && c.targets.size() == 3 ? std::clamp(pose[c.pinChannel], 0.0, 1.0) : 0.0;
    if (pin > 0.0) {
        positions[1] = glm::mix(positions[1], world[c.targets[2]].translation, pin);
        const Vec3 pinned = glm::cross(positions[1] - root, positions[joints - 1] - root);
        if (glm::length(pinned) > 1e-9 && glm::dot(pinned, normal) > 0.0)
            normal = glm::normalize(pinned);
    }
    if (joints == 4) {
        const Vec3 bone = positions[3] - positions[1];
        const Mat3 virtualBone = frameFromAxes(bone, normal);
        positions[2] = positions[1] + virtualBone * c.midOffset * (glm::length(bone) / c.lengths[3]);
    }
    // Volume: each bone, stretched by s, is scaled across by s^(power * volume).
    const double volume = c.volumeChannel >= 0 ? std::clamp(pose[c.volumeChannel], 0.0, 1.0) : 0.0;
    for (std::size_t i = 0; i + 1 < joints; ++i) {
        const Vec3 bone = positions[i + 1] - positions[i];
        const Mat3 frame = frameFromAxes(bone, normal);
        const Mat3 r = frame * glm::transpose(c.restBoneFrames[i]) * c.restRotations[i];
        Vec3 scales(scale);
        if (volume > 0.0) {
            const double rest = c.lengths[i] * scale;
            const double across = std::pow(std::max(glm::length(bone) / rest, 1e-6), c.volumePower * volume);
            for (int k = 0; k < 3; ++k)
                if (k != c.boneAxes[i])
                    scales[k] *= across;
        }
        world[c.driven[i]] = compose(r, scales, positions[i]);
    }
    const Mat3 effector = world[c.targets[0]].rotation();
    const Mat3 last = effector * glm::transpose(c.restEffectorRotation) * c.restRotations.back();
    world[c.driven.back()] = compose(last, Vec3(scale), positions[joints - 1]);
}

} // namespace rs::eval
