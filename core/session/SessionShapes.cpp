// Session's shape editing in Guide mode: the gizmo on a controller's whole
// shape, and CV mode (control points one by one). A drag is one history
// transaction of the instance's shape edit; each preview rebuilds the rig, so
// a mirrored branch follows under the cursor.
#include "session/Session.h"

#include "edit/GuideEdits.h"

#include <algorithm>
#include <utility>

namespace rs::session {

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

// The stored edit of an authored controller (its instance's authored side: branch "").
model::ShapeEdit shapeEditOf(const model::GuideDocument& document, const NodeKey& authored)
{
    const auto record = document.overrides.find(NodeKey{authored.instance, {}, authored.tag});
    return record == document.overrides.end() || !record->second.shape ? model::ShapeEdit{} : record->second.shape->edit;
}

} // namespace

std::optional<Mat4> Session::shapeFrame(model::RigNodeIndex node) const
{
    const auto source = m_rig ? shapeSourceOf(*m_rig, node) : std::nullopt;
    if (!source || !m_document.instance(source->authored->key.instance))
        return std::nullopt;
    const model::ShapeEdit edit = shapeEditOf(m_document, source->authored->key);
    const Mat4 m = edit.transform.matrix();
    // A mirrored copy shows the edit reflected: m' = R m R in its own space.
    return m_rig->nodes[node].worldMatrix * source->reflection * m * source->reflection;
}

void Session::beginShapeDrag(model::RigNodeIndex node)
{
    if (!shapeFrame(node))
        return;
    const ShapeSource source = *shapeSourceOf(*m_rig, node);
    const model::TemplateInstance* owner = m_document.instance(source.authored->key.instance);
    const std::string& tag = source.authored->key.tag;
    const model::ShapeEdit start = shapeEditOf(m_document, source.authored->key);
    // The node's world matrix without the edit's transform: where the gizmo's
    // frame maps from (the rebuilt rig keeps the node where it is).
    m_shapeDrag = ShapeDrag{node, owner->id, tag, start, m_rig->nodes[node].worldMatrix, source.reflection};
    m_history.begin("Edit shape " + tag);
}

void Session::dragShapeTo(const Mat4& world)
{
    if (!m_shapeDrag || !m_history.inTransaction())
        return;
    // The new edit seen from the authored side.
    const Mat4& r = m_shapeDrag->reflection;
    model::ShapeEdit now = m_shapeDrag->start;
    now.transform = edit::localTransformOf(r * (glm::inverse(m_shapeDrag->nodeWorld) * world) * r);
    replacePreview([&] {
        if (!(now == m_shapeDrag->start))
            edit::setShapeEdit(m_history, m_shapeDrag->instance, m_shapeDrag->tag, now);
    });
}

Status Session::endShapeDrag()
{
    if (!m_shapeDrag)
        return {};
    m_shapeDrag.reset();
    m_history.commit(); // the shape edit's own name: "Edit shape ctrls.ik of arm"
    return {};
}

void Session::setCvMode(bool on)
{
    m_cvMode = on;
    if (!on)
        m_selection.cvs.clear();
    else if (!m_rig || m_rigStale)
        build(); // CVs are the built shapes'
    emitChange(Change::of(ChangeKind::Mode | ChangeKind::Selection));
}

void Session::selectCvs(const std::vector<model::CurveCv>& cvs, bool add)
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

std::optional<edit::CvDrag> Session::selectedCvDrag() const
{
    if (!m_cvMode || m_selection.cvs.empty() || !m_rig || m_rigStale)
        return std::nullopt;
    auto drag = edit::CvDrag::begin(m_document, *m_rig, m_selection.cvs);
    return drag ? std::optional(drag.take()) : std::nullopt;
}

std::optional<Mat4> Session::cvFrame() const
{
    if (m_cvDrag) // during a drag the frame is where the drag began
        return m_cvDrag->change * m_cvDrag->drag.frame();
    const auto drag = selectedCvDrag();
    return drag ? std::optional(drag->frame()) : std::nullopt;
}

void Session::beginCvDrag()
{
    auto drag = selectedCvDrag();
    if (!drag)
        return;
    m_cvDrag.emplace(CvDragState{std::move(*drag), Mat4(1.0)});
    m_history.begin("Move CVs");
}

void Session::dragCvsTo(const Mat4& world)
{
    if (!m_cvDrag || !m_history.inTransaction())
        return;
    m_cvDrag->change = world * glm::inverse(m_cvDrag->drag.frame());
    replacePreview([&] {
        if (m_cvDrag->change != Mat4(1.0))
            m_cvDrag->drag.commit(m_history, m_cvDrag->change);
    });
}

Status Session::endCvDrag(const std::string& verb)
{
    if (!m_cvDrag)
        return {};
    const CvDragState state = *std::exchange(m_cvDrag, std::nullopt);
    if (state.change == Mat4(1.0)) {
        m_history.rollback();
        return {};
    }
    // The step is named as CvDrag names it ("Move 4 CVs of ctrls.ik"): the
    // last preview is replaced by the same edit under that name.
    Status committed;
    replacePreview([&] { committed = state.drag.commit(m_history, state.change, verb); });
    m_history.commit();
    return committed;
}

} // namespace rs::session
