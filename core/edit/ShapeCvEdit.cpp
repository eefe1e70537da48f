#include "edit/ShapeCvEdit.h"

#include <algorithm>
#include <cmath>

namespace rs::edit {

namespace {

Result<CvDrag> failure(const std::string& message, Subject subject = {}) { return Result<CvDrag>::refused(message, std::move(subject)); }

// Offsets closer to zero than float noise are dropped so files keep clean values.
Vec3 cleaned(Vec3 v)
{
    for (int k = 0; k < 3; ++k)
        if (std::abs(v[k]) < 1e-12) v[k] = 0.0;
    return v;
}

} // namespace

Vec3 cvWorldPosition(const model::Rig& rig, const model::CurveCv& cv)
{
    const model::RigNode& node = rig.nodes.at(cv.node);
    return Vec3(node.worldMatrix * Vec4(node.curves.at(cv.curve).cvs.at(cv.cv), 1.0));
}

Result<CvDrag> CvDrag::begin(const model::GuideDocument& document, const model::Rig& rig, std::vector<model::CurveCv> cvs)
{
    if (cvs.empty())
        return failure("no CVs selected");
    const model::RigNodeIndex index = cvs.front().node;
    if (index >= rig.nodes.size())
        return failure("CVs can only be edited on a controller's shape");
    const model::RigNode& node = rig.nodes[index];
    if (node.kind != model::RigNodeKind::Controller)
        return failure("CVs can only be edited on a controller's shape", Subject::ofNode(node.key));
    for (const model::CurveCv& cv : cvs) {
        if (cv.node != index)
            return failure("the selected CVs are on several controllers; edit one controller's shape at a time",
                           Subject::ofShape(node.key));
        if (cv.curve < 0 || std::size_t(cv.curve) >= node.curves.size() || cv.cv < 0 ||
            std::size_t(cv.cv) >= node.curves[cv.curve].cvs.size())
            return failure("'" + node.name + "' has no CV " + std::to_string(cv.cv) + " on curve " + std::to_string(cv.curve),
                           Subject::ofShape(node.key));
    }
    std::sort(cvs.begin(), cvs.end());
    cvs.erase(std::unique(cvs.begin(), cvs.end()), cvs.end());

    CvDrag d;
    d.m_onCopy = node.shapeFromTwin;
    const bool paired = node.twin != model::kNoNode && node.mirrorPlane >= 0 &&
                        (node.shapeFromTwin || rig.nodes[node.twin].shapeFromTwin);
    if (d.m_onCopy && !paired)
        return failure("the shape of '" + node.name + "' is mirrored from the other side; edit its CVs there",
                       Subject::ofShape(node.key));
    if (paired) {
        d.m_twin = node.twin;
        d.m_reflection[node.mirrorPlane][node.mirrorPlane] = -1.0;
        d.m_twinCurves = rig.nodes[node.twin].curves;
    }
    const model::RigNode& authored = d.m_onCopy ? rig.nodes[node.twin] : node;
    const model::TemplateInstance* instance = document.instance(authored.key.instance);
    if (!instance)
        return failure("'" + node.name + "' belongs to no template instance of the guide", Subject::ofNode(node.key));
    d.m_instance = instance->id;
    d.m_tag = authored.key.tag;
    if (const auto record = document.overrides.find(NodeKey{instance->id, {}, d.m_tag});
        record != document.overrides.end() && record->second.shape)
        d.m_start = record->second.shape->edit;
    d.m_cvs = std::move(cvs);
    d.m_nodeWorld = node.worldMatrix;
    d.m_curves = node.curves;
    Vec3 centroid(0.0);
    for (const model::CurveCv& cv : d.m_cvs) {
        d.m_startWorld.push_back(cvWorldPosition(rig, cv));
        centroid += d.m_startWorld.back();
    }
    Vec3 t, s;
    Quat q;
    decompose(node.worldMatrix, t, q, s);
    d.m_frame = translationMatrix(centroid / double(d.m_cvs.size())) * glm::mat4_cast(q);
    return d;
}

std::vector<Vec3> CvDrag::controllerDeltas(const Mat4& change) const
{
    const Mat4 toController = glm::inverse(m_nodeWorld);
    std::vector<Vec3> out;
    for (std::size_t i = 0; i < m_cvs.size(); ++i) {
        const Vec3 moved = Vec3(toController * (change * Vec4(m_startWorld[i], 1.0)));
        out.push_back(moved - m_curves[m_cvs[i].curve].cvs[m_cvs[i].cv]);
    }
    return out;
}

model::ShapeEdit CvDrag::editFor(const Mat4& change) const
{
    // Offsets live before the edit's own transform: undo its linear part.
    const Mat3 toOffsets = glm::inverse(Mat3(m_start.transform.matrix()));
    const std::vector<Vec3> deltas = controllerDeltas(change);
    model::ShapeEdit edit = m_start;
    for (std::size_t i = 0; i < m_cvs.size(); ++i) {
        const Vec3 authoredDelta = m_onCopy ? m_reflection * deltas[i] : deltas[i];
        const std::pair key{m_cvs[i].curve, m_cvs[i].cv};
        const auto before = edit.cvs.find(key);
        const Vec3 offset = cleaned((before == edit.cvs.end() ? Vec3(0.0) : before->second) + toOffsets * authoredDelta);
        if (offset == Vec3(0.0))
            edit.cvs.erase(key);
        else
            edit.cvs[key] = offset;
    }
    return edit;
}

std::map<model::RigNodeIndex, std::vector<model::ControllerCurve>> CvDrag::previewFor(const Mat4& change) const
{
    const std::vector<Vec3> deltas = controllerDeltas(change);
    std::vector<model::ControllerCurve> own = m_curves, twin = m_twinCurves;
    std::vector<bool> touched(own.size(), false);
    for (std::size_t i = 0; i < m_cvs.size(); ++i) {
        const auto [curve, cv] = std::pair{m_cvs[i].curve, m_cvs[i].cv};
        own[curve].cvs[cv] += deltas[i];
        if (std::size_t(curve) < twin.size() && std::size_t(cv) < twin[curve].cvs.size())
            twin[curve].cvs[cv] += m_reflection * deltas[i];
        touched[curve] = true;
    }
    for (std::size_t k = 0; k < own.size(); ++k) {
        if (!touched[k]) continue;
        own[k].resample();
        if (k < twin.size()) twin[k].resample();
    }
    std::map<model::RigNodeIndex, std::vector<model::ControllerCurve>> out;
    out[m_cvs.front().node] = std::move(own);
    if (m_twin != model::kNoNode)
        out[m_twin] = std::move(twin);
    return out;
}

Status CvDrag::commit(History& history, const Mat4& change, const std::string& verb) const
{
    const model::ShapeEdit edit = editFor(change);
    if (edit == m_start)
        return {};
    const std::string what = m_cvs.size() == 1 ? "CV " + std::to_string(m_cvs.front().cv)
                                                : std::to_string(m_cvs.size()) + " CVs";
    return setShapeEdit(history, m_instance, m_tag, edit, verb + " " + what + " of " + m_tag);
}

} // namespace rs::edit
