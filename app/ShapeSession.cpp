// EditorSession's shape editing in Guide mode: the gizmo on a controller's
// whole shape, and CV mode (control points one by one). Both preview on the
// built curves and land as one undo step of the instance's shape edit; the
// rig is rebuilt at once (shape edits cannot break a build), so a mirrored
// branch follows. A topic file of the session, like GuideSession.cpp.
#include "EditorSession.h"

#include "edit/GuideMove.h"

#include <algorithm>
#include <utility>

namespace rs::app {

namespace {

// Whose shape edit a controller's curves show: the authored node (the twin of
// a mirrored branch copy) and the reflection between the two controller spaces.
struct ShapeSource {
    const model::RigNode* authored = nullptr;
    Mat4 reflection{1.0};
};

std::optional<ShapeSource> shapeSourceOf(const model::Rig& rig, model::RigNodeIndex node)
{
    if (node >= rig.nodes.size() || rig.nodes[node].kind != model::RigNodeKind::Controller)
        return std::nullopt;
    const model::RigNode& n = rig.nodes[node];
    if (!n.shapeFromTwin)
        return ShapeSource{&n, Mat4(1.0)};
    if (n.twin == model::kNoNode || n.mirrorPlane < 0)
        return std::nullopt;
    ShapeSource source{&rig.nodes[n.twin], Mat4(1.0)};
    source.reflection[n.mirrorPlane][n.mirrorPlane] = -1.0;
    return source;
}

const std::string& tagOf(const model::RigNode& node) { return node.key.tag; }

} // namespace

std::optional<Mat4> EditorSession::shapeFrame(model::RigNodeIndex node) const
{
    const auto source = m_rig ? shapeSourceOf(*m_rig, node) : std::nullopt;
    if (!source || !m_document.instance(source->authored->key.instance))
        return std::nullopt;
    const model::TemplateInstance* owner = m_document.instance(source->authored->key.instance);
    const auto edit = owner->shapes.find(tagOf(*source->authored));
    const Mat4 m = edit == owner->shapes.end() ? Mat4(1.0) : edit->second.transform.matrix();
    // A mirrored copy shows the edit reflected: m' = R m R in its own space.
    return m_rig->nodes[node].worldMatrix * source->reflection * m * source->reflection;
}

void EditorSession::beginShapeDrag(model::RigNodeIndex node)
{
    if (!shapeFrame(node))
        return;
    const ShapeSource source = *shapeSourceOf(*m_rig, node);
    const model::TemplateInstance* owner = m_document.instance(source.authored->key.instance);
    const std::string tag = tagOf(*source.authored);
    const auto edit = owner->shapes.find(tag);
    const model::ShapeEdit start = edit == owner->shapes.end() ? model::ShapeEdit{} : edit->second;
    m_shapeDrag = ShapeDrag{node,  owner->id, tag, start, start, m_rig->nodes[node].worldMatrix, source.reflection,
                            m_rig->nodes[node].curves};
}

void EditorSession::dragShapeTo(const Mat4& world)
{
    if (!m_shapeDrag)
        return;
    // The new edit seen from the authored side; the preview applies the change
    // from the edit the curves were built with, on the dragged side.
    const Mat4& r = m_shapeDrag->reflection;
    const Mat4 dragged = glm::inverse(m_shapeDrag->nodeWorld) * world;
    m_shapeDrag->now.transform = edit::localTransformOf(r * dragged * r);
    const Mat4 change = dragged * glm::inverse(r * m_shapeDrag->start.transform.matrix() * r);
    auto& curves = m_rig->nodes[m_shapeDrag->node].curves;
    curves = m_shapeDrag->curves;
    for (auto& curve : curves)
        curve.transform(change);
    emit guidePreviewed();
}

QString EditorSession::endShapeDrag()
{
    if (!m_shapeDrag)
        return {};
    const ShapeDrag drag = *std::exchange(m_shapeDrag, std::nullopt);
    m_rig->nodes[drag.node].curves = drag.curves;
    if (drag.now == drag.start)
        return {};
    return messageOf(edit::setShapeEdit(m_history, drag.instance, drag.tag, drag.now));
}

void EditorSession::setCvMode(bool on)
{
    m_cvMode = on;
    if (!on)
        m_selection.cvs.clear();
    else if (!m_rig || m_rigStale)
        build(); // CVs are the built shapes'
    emit selectionChanged();
}

void EditorSession::selectCvs(const std::vector<model::CurveCv>& cvs, bool add)
{
    if (!m_rig)
        return;
    Selection s = m_selection;
    // One controller's CVs at a time: the current one when the pick touches it.
    model::RigNodeIndex node = model::kNoNode;
    for (const model::CurveCv& cv : cvs)
        if (cv.node == s.node) node = s.node;
    if (node == model::kNoNode && !cvs.empty())
        node = cvs.front().node;
    if (!add || node != s.node)
        s.cvs.clear();
    if (node != model::kNoNode && node < m_rig->nodes.size()) {
        s.node = node;
        if (std::find(s.nodes.begin(), s.nodes.end(), node) == s.nodes.end())
            s.nodes.push_back(node);
        s.instance = m_rig->nodes[node].owner;
        s.joint = model::kNoId;
        s.joints.clear();
    }
    // With Shift, picking CVs that are all selected already deselects them (a
    // click toggles, as Maya's Shift); otherwise they are added.
    const bool toggle = !cvs.empty() && std::all_of(cvs.begin(), cvs.end(), [&](const model::CurveCv& cv) {
        return cv.node != node || std::find(s.cvs.begin(), s.cvs.end(), cv) != s.cvs.end();
    });
    for (const model::CurveCv& cv : cvs) {
        if (cv.node != node)
            continue;
        const auto it = std::find(s.cvs.begin(), s.cvs.end(), cv);
        if (add && toggle && it != s.cvs.end())
            s.cvs.erase(it);
        else if (it == s.cvs.end())
            s.cvs.push_back(cv);
    }
    select(s);
}

std::optional<edit::CvDrag> EditorSession::selectedCvDrag() const
{
    if (!m_cvMode || m_selection.cvs.empty() || !m_rig || m_rigStale)
        return std::nullopt;
    auto drag = edit::CvDrag::begin(m_document, *m_rig, m_selection.cvs);
    return drag ? std::optional(drag.take()) : std::nullopt;
}

std::optional<Mat4> EditorSession::cvFrame() const
{
    const auto drag = selectedCvDrag();
    return drag ? std::optional(drag->frame()) : std::nullopt;
}

void EditorSession::beginCvDrag()
{
    auto drag = selectedCvDrag();
    if (!drag)
        return;
    m_cvDrag.emplace(CvDragState{std::move(*drag), Mat4(1.0), {}});
    for (const auto& [node, curves] : m_cvDrag->drag.previewFor(Mat4(1.0)))
        m_cvDrag->original[node] = m_rig->nodes[node].curves;
}

void EditorSession::dragCvsTo(const Mat4& world)
{
    if (!m_cvDrag)
        return;
    m_cvDrag->change = world * glm::inverse(m_cvDrag->drag.frame());
    for (auto& [node, curves] : m_cvDrag->drag.previewFor(m_cvDrag->change))
        m_rig->nodes[node].curves = std::move(curves);
    emit guidePreviewed();
}

QString EditorSession::endCvDrag(const QString& verb)
{
    if (!m_cvDrag)
        return {};
    const CvDragState state = *std::exchange(m_cvDrag, std::nullopt);
    for (const auto& [node, curves] : state.original)
        m_rig->nodes[node].curves = curves;
    const auto error = state.drag.commit(m_history, state.change, verb.toStdString());
    emit guidePreviewed();
    return messageOf(error);
}

} // namespace rs::app
