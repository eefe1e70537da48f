// wheel.legacy and util.camera: Mikan's templates for vehicles and props (and
// rig.slide, in SlideBuilder.cpp). A wheel rolls by itself as it travels
// (model::RollConstraint), a camera aims at its target control with a roll.
#include "rigging/builders/Builders.h"

#include "rigging/builders/BuilderKit.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace rs::rigging {

namespace {

using model::JointId;
using model::RigNodeIndex;
using model::RigNodeKind;

constexpr int kTranslate = 0, kRotate = 3, kScale = 6; // first channel of each (ChannelSettings)

// A frame whose columns are the given unit axes, at `origin`.
Mat4 frameOf(const Vec3& x, const Vec3& y, const Vec3& z, const Vec3& origin)
{
    Mat4 m(1.0);
    m[0] = Vec4(x, 0.0);
    m[1] = Vec4(y, 0.0);
    m[2] = Vec4(z, 0.0);
    m[3] = Vec4(origin, 1.0);
    return m;
}

Mat4 movedTo(Mat4 frame, const Vec3& origin)
{
    frame[3] = Vec4(origin, 1.0);
    return frame;
}

// The one guide joint tagged `tag`; nullopt, with an error, when there is none or several.
std::optional<JointId> taggedJoint(const BuildContext& ctx, const std::string& tag, const std::string& what)
{
    const auto joints = ctx.taggedJoints(tag);
    if (joints.size() == 1)
        return joints.front();
    ctx.error(what + " needs one guide joint tagged '" + tag + "'; it has " + std::to_string(joints.size()));
    return std::nullopt;
}

// The top of the rig above `node` (the rig root: it never moves).
RigNodeIndex topOf(const BuildContext& ctx, RigNodeIndex node)
{
    while (node != model::kNoNode && ctx.node(node).parent != model::kNoNode)
        node = ctx.node(node).parent;
    return node;
}

// --- wheel.legacy -----------------------------------------------------------

class WheelBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                            const std::map<std::string, Value>& guides) const override
    {
        // The swivel (steering pivot), the wheel's centre a little outboard of
        // it, the ground contact below the centre.
        const double radius = kit::guideNumber(guides, "radius", 0.35);
        std::vector<GuideJointSpec> specs;
        const int swivel = kit::appendJoint(specs, -1, Vec3(0.0));
        const int axis = kit::appendJoint(specs, swivel, Vec3(0.1, 0.0, 0.0), {"axis"});
        kit::appendJoint(specs, axis, Vec3(0.0, -radius, 0.0), {"ground"});
        return specs;
    }

    bool gather(const BuildContext& ctx) const override
    {
        const auto swivel = ctx.structure("swivel");
        const auto axis = taggedJoint(ctx, "axis", "a wheel");
        const auto ground = taggedJoint(ctx, "ground", "a wheel");
        if (!swivel || swivel->empty() || !axis || !ground)
            return false;
        if (glm::length(ctx.guidePosition(*axis) - ctx.guidePosition(*ground)) < 1e-3) {
            ctx.error("the wheel's ground guide sits on its axis guide: their distance is the wheel's radius");
            return false;
        }
        return true;
    }

    void generate(BuildContext& ctx) const override
    {
        const JointId swivelJoint = ctx.structure("swivel")->front();
        const JointId axisJoint = ctx.taggedJoints("axis").front();
        const JointId groundJoint = ctx.taggedJoints("ground").front();
        const Vec3 swivel = ctx.guidePosition(swivelJoint), centre = ctx.guidePosition(axisJoint),
                   ground = ctx.guidePosition(groundJoint);
        const double radius = glm::length(centre - ground);
        // Y up from the ground to the centre, X the axle (the swivel guide's X,
        // as Mikan copies the swivel's orientation), Z forward: X x Z points
        // down to the ground, so a positive roll about X rolls forward.
        const Vec3 up = (centre - ground) / radius;
        Vec3 axle = kit::guideAxis(ctx, swivelJoint, 0, Vec3(1.0, 0.0, 0.0));
        axle -= up * glm::dot(axle, up);
        if (glm::length(axle) < 1e-6)
            axle = std::abs(up.x) < 0.9 ? glm::cross(up, Vec3(0.0, 0.0, 1.0)) : glm::cross(Vec3(0.0, 0.0, 1.0), up);
        axle = glm::normalize(axle);
        const Vec3 forward = glm::cross(axle, up);
        const Mat4 frame = frameOf(axle, up, forward, swivel);

        const RigNodeIndex swivelNode =
            ctx.createNode(RigNodeKind::Group, "roots.swivel", ctx.nodeName(model::NameRole::Offset, "swivel"), ctx.hookNode(),
                           frame, swivelJoint);
        const auto bank = kit::addControl(ctx, "bank", "base", {}, swivelNode, movedTo(frame, ground), groundJoint);
        const auto wheel = kit::addControl(ctx, "wheel", "", {}, bank.ctrl, movedTo(frame, centre), axisJoint);
        kit::animate(ctx, bank, kit::kTranslate | kit::kRotate | kit::kScale); // banks, and flattens by its scale
        kit::animate(ctx, wheel, kit::kTranslate | kit::kRotate);
        kit::addSkin(ctx, "wheel", "center", {}, wheel.ctrl, movedTo(frame, centre), axisJoint);
        const model::AttributeRef autoRotate = ctx.addAttribute(wheel.ctrl, "auto_rotate", 1.0, 0.0, 1.0);

        // The roll: travel measured in the ground's frame (the `hook` space),
        // along the path (accumulated each evaluation) or from rest (`roll: axis`).
        const RigNodeIndex roll =
            kit::addSetup(ctx, RigNodeKind::Group, "mch.roll", "roll", {}, wheel.ctrl, movedTo(frame, centre), axisJoint);
        const bool axisRoll = ctx.optionString("roll") == "axis";
        const double jump = ctx.optionFloat("roll_jump"); // the manifest's min keeps it >= 0
        ctx.addConstraint("cns.roll", {roll}, {reference(ctx)},
                          model::RollConstraint{.axle = model::Axis::X, .forward = model::Axis::Z, .radius = radius,
                                                .amount = autoRotate,
                                                .mode = axisRoll ? model::RollMode::Axis : model::RollMode::Path,
                                                .jump = std::max(jump, 0.0)});
        const auto spin = kit::addControl(ctx, "spin", "spin", {}, roll, movedTo(frame, centre), axisJoint);
        kit::animate(ctx, spin, std::uint16_t(1u << model::channelIndex("rx"))); // the manual spin
        if (spin.ctrl != spin.offset) { // the manual spin: rotate X only
            model::ChannelSettings& channels = ctx.channels(spin.ctrl);
            channels.lock(kTranslate, 3);
            channels.lock(kRotate + 1, 2);
            channels.lock(kScale, 3);
        }
        kit::addSkin(ctx, "spin", "", {}, spin.ctrl, movedTo(frame, centre), axisJoint);

        ctx.setHook(swivelJoint, wheel.ctrl);
        ctx.setHook(axisJoint, spin.ctrl);
        ctx.setHook(groundJoint, bank.ctrl);
    }

