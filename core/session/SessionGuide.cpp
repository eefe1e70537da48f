// Session's guide authoring: guide-joint selection and gizmo drags on guide
// joints. A drag is one history transaction: each preview replaces the last
// (the rig is rebuilt live), the end commits one undo step or, when nothing
// moved, rolls back.
#include "session/Session.h"

#include "edit/GuideEdits.h"

#include <algorithm>

namespace rs::session {

std::vector<MirroredGuideJoint> Session::mirroredGuideJoints() const
{
    return session::mirroredGuideJoints(m_document, *m_templates);
}

void Session::selectGuideJoints(const std::vector<model::JointId>& joints, bool add)
{
    Selection s = add ? m_selection : Selection{};
    s.node = model::kNoNode;
    s.nodes.clear();
    s.cvs.clear();
    if (add && s.joints.empty() && s.joint != model::kNoId)
        s.joints.push_back(s.joint);
    for (model::JointId joint : joints) {
        if (!m_document.joint(joint))
            continue;
        const auto it = std::find(s.joints.begin(), s.joints.end(), joint);
        if (add && joints.size() == 1 && it != s.joints.end())
            s.joints.erase(it); // Shift+click toggles
        else if (it == s.joints.end())
            s.joints.push_back(joint);
    }
    s.joint = s.joints.empty() ? model::kNoId : s.joints.back();
    s.instance = s.joint != model::kNoId ? m_document.ownerOf(s.joint)->id : (add ? s.instance : model::kNoId);
    select(s);
}

model::JointId Session::gizmoJoint() const
{
    if (m_selection.joint != model::kNoId && m_document.joint(m_selection.joint))
        return m_selection.joint;
    const model::TemplateInstance* instance = m_document.instance(m_selection.instance);
    return instance && !instance->joints.empty() ? instance->joints.front().id : model::kNoId;
}

void Session::beginGuideDrag(model::JointId lead)
{
    if (!m_document.joint(lead))
        return;
    std::vector<model::JointId> joints = m_selection.joints;
    if (joints.empty())
        joints.push_back(lead);
    m_guideDrag.emplace(m_document, lead, joints, m_guideDragOptions);
    m_history.begin("Move guide joints");
}

void Session::dragGuideTo(const Mat4& leadWorld)
{
    if (!m_guideDrag || !m_history.inTransaction())
        return;
    const auto transforms = m_guideDrag->transformsFor(leadWorld);
    replacePreview([&] {
        if (transforms != m_guideDrag->start())
            edit::setJointTransforms(m_history, transforms, "Move guide joints");
    });
}

Status Session::endGuideDrag(const std::string& what)
{
    if (!m_guideDrag)
        return {};
    m_guideDrag.reset();
    m_history.commit(what); // a drag that moved nothing records nothing
    return {};
}

Status Session::moveGuideJoints(model::JointId lead, const Mat4& leadWorld, const std::string& what)
{
    if (!m_document.joint(lead))
        return Status::refused("no guide joint with id " + std::to_string(lead), Subject::ofJoint(model::kNoId, lead));
    if (m_history.inTransaction())
        return Status::refused("finish the drag first", Subject::ofJoint(m_document.ownerOf(lead)->id, lead));
    std::vector<model::JointId> joints = m_selection.joints;
    if (std::find(joints.begin(), joints.end(), lead) == joints.end())
        joints = {lead};
    edit::GuideDragOptions options = m_guideDragOptions;
    options.snapStep = 0.0; // a typed value is meant exactly
    const edit::GuideDrag move(m_document, lead, joints, options);
    return edit::setJointTransforms(m_history, move.transformsFor(leadWorld), what);
}

} // namespace rs::session
