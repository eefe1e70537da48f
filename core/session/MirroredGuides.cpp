#include "session/MirroredGuides.h"

#include "rigging/BranchStage.h"

namespace rs::session {

std::vector<MirroredGuideJoint> mirroredGuideJoints(const model::GuideDocument& guide,
                                                    const templates::TemplateRegistry& templates)
{
    Diagnostics ignored; // the build reports branch problems
    const rigging::ExpandedGuide expanded = rigging::expandBranches(guide, templates, ignored);
    std::vector<MirroredGuideJoint> out;
    for (const auto& instance : expanded.document.instances()) {
        const auto copy = expanded.copies.find(instance.id);
        if (copy == expanded.copies.end() || copy->second.mirror == Mat4(1.0))
            continue;
        const Mat4& mirror = copy->second.mirror;
        auto placed = [&](model::JointId id) { return Vec3(mirror * Vec4(translationOf(expanded.document.jointWorldMatrix(id)), 1.0)); };
        for (const auto& joint : instance.joints) {
            MirroredGuideJoint j;
            j.owner = copy->second.original;
            j.position = placed(joint.id);
            const model::JointId parent = joint.parent != model::kNoId ? joint.parent : instance.parentJoint;
            if (parent != model::kNoId) {
                j.hasParent = true;
                const auto parentCopy = expanded.copies.find(expanded.document.ownerOf(parent)->id);
                const Mat4& parentMirror = parentCopy != expanded.copies.end() ? parentCopy->second.mirror : Mat4(1.0);
                j.parentPosition = Vec3(parentMirror * Vec4(translationOf(expanded.document.jointWorldMatrix(parent)), 1.0));
            }
            out.push_back(j);
        }
    }
    return out;
}

} // namespace rs::session
