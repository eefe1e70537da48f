#include "rigging/builders/LimbBendy.h"

#include "rigging/builders/BuilderKit.h"

#include <glm/gtc/quaternion.hpp>

namespace rs::rigging::limb {

using model::RigNodeIndex;
using model::RigNodeKind;

namespace {

// The frame halfway (by rotation) between two frames, at `position`.
Mat4 halfwayFrame(const Mat4& a, const Mat4& b, const Vec3& position)
{
    const Quat qa = glm::quat_cast(Mat3(a)), qb = glm::quat_cast(Mat3(b));
    Mat4 frame(glm::mat3_cast(glm::slerp(qa, glm::dot(qa, qb) < 0.0 ? -qb : qb, 0.5)));
    frame[3] = Vec4(position, 1.0);
    return frame;
}

} // namespace

BendControls addBendControls(BuildContext& ctx, const std::vector<Vec3>& points, const std::vector<Mat4>& frames,
                             const std::vector<model::JointId>& guides, const std::vector<RigNodeIndex>& blend,
                             RigNodeIndex limbRoot)
{
    BendControls out;
    if (!ctx.optionBool("bendy") || !ctx.optionBool("do_skin"))
        return out;
    if (ctx.optionInt("twist_upper") == 0 && ctx.optionInt("twist_lower") == 0)
        ctx.warning("bendy: twist_upper and twist_lower are 0, so no joint rides the bend controls' curves; add twist "
                    "joints for them to bend anything",
                    "bendy");
    // The tweak: at the middle joint, turned halfway between the two bones.
    const Mat4 tweakFrame = halfwayFrame(frames[0], frames[1], points[1]);
    const auto tweakGroup = kit::addSetup(ctx, RigNodeKind::Group, "bendy.tweak", "tweak_space", {}, limbRoot, tweakFrame, guides[1]);
    ctx.addConstraint("cns.bendy.tweak.point", {tweakGroup}, {blend[1]}, model::PointConstraint{.keepOffset = false});
    ctx.addConstraint("cns.bendy.tweak.orient", {tweakGroup}, {blend[0], blend[1]}, model::OrientConstraint{.weights = {0.5, 0.5}});
    const kit::Control tweak = kit::addControl(ctx, "tweak", "tweak", {}, tweakGroup, tweakFrame, guides[1]);
    kit::animate(ctx, tweak, kit::kTranslate | kit::kRotate); // scale would mean nothing to a curve point

    // A bend control halfway along each segment, between its start and end
    // (the tweak on the middle joint's side), turned like the segment's bone.
    const char* segment[] = {"up", "dn"};
    for (std::size_t s = 0; s < 2; ++s) {
        const RigNodeIndex start = s == 0 ? blend[0] : tweak.ctrl;
        const RigNodeIndex end = s == 0 ? tweak.ctrl : blend[2];
        Mat4 frame = frames[s];
        frame[3] = Vec4(glm::mix(points[s], points[s + 1], 0.5), 1.0);
        const std::string key = std::string("bend.") + segment[s];
        const auto group = kit::addSetup(ctx, RigNodeKind::Group, "bendy." + std::string(segment[s]), "bend_space", int(s) + 1,
                                         limbRoot, frame, guides[s]);
        ctx.addConstraint("cns.bendy." + std::string(segment[s]) + ".point", {group}, {start, end},
                          model::PointConstraint{.weights = {0.5, 0.5}, .keepOffset = false});
        ctx.addConstraint("cns.bendy." + std::string(segment[s]) + ".orient", {group}, {blend[s]}, model::OrientConstraint{});
        const kit::Control bend = kit::addControl(ctx, key, "bend", int(s) + 1, group, frame, guides[s]);
        kit::animate(ctx, bend, kit::kTranslate | kit::kRotate); // rotation turns the curve's tangent there
        // model::TwistConstraint's bendy targets: the limb's three joints, the
        // tweak and its space, the segment's bend control.
        out.curveTargets.push_back({blend[0], blend[1], blend[2], tweak.ctrl, tweak.offset, bend.ctrl});
    }
    return out;
}

} // namespace rs::rigging::limb
