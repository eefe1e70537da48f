#pragma once
// Moving guide joints in the viewport: a gizmo drag turns the lead joint's new
// world matrix into new local transforms for every selected joint (and, with
// symmetry on, their mirror twins), recorded as one undo step at the end.
//
// The drag is relative: the lead's change (translation, and the linear part
// about its own pivot) is applied to each moved joint about its own pivot, so a
// multi-selection moves and turns together. Joints below another moved joint
// follow their parent rather than being moved twice.
#include "edit/History.h"
#include "edit/GuideEdits.h"

#include <vector>

namespace rs::edit {

struct JointTransform {
    model::JointId joint = model::kNoId;
    Transform local;
    bool operator==(const JointTransform&) const = default;
};

// A local matrix as translate / rotate (XYZ, degrees) / scale, float noise
// below 1e-9 around the sixth decimal rounded off so files keep clean values.
Transform localTransformOf(const Mat4& local);
// The local transform giving `joint` the world matrix `world`, with its parent
// where it is now. Shear is dropped; rotation comes out in the document's XYZ order.
Transform localFor(const model::GuideDocument& document, model::JointId joint, const Mat4& world);

// Several joints' local transforms as one undo step named `what`; unchanged
// joints are left out and nothing changes at all is refused. A joint not in
// the document is refused, naming that guide joint.
Status setJointTransforms(History& history, const std::vector<JointTransform>& transforms, const std::string& what);

// The joint on the other side: the same place (index) in the instance whose
// name swaps the side token (arm_L <-> arm_R). kNoId when there is none.
model::JointId mirrorJointOf(const model::GuideDocument& document, model::JointId joint);
// A world matrix reflected across the YZ plane (x -> -x), as a proper frame.
Mat4 mirroredAcrossX(const Mat4& world);
// True when `joint` hangs (directly or through instances' hooks) below `ancestor`.
bool isBelow(const model::GuideDocument& document, model::JointId joint, model::JointId ancestor);

struct GuideDragOptions {
    bool symmetric = false;   // move mirror twins too
    double snapStep = 0.0;    // > 0: the lead's world position snaps to this grid (metres)
};

class GuideDrag {
public:
    // `lead` carries the gizmo; `joints` are all selected joints (lead among them).
    GuideDrag(const model::GuideDocument& document, model::JointId lead, std::vector<model::JointId> joints,
              GuideDragOptions options);
    // The new local transforms for the lead's new world matrix (from the start state).
    std::vector<JointTransform> transformsFor(const Mat4& leadWorld) const;
    // The start transforms of every joint the drag moves (to restore a preview).
    const std::vector<JointTransform>& start() const { return m_start; }

private:
    struct Moved {
        model::JointId joint;
        Mat4 startWorld;
        Mat4 parentWorld;       // unchanged during the drag
        model::JointId mirrorOf; // kNoId, or the selected joint this one mirrors
        Mat4 sourceStart;        // that joint's world matrix at the start
    };
    Mat4 m_leadStart;
    GuideDragOptions m_options;
    std::vector<Moved> m_moved;
    std::vector<JointTransform> m_start;
};

} // namespace rs::edit
