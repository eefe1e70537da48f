#pragma once
// Joint orientation of a chain computed at build from where its guide joints
// are, as Mikan's `orient`, `aim_axis`, `up_axis`, `up_dir` and `up_auto`
// options (core.joints, core.bones, rig.spline), so a rigger places a chain by
// translating guides only. Frames are rigid (unit, right-handed) and in
// authored space: the build context maps them onto a mirrored branch copy
// (W' = M W M, BuildContext.h), which gets the exact mirror frames.
#include "rigging/TemplateBuilder.h"

#include <optional>
#include <string>
#include <vector>

namespace rs::rigging {

struct ChainOrient {
    enum class Mode {
        Copy,  // each guide joint's own orientation (scale and shear dropped)
        Auto,  // aimed at the child joint, rolled towards `upDir` or the bend normal
        World, // the world axes (identity rotation) at each guide joint
    };
    Mode mode = Mode::Copy;
    Vec3 aimAxis{1.0, 0.0, 0.0}; // local unit axis (+-x, +-y, +-z) pointing at the child
    Vec3 upAxis{0.0, 1.0, 0.0};  // local unit axis, never parallel to aimAxis
    Vec3 upDir{0.0, 0.0, 1.0};   // unit direction in authored world space
    bool upAuto = false;         // roll towards the chain's bend normal where it bends
    // The up direction is the root guide's up axis (so turning the root guide
    // rolls the chain, as rig.spline's frames always did), or upDir where that
    // lies along the chain's first segment: set by orientFrames when its
    // builder asks and the instance leaves up_dir at its default.
    bool upDirFromRootGuide = false;
};

// The orientation options of the instance (`orient` copy / auto / world,
// `aim_axis`, `up_axis`, `up_dir`, `up_auto`); an option the manifest does
// not declare keeps the default above. Reports an error naming the option and
// returns nullopt for a label that is no axis, a zero `up_dir`, or an
// `up_axis` on the same line as `aim_axis` (equal or opposite); an `orient`
// label other than copy, auto and world (a template of its own based on
// core.joints may use other labels) is warned about and read as copy.
// `report` off: no warning (generate reads them again after gather checked them).
std::optional<ChainOrient> readChainOrient(const BuildContext& ctx, bool report = true);

// One frame per guide joint from the joints' world matrices (authored space),
// at the joints' positions.
//  - copy: the guide's own rotation; world: the identity.
//  - auto: aimAxis along the segment to the next joint and upAxis as close as
//    it can be to the up direction: with upAuto, the normal of the plane
//    through the joint, the next and the one after (cross product of the two
//    segments), carried on where the chain is straight, starting from upDir;
//    else upDir. Where the up direction lies along the segment, the previous
//    joint's up axis is used (the first joint: any perpendicular). A joint on
//    top of the next keeps the previous frame. The last joint takes its
//    parent's frame; a chain of one joint keeps its guide's rotation.
// `aimAlways` (bones): copy and world are aimed too, by the smallest turn of
// their aimAxis onto the segment, so they keep the guide's (world's) roll.
std::vector<Mat4> orientChain(const ChainOrient& orient, const std::vector<Mat4>& guideWorld, bool aimAlways = false);

// orientChain for the instance's options and the guide joints `chain`; the
// options must have been checked by readChainOrient (in gather): on an error
// it gives the guides' own frames.
// `rootGuideUp` (rig.spline): an instance that leaves up_dir at its default
// takes the root guide's up axis instead (ChainOrient::upDirFromRootGuide).
std::vector<Mat4> orientFrames(const BuildContext& ctx, const std::vector<model::JointId>& chain, bool aimAlways = false,
                               bool rootGuideUp = false);
// The same at world matrices that stand for guide joints (authored space;
// rig.spline's bones along its curve, the first standing for the root guide).
std::vector<Mat4> orientFrames(const BuildContext& ctx, const std::vector<Mat4>& guideWorld, bool aimAlways = false,
                               bool rootGuideUp = false);

// The rotation taking local `aimAxis` onto unit `aim` and local `upAxis` onto
// `up` made perpendicular to `aim`; nullopt when `up` lies along `aim`.
std::optional<Mat3> aimRotation(const Vec3& aim, const Vec3& up, const Vec3& aimAxis, const Vec3& upAxis);

} // namespace rs::rigging
