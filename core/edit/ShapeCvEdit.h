#pragma once
// CV mode: moving control points of a built controller's shape one by one.
// The rig's curves carry their CVs in the controller's space; a drag turns the
// gizmo's change into per-CV offsets of the instance's shape edit
// (model::ShapeEdit: final CV = transform * (placed CV + offset)), recorded as
// one undo step, so a rebuild (and every later one) draws the edited shape.
//
// CVs of a mirrored branch copy (RigNode::shapeFromTwin, the R side of
// `branches: [L, R]`) are edited through their twin: the offsets land on the
// authored side, reflected, and the copy follows when the rig is rebuilt.
#include "base/Result.h"
#include "edit/GuideEdits.h"
#include "model/Rig.h"

#include <map>
#include <vector>

namespace rs::edit {

// A CV's world position in the built rig's rest pose.
Vec3 cvWorldPosition(const model::Rig& rig, const model::CurveCv& cv);

class CvDrag {
public:
    // Starts a drag of `cvs` (one controller's) of `rig`, built from `document`.
    // Fails when the CVs are of several controllers or out of range, or the
    // controller has no instance in the document to keep the edit; the error
    // names the controller's shape (or node).
    static Result<CvDrag> begin(const model::GuideDocument& document, const model::Rig& rig,
                                std::vector<model::CurveCv> cvs);

    // The gizmo's frame: at the CVs' centroid, turned as the controller.
    const Mat4& frame() const { return m_frame; }
    // The shape edit putting each CV at `change * startWorld` (`change` a world affine map).
    model::ShapeEdit editFor(const Mat4& change) const;
    // The curves (controller space, resampled) of the dragged controller and of
    // its mirrored twin for `change`, to preview without rebuilding.
    std::map<model::RigNodeIndex, std::vector<model::ControllerCurve>> previewFor(const Mat4& change) const;
    // Records `editFor(change)` as one undo step ("Move 3 CVs of ctrls.ik of
    // arm"); a drag that moved nothing records nothing. Refusals as setShapeEdit's.
    Status commit(History& history, const Mat4& change, const std::string& verb = "Move") const;

    model::InstanceId instance() const { return m_instance; }
    const std::string& tag() const { return m_tag; }

private:
    CvDrag() = default;
    // Each CV's change in the dragged controller's space.
    std::vector<Vec3> controllerDeltas(const Mat4& change) const;

    std::vector<model::CurveCv> m_cvs;
    std::vector<Vec3> m_startWorld;
    Mat4 m_nodeWorld{1.0};
    std::vector<model::ControllerCurve> m_curves, m_twinCurves;
    model::RigNodeIndex m_twin = model::kNoNode; // the other side's node, if any
    Mat3 m_reflection{1.0};                      // one side's controller space -> the other's
    bool m_onCopy = false;                       // dragging the mirrored copy: offsets go to the twin
    model::InstanceId m_instance = model::kNoId;
    std::string m_tag;
    model::ShapeEdit m_start;
    Mat4 m_frame{1.0};
};

} // namespace rs::edit
