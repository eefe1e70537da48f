#include "skin/SkinBones.h"

#include "model/Skeleton.h"

#include <algorithm>

namespace rs::skin {

Result<std::vector<SkinBone>> skinBones(const model::Rig& rig)
{
    auto skeleton = model::extractSkeleton(rig);
    if (!skeleton)
        return Result<std::vector<SkinBone>>::failure(skeleton.takeDiagnostics());
    const auto& joints = skeleton->joints;
    std::vector<SkinBone> bones(joints.size());
    for (std::size_t j = 0; j < joints.size(); ++j) {
        bones[j].node = joints[j].node;
        bones[j].key = rig.nodes[joints[j].node].key;
        bones[j].head = translationOf(joints[j].bindWorld);
        bones[j].parent = joints[j].parent;
    }
    for (std::size_t j = 0; j < joints.size(); ++j)
        if (joints[j].parent >= 0)
            bones[std::size_t(joints[j].parent)].tails.push_back(bones[j].head);
    // A root with one child is where the rig stands (world.character's root on
    // the ground), not a bone of the body: its segment up to the hips would run
    // between the legs and take the inner thighs (the fitted human did).
    for (SkinBone& bone : bones)
        if (bone.parent < 0 && bone.tails.size() == 1)
            bone.tails.clear();
    for (std::size_t j = 0; j < joints.size(); ++j) {
        if (!bones[j].tails.empty() || joints[j].parent < 0)
            continue;
        const Vec3 along = bones[j].head - bones[std::size_t(joints[j].parent)].head;
        if (glm::length(along) > 1e-9)
            bones[j].tails.push_back(bones[j].head + 0.5 * along);
    }
    return bones;
}

Vec3 nearestPointOn(const SkinBone& bone, const Vec3& p)
{
    Vec3 best = bone.head;
    double bestDistance = glm::dot(p - bone.head, p - bone.head); // squared
    for (const Vec3& tail : bone.tails) {
        const Vec3 d = tail - bone.head;
        const double t = std::clamp(glm::dot(p - bone.head, d) / std::max(glm::dot(d, d), 1e-30), 0.0, 1.0);
        const Vec3 q = bone.head + t * d;
        const double distance = glm::dot(p - q, p - q);
        if (distance < bestDistance) {
            bestDistance = distance;
            best = q;
        }
    }
    return best;
}

} // namespace rs::skin
