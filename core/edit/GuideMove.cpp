#include "edit/GuideMove.h"

#include "eval/Channels.h"

#include <algorithm>
#include <cmath>

namespace rs::edit {

using model::GuideDocument;
using model::JointId;

namespace {

class SetJointTransforms final : public Command {
public:
    struct JointChange {
        model::InstanceId owner;
        JointId joint;
        Transform from, to;
    };
    SetJointTransforms(std::vector<JointChange> changes, std::string what) : m_changes(std::move(changes)), m_what(std::move(what)) {}
    std::string text() const override { return m_what; }
    void redo(GuideDocument& d) override
    {
        for (const JointChange& c : m_changes) d.instance(c.owner)->joint(c.joint)->local = c.to;
    }
    void undo(GuideDocument& d) override
    {
        for (const JointChange& c : m_changes) d.instance(c.owner)->joint(c.joint)->local = c.from;
    }
    Change change() const override
    {
        Change out = Change::of(ChangeKind::Joints);
        for (const JointChange& c : m_changes) {
            out.joints.push_back(c.joint);
            if (std::find(out.instances.begin(), out.instances.end(), c.owner) == out.instances.end())
                out.instances.push_back(c.owner);
        }
        return out;
    }

private:
    std::vector<JointChange> m_changes;
    std::string m_what;
};

Mat4 withTranslation(Mat3 linear, const Vec3& t)
{
    Mat4 m(linear);
    m[3] = Vec4(t, 1.0);
    return m;
}

} // namespace

// A local matrix as the document's translate / rotate (XYZ, degrees) / scale,
// with float noise rounded off so a joint moved along one axis keeps clean values.
Transform localTransformOf(const Mat4& local)
{
    Transform out;
    Quat rotation;
    decompose(local, out.translate, rotation, out.scale);
    out.rotateDegrees = eval::eulerDegrees(glm::mat3_cast(rotation), model::RotateOrder::Xyz);
    for (Vec3* v : {&out.translate, &out.rotateDegrees, &out.scale})
        for (int i = 0; i < 3; ++i) {
            const double r = std::round((*v)[i] * 1e6) / 1e6;
            if (std::abs((*v)[i] - r) < 1e-9) (*v)[i] = r == 0.0 ? 0.0 : r;
        }
    return out;
}

Transform localFor(const GuideDocument& document, JointId joint, const Mat4& world)
{
    return localTransformOf(glm::inverse(document.parentWorldMatrix(joint)) * world);
}

Status setJointTransforms(History& history, const std::vector<JointTransform>& transforms, const std::string& what)
{
    const GuideDocument& d = history.document();
    std::vector<SetJointTransforms::JointChange> changes;
    for (const JointTransform& t : transforms) {
        const model::TemplateInstance* owner = d.ownerOf(t.joint);
        if (!owner)
            return Status::refused("no joint with id " + std::to_string(t.joint), Subject::ofJoint(model::kNoId, t.joint));
        const Transform before = owner->joint(t.joint)->local;
        if (!(before == t.local))
            changes.push_back({owner->id, t.joint, before, t.local});
    }
    if (changes.empty())
        return Status::refused("the joints did not move");
    history.push(std::make_unique<SetJointTransforms>(std::move(changes), what));
    return {};
}

JointId mirrorJointOf(const GuideDocument& document, JointId joint)
{
    const model::TemplateInstance* owner = document.ownerOf(joint);
    if (!owner)
        return model::kNoId;
    const std::string name = model::mirroredName(owner->name);
    const model::TemplateInstance* other = name.empty() ? nullptr : document.instanceNamed(name);
    if (!other || other->joints.size() != owner->joints.size())
        return model::kNoId;
    const auto index = std::size_t(owner->joint(joint) - owner->joints.data());
    return other->joints[index].id;
}

Mat4 mirroredAcrossX(const Mat4& world)
{
    Mat4 reflect(1.0);
    reflect[0][0] = -1.0;
    return reflect * world * reflect;
}

bool isBelow(const GuideDocument& document, JointId joint, JointId ancestor)
{
    for (std::size_t guard = 0; guard < 100000; ++guard) {
        const model::TemplateInstance* owner = document.ownerOf(joint);
        if (!owner)
            return false;
        const model::GuideJoint* j = owner->joint(joint);
        joint = j->parent != model::kNoId ? j->parent : owner->parentJoint;
        if (joint == model::kNoId)
            return false;
        if (joint == ancestor)
            return true;
    }
    return false;
}

GuideDrag::GuideDrag(const GuideDocument& document, JointId lead, std::vector<JointId> joints, GuideDragOptions options)
    : m_leadStart(document.jointWorldMatrix(lead)), m_options(options)
{
    if (std::find(joints.begin(), joints.end(), lead) == joints.end())
        joints.push_back(lead);
    std::vector<std::pair<JointId, JointId>> candidates; // joint, the joint it mirrors (or kNoId)
    for (JointId j : joints)
        if (document.joint(j)) candidates.emplace_back(j, model::kNoId);
    if (options.symmetric)
        for (JointId j : joints) {
            const JointId twin = mirrorJointOf(document, j);
            const bool taken = std::any_of(candidates.begin(), candidates.end(), [&](const auto& c) { return c.first == twin; });
            if (twin != model::kNoId && !taken) candidates.emplace_back(twin, j);
        }
    for (const auto& candidate : candidates) {
        const JointId joint = candidate.first, mirrorOf = candidate.second; // not a structured binding: clang 14 cannot capture one
        const bool follows = std::any_of(candidates.begin(), candidates.end(),
                                         [&](const auto& other) { return isBelow(document, joint, other.first); });
        if (follows)
            continue;
        const Mat4 sourceStart = mirrorOf != model::kNoId ? document.jointWorldMatrix(mirrorOf) : Mat4(1.0);
        m_moved.push_back({joint, document.jointWorldMatrix(joint), document.parentWorldMatrix(joint), mirrorOf, sourceStart});
        m_start.push_back({joint, document.joint(joint)->local});
    }
}

std::vector<JointTransform> GuideDrag::transformsFor(const Mat4& leadWorld) const
{
    Vec3 target = translationOf(leadWorld);
    const Vec3 start = translationOf(m_leadStart);
    if (m_options.snapStep > 0.0 && glm::length(target - start) > 1e-12)
        target = glm::round(target / m_options.snapStep) * m_options.snapStep;
    const Vec3 delta = target - start;
    const Mat3 linear = Mat3(leadWorld) * glm::inverse(Mat3(m_leadStart));
    auto moved = [&](const Mat4& startWorld) { return withTranslation(linear * Mat3(startWorld), translationOf(startWorld) + delta); };

    std::vector<JointTransform> out;
    for (const Moved& m : m_moved) {
        const Mat4 world = m.mirrorOf == model::kNoId ? moved(m.startWorld) : mirroredAcrossX(moved(m.sourceStart));
        out.push_back({m.joint, localTransformOf(glm::inverse(m.parentWorld) * world)});
    }
    return out;
}

} // namespace rs::edit
