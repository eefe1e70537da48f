#include "io/BoneInference.h"

#include "base/Math.h"

namespace rs::io {

std::vector<int> connectedMovingJoints(const ExportScene& scene)
{
    const std::size_t n = scene.joints.size();
    std::vector<bool> translated(n, false);
    for (const ExportClip& clip : scene.clips)
        for (const ExportTrack& track : clip.tracks)
            if (track.isJoint() && ((track.animated | track.held) & kTranslationChannel))
                translated[std::size_t(track.node)] = true;
    std::vector<double> meanChildDistance(n, 0.0);
    std::vector<int> childCount(n, 0);
    for (const ExportJoint& joint : scene.joints)
        if (joint.parent >= 0) {
            meanChildDistance[std::size_t(joint.parent)] += glm::length(translationOf(joint.bindLocal));
            ++childCount[std::size_t(joint.parent)];
        }
    std::vector<int> out;
    for (std::size_t j = 0; j < n; ++j) {
        const int parent = scene.joints[j].parent;
        if (parent < 0 || !translated[j])
            continue;
        const auto p = std::size_t(parent);
        const double size = std::max(0.01, meanChildDistance[p] / childCount[p]);
        const Mat4& bind = scene.joints[p].bindWorld;
        const Vec3 yAxis = glm::normalize(Vec3(bind[1]));
        const Vec3 tail = translationOf(bind) + yAxis * size;
        if (glm::length(tail - translationOf(scene.joints[j].bindWorld)) <= 1e-6 * size)
            out.push_back(int(j));
    }
    return out;
}

} // namespace rs::io
