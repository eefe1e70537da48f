// EditorSession's guide authoring: guide-joint selection, gizmo drags on guide
// joints, duplicating and re-hanging instances, the reference model (shapes
// and CVs: ShapeSession.cpp). A topic
// file of the session, like PoseSession.cpp.
#include "EditorSession.h"

#include "io/ReferenceModel.h"

#include <algorithm>
#include <filesystem>
#include <utility>

namespace rs::app {

void EditorSession::selectGuideJoints(const std::vector<model::JointId>& joints, bool add)
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

model::JointId EditorSession::gizmoJoint() const
{
    if (m_selection.joint != model::kNoId && m_document.joint(m_selection.joint))
        return m_selection.joint;
    const model::TemplateInstance* instance = m_document.instance(m_selection.instance);
    return instance && !instance->joints.empty() ? instance->joints.front().id : model::kNoId;
}

void EditorSession::beginGuideDrag(model::JointId lead)
{
    if (!m_document.joint(lead))
        return;
    std::vector<model::JointId> joints = m_selection.joints;
    if (joints.empty())
        joints.push_back(lead);
    m_guideDrag.emplace(m_document, lead, joints, m_guideDragOptions);
    m_guideDragLast.clear();
}

void EditorSession::previewJoints(const std::vector<edit::JointTransform>& transforms)
{
    for (const edit::JointTransform& t : transforms)
        if (model::TemplateInstance* owner = m_document.instance(m_document.ownerOf(t.joint)->id))
            owner->joint(t.joint)->local = t.local;
    emit guidePreviewed();
}

void EditorSession::dragGuideTo(const Mat4& leadWorld)
{
    if (!m_guideDrag)
        return;
    // The preview writes the document directly; endGuideDrag puts the start
    // back and records the whole drag as one command.
    m_guideDragLast = m_guideDrag->transformsFor(leadWorld);
    previewJoints(m_guideDragLast);
}

QString EditorSession::endGuideDrag(const QString& what)
{
    if (!m_guideDrag)
        return {};
    previewJoints(m_guideDrag->start());
    const auto transforms = std::move(m_guideDragLast);
    const bool moved = !transforms.empty() && transforms != m_guideDrag->start(); // a click on a handle moves nothing
    m_guideDrag.reset();
    m_guideDragLast.clear();
    return moved ? messageOf(edit::setJointTransforms(m_history, transforms, what.toStdString())) : QString();
}

QString EditorSession::duplicateInstances(const std::vector<model::InstanceId>& ids)
{
    std::vector<model::InstanceId> copies;
    if (auto error = edit::duplicateInstances(m_history, ids, &copies))
        return QString::fromStdString(*error);
    select(Selection::ofInstance(copies.back()));
    return {};
}

QString EditorSession::reparentInstance(model::InstanceId id, model::JointId hookJoint)
{
    return messageOf(edit::reparentInstance(m_history, id, hookJoint));
}

namespace {

std::optional<std::vector<glm::vec3>> readReference(const std::string& path, Diagnostics& diagnostics)
{
    auto model = io::loadReferenceModel(path);
    diagnostics = model.diagnostics();
    return model ? std::optional(model.take().triangles) : std::nullopt;
}

} // namespace

bool EditorSession::loadReference(const QString& path, Diagnostics& diagnostics)
{
    if (path.isEmpty())
        return !edit::setReferenceModel(m_history, {}); // the listener clears the view
    const std::string absolute = std::filesystem::absolute(path.toStdString()).lexically_normal().string();
    auto triangles = readReference(absolute, diagnostics);
    if (!triangles)
        return false; // the shown model and the document stay
    m_reference = std::move(*triangles);
    m_referencePath = absolute;
    emit referenceChanged();
    return !edit::setReferenceModel(m_history, absolute);
}

void EditorSession::syncReference()
{
    if (m_document.referenceModel == m_referencePath)
        return;
    m_referencePath = m_document.referenceModel;
    m_reference.clear();
    if (!m_referencePath.empty()) {
        Diagnostics diagnostics;
        if (auto triangles = readReference(m_referencePath, diagnostics))
            m_reference = std::move(*triangles);
        else
            diagnostics.insert(diagnostics.begin(), makeError({m_referencePath, 0, 0},
                                                              "the guide's reference model could not be loaded (the guide keeps its path)"));
        if (!diagnostics.empty())
            emit diagnosticsReported(diagnostics);
    }
    emit referenceChanged();
}

} // namespace rs::app