private:
    // What the wheel travels over: the rig's space named by `hook` (the
    // world templates' `ground`, their world control, by default), else the rig's root.
    static RigNodeIndex reference(BuildContext& ctx)
    {
        const std::string name = ctx.optionString("hook");
        if (!name.empty()) {
            if (const RigNodeIndex space = ctx.space(name); space != model::kNoNode)
                return space;
            if (name != "ground")
                ctx.warning("the rig has no space '" + name + "': the wheel rolls as it moves in the rig's root", "hook");
        }
        return topOf(ctx, ctx.hookNode());
    }
};

// --- util.camera ------------------------------------------------------------

class CameraBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                            const std::map<std::string, Value>& guides) const override
    {
        // The camera at eye height behind, its target `distance` in front (-Z from it).
        const double distance = kit::guideNumber(guides, "distance", 4.0);
        std::vector<GuideJointSpec> specs;
        const int camera = kit::appendJoint(specs, -1, Vec3(0.0, 1.6, distance));
        kit::appendJoint(specs, camera, Vec3(0.0, -0.6, -distance), {"target"});
        return specs;
    }

    bool gather(const BuildContext& ctx) const override
    {
        const auto camera = ctx.structure("camera");
        const auto target = taggedJoint(ctx, "target", "a camera");
        if (!camera || camera->empty() || !target)
            return false;
        if (glm::length(ctx.guidePosition(*target) - ctx.guidePosition(camera->front())) < 1e-3) {
            ctx.error("the camera's target guide sits on the camera: it gives the camera its direction");
            return false;
        }
        return true;
    }

    void generate(BuildContext& ctx) const override
    {
        const JointId cameraJoint = ctx.structure("camera")->front();
        const JointId targetJoint = ctx.taggedJoints("target").front();
        const Vec3 eye = ctx.guidePosition(cameraJoint), target = ctx.guidePosition(targetJoint);
        // A camera looks down its -Z with +Y up (glTF, Maya): Z from the target to the eye.
        const Vec3 back = glm::normalize(eye - target);
        Vec3 side = glm::cross(Vec3(0.0, 1.0, 0.0), back);
        if (glm::length(side) < 1e-6) // looking straight up or down: the guide's X
            side = kit::guideAxis(ctx, cameraJoint, 0, Vec3(1.0, 0.0, 0.0));
        side = glm::normalize(side - back * glm::dot(side, back));
        const Mat4 frame = frameOf(side, glm::cross(back, side), back, eye);

        const auto body = kit::addControl(ctx, "camera", "", {}, ctx.hookNode(), frame, cameraJoint);
        const auto aimTarget = kit::addControl(ctx, "target", "target", {}, ctx.hookNode(), movedTo(frame, target), targetJoint);
        kit::animate(ctx, body, kit::kTranslate | kit::kRotate);
        kit::animate(ctx, aimTarget, kit::kTranslate); // a point the camera looks at
        // The up target above the camera turns with the camera control, so
        // banking the control banks the view; roll turns it about the view axis.
        const RigNodeIndex upNode = kit::addSetup(ctx, RigNodeKind::Group, "mch.up", "up", {}, body.ctrl,
                                                  movedTo(frame, eye + Vec3(frame[1])), cameraJoint);
        const RigNodeIndex aim = kit::addSetup(ctx, RigNodeKind::Group, "mch.aim", "aim", {}, body.ctrl, frame, cameraJoint);
        ctx.addConstraint("cns.aim", {aim}, {aimTarget.ctrl, upNode}, model::AimConstraint{.aim = model::Axis::Z, .up = model::Axis::Y});
        const model::AttributeRef roll = ctx.addAttribute(body.ctrl, "roll", 0.0, -180.0, 180.0);
        const RigNodeIndex camera = ctx.createNode(RigNodeKind::Group, "camera", ctx.nodeName(model::NameRole::Group, "camera"),
                                                   aim, frame, cameraJoint);
        ctx.addConstraint("cns.roll", {camera}, {}, model::DriveConstraint{.value = roll, .output = model::DriveOutput::RotateZ});
        kit::addSkin(ctx, "camera", "", {}, camera, frame, cameraJoint);

        // The lens, animatable on the camera control, as Mikan's camera carries it.
        ctx.addAttribute(body.ctrl, "focal_length", ctx.optionFloat("focal_length"), 1.0, 10000.0);
        ctx.addAttribute(body.ctrl, "horizontal_aperture", ctx.optionFloat("horizontal_aperture"), 0.001, 100.0);
        ctx.addAttribute(body.ctrl, "vertical_aperture", ctx.optionFloat("vertical_aperture"), 0.001, 100.0);
        ctx.addAttribute(body.ctrl, "near_clip", ctx.optionFloat("near_clip"), 0.001, 1e6);
        ctx.addAttribute(body.ctrl, "far_clip", ctx.optionFloat("far_clip"), 0.001, 1e6);
        ctx.addEnumAttribute(body.ctrl, "orthographic", ctx.optionBool("orthographic") ? 1 : 0, {"off", "on"});
        ctx.addAttribute(body.ctrl, "ortho_width", ctx.optionFloat("ortho_width"), 0.001, 1e6);
        if (ctx.optionBool("image_plane"))
            ctx.addAttribute(body.ctrl, "imageplane_depth", 100.0, 0.0, 1e6);

        ctx.setHook(cameraJoint, camera);
        ctx.setHook(targetJoint, aimTarget.ctrl);
    }
};

} // namespace

std::unique_ptr<TemplateBuilder> makeWheelBuilder() { return std::make_unique<WheelBuilder>(); }
std::unique_ptr<TemplateBuilder> makeCameraBuilder() { return std::make_unique<CameraBuilder>(); }

} // namespace rs::rigging
