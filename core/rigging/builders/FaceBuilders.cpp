// face.jaw, face.eye, face.brow and face.mouth: a face built on guide joints the
// rigger places on the head. Each part is its own template, so a face has only
// the parts its character needs; they meet through named spaces ("jaw",
// "eye_look"), so the mouth follows whichever jaw the rig has.
#include "rigging/builders/Builders.h"

#include "rigging/builders/BuilderKit.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace rs::rigging {

namespace {

using model::JointId;
using model::RigNodeIndex;
using model::RigNodeKind;

const Vec3 kSide(1.0, 0.0, 0.0); // the character's left; faces look down +Z

// The one guide joint tagged `tag`; nullopt (with an error naming what it is
// for) when there is none or several.
std::optional<JointId> taggedJoint(const BuildContext& ctx, const std::string& tag, const std::string& what)
{
    const auto joints = ctx.taggedJoints(tag);
    if (joints.size() == 1)
        return joints.front();
    ctx.error(what + " needs one guide joint tagged '" + tag + "'; it has " + std::to_string(joints.size()));
    return std::nullopt;
}

// Signed angle (degrees) that turns `from` onto `to` about `axis` (their
// projections on the plane normal to it).
double angleAbout(const Vec3& from, const Vec3& to, const Vec3& axis)
{
    const Vec3 a = from - axis * glm::dot(from, axis), b = to - axis * glm::dot(to, axis);
    return glm::degrees(std::atan2(glm::dot(glm::cross(a, b), axis), glm::dot(a, b)));
}

class JawBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&, const std::map<std::string, Value>&) const override
    {
        // The pivot below the ear, the chin in front and below (from the head joint).
        std::vector<GuideJointSpec> specs;
        const int pivot = kit::appendJoint(specs, -1, Vec3(0.0, 0.03, 0.02));
        kit::appendJoint(specs, pivot, Vec3(0.0, -0.08, 0.09));
        return specs;
    }

    bool gather(const BuildContext& ctx) const override
    {
        return kit::chainOfAtLeast(ctx, 2, "a jaw", " (the pivot and the chin)").has_value();
    }

    void generate(BuildContext& ctx) const override
    {
        const auto chain = *ctx.structure("chain");
        const Vec3 pivot = ctx.guidePosition(chain[0]), chin = ctx.guidePosition(chain[1]);
        const Mat4 frame = kit::aimFrame(pivot, chin - pivot, kSide);
        Mat4 chinFrame = frame;
        chinFrame[3] = Vec4(chin, 1.0);
        const auto jaw = kit::addControl(ctx, "jaw", "jaw", {}, ctx.hookNode(), frame, chain[0]);
        kit::animate(ctx, jaw, kit::kTranslate | kit::kRotate); // opens, and slides forward or sideways
        kit::addSkin(ctx, "jaw", "jaw", {}, jaw.ctrl, frame, chain[0]);
        RigNodeIndex end = jaw.ctrl;
        if (ctx.optionBool("chin")) { // the chin control shapes the chin on top of the jaw's turn
            const kit::Control chinControl = kit::addControl(ctx, "chin", "chin", {}, jaw.ctrl, chinFrame, chain[1]);
            kit::animate(ctx, chinControl, kit::kTranslate | kit::kRotate);
            end = chinControl.ctrl;
            kit::addSkin(ctx, "chin", "chin", {}, end, chinFrame, chain[1]);
        }
        ctx.setHook(chain[0], jaw.ctrl);
        ctx.setHook(chain[1], end);
        ctx.defineSpace("jaw", jaw.ctrl);
    }
};

class EyeBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&, const std::map<std::string, Value>&) const override
    {
        // The eyeball's centre, the pupil in front of it, the lids' edges above and below.
        std::vector<GuideJointSpec> specs;
        const int centre = kit::appendJoint(specs, -1, Vec3(0.032, 0.075, 0.075));
        kit::appendJoint(specs, centre, Vec3(0.0, 0.0, 0.013), {"pupil"});
        kit::appendJoint(specs, centre, Vec3(0.0, 0.009, 0.01), {"lid_up"});
        kit::appendJoint(specs, centre, Vec3(0.0, -0.009, 0.01), {"lid_low"});
        return specs;
    }

    bool gather(const BuildContext& ctx) const override
    {
        const auto pupil = taggedJoint(ctx, "pupil", "an eye");
        if (!pupil)
            return false;
        const auto centre = ctx.structure("eye");
        if (!centre || centre->empty())
            return false;
        if (glm::length(ctx.guidePosition(*pupil) - ctx.guidePosition(centre->front())) < 1e-4) {
            ctx.error("the pupil guide sits on the eye's centre: it gives the eye its direction");
            return false;
        }
        return true;
    }

    void generate(BuildContext& ctx) const override
    {
        const JointId centreJoint = ctx.structure("eye")->front();
        const JointId pupilJoint = ctx.taggedJoints("pupil").front();
        const Vec3 centre = ctx.guidePosition(centreJoint);
        const Vec3 forward = glm::normalize(ctx.guidePosition(pupilJoint) - centre);
        const Mat4 frame = kit::aimFrame(centre, forward, kSide);

        const auto eye = kit::addControl(ctx, "eye", "eye", {}, ctx.hookNode(), frame, centreJoint);
        kit::animate(ctx, eye, kit::kTranslate | kit::kRotate); // the eyeball's place; the gaze is the target's
        const RigNodeIndex aim = kit::addSetup(ctx, RigNodeKind::Joint, "mch.aim", "aim", {}, eye.ctrl, frame, centreJoint);
        kit::addSkin(ctx, "eye", "eye", {}, aim, frame, centreJoint);
        ctx.setHook(centreJoint, aim);
        ctx.setHook(pupilJoint, aim);

        // The gaze: each eye aims at its own target; the targets hang under one
        // look control between the eyes (the authored branch makes it, a
        // mirrored branch follows it, see configure).
        const Vec3 target = centre + forward * ctx.optionFloat("target_distance");
        RigNodeIndex targetParent = ctx.hookNode();
        if (!ctx.mirrored()) {
            const auto branches = ctx.optionList("branches");
            const bool pair = branches && branches->size() > 1;
            const Vec3 between = pair ? Vec3(0.0, target.y, target.z) : target; // on the mirror plane
            const auto look = kit::addControl(ctx, "look", "look", {}, ctx.hookNode(), translationMatrix(between), centreJoint);
            kit::animate(ctx, look, kit::kTranslate | kit::kRotate);
            ctx.defineSpace("eye_look", look.ctrl);
            targetParent = look.ctrl;
        }
        const auto aimTarget = kit::addControl(ctx, "target", "target", {}, targetParent, translationMatrix(target), pupilJoint);
        kit::animate(ctx, aimTarget, kit::kTranslate); // a point the eye looks at
        ctx.addConstraint("cns.aim", {aim}, {aimTarget.ctrl}, model::AimConstraint{.aim = model::Axis::X, .up = model::Axis::Y});

        // Lids: each turns about the eye's centre. A follow group takes
        // lid_follow of the eye's turn (the lids ride with the gaze), a blink
        // group closes it (the blink attribute on the eye control: the lids
        // meet at blink_height between the rest lid edges), and the lid
        // control under both is the animator's.
        const auto lidUp = ctx.taggedJoints("lid_up"), lidLow = ctx.taggedJoints("lid_low");
        const bool bothLids = lidUp.size() == 1 && lidLow.size() == 1;
        const model::AttributeRef blink = ctx.addAttribute(eye.ctrl, "blink", 0.0, 0.0, 1.0);
        const double follow = std::clamp(ctx.optionFloat("lid_follow"), 0.0, 1.0);
        const double meet = std::clamp(ctx.optionFloat("blink_height"), 0.0, 1.0);
        for (const auto& [lid, joints, other, share] :
             {std::tuple{std::string("lid_up"), lidUp, lidLow, meet}, std::tuple{std::string("lid_low"), lidLow, lidUp, 1.0 - meet}}) {
            if (joints.empty())
                continue;
            if (joints.size() > 1) {
                ctx.warning("more than one guide joint is tagged '" + lid + "'; the first makes the lid");
            }
            const Vec3 edge = ctx.guidePosition(joints.front());
            const Mat4 lidFrame = kit::aimFrame(centre, edge - centre, kSide);
            const RigNodeIndex followGroup =
                kit::addSetup(ctx, RigNodeKind::Group, "mch." + lid, lid + "_follow", {}, ctx.hookNode(), lidFrame, joints.front());
            ctx.addConstraint("cns." + lid + "_follow", {followGroup}, {eye.offset, aim},
                              model::OrientConstraint{.weights = {1.0 - follow, follow}});
            RigNodeIndex parent = followGroup;
            if (bothLids) {
                parent = kit::addSetup(ctx, RigNodeKind::Group, "mch." + lid + "_blink", lid + "_blink", {}, followGroup, lidFrame,
                                       joints.front());
                const double closing = angleAbout(edge - centre, ctx.guidePosition(other.front()) - centre, Vec3(lidFrame[2]));
                ctx.addConstraint("cns." + lid + "_blink", {parent}, {},
                                  model::DriveConstraint{.value = blink,
                                                         .output = model::DriveOutput::RotateZ,
                                                         .factor = closing * share,
                                                         .response = model::DriveClamped{.low = 0.0, .high = 1.0}});
            }
            const auto control = kit::addControl(ctx, lid, lid, {}, parent, lidFrame, joints.front());
            kit::animate(ctx, control, kit::kRotate); // a lid turns about the eye's centre
            kit::addSkin(ctx, lid, lid, {}, control.ctrl, lidFrame, joints.front());
            ctx.setHook(joints.front(), control.ctrl);
        }
    }

    void configure(BuildContext& ctx) const override
    {
        if (!ctx.mirrored())
            return;
        const auto group = ctx.findNode("roots.target");
        const RigNodeIndex look = ctx.space("eye_look");
        if (group && look != model::kNoNode)
            ctx.addConstraint("cns.look", {*group}, {look}, model::ParentConstraint{});
    }
};

class BrowBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                            const std::map<std::string, Value>& guides) const override
    {
        // Inner end above the nose, outwards along the brow ridge.
        const int count = std::max(2, static_cast<int>(kit::guideNumber(guides, "number", 3)));
        std::vector<GuideJointSpec> specs;
        kit::appendChain(specs, count, Vec3(0.012, 0.1, 0.1), Vec3(0.045 / (count - 1), 0.002, -0.012 / (count - 1)));
        return specs;
    }

    bool gather(const BuildContext& ctx) const override { return kit::chainOfAtLeast(ctx, 2, "a brow").has_value(); }

    void generate(BuildContext& ctx) const override
    {
        const auto chain = *ctx.structure("chain");
        const auto points = *kit::positions(ctx, chain);
        const auto frames = kit::chainFrames(points, Vec3(0.0, 0.0, 1.0));
        // The brow control at the middle moves the whole brow; one control per guide shapes it.
        Vec3 middle(0.0);
        for (const Vec3& p : points)
            middle += p / double(points.size());
        Mat4 mainFrame = frames[points.size() / 2];
        mainFrame[3] = Vec4(middle, 1.0);
        const auto brow = kit::addControl(ctx, "brow", "brow", {}, ctx.hookNode(), mainFrame, chain[points.size() / 2]);
        kit::animate(ctx, brow, kit::kTranslate | kit::kRotate);
        for (std::size_t i = 0; i < chain.size(); ++i) {
            const auto control = kit::addControl(ctx, "fk." + std::to_string(i), "", int(i) + 1, brow.ctrl, frames[i], chain[i]);
            kit::animate(ctx, control, kit::kTranslate | kit::kRotate);
            kit::addSkin(ctx, std::to_string(i), "", int(i) + 1, control.ctrl, frames[i], chain[i]);
            ctx.setHook(chain[i], control.ctrl);
        }
    }
};

class MouthBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&, const std::map<std::string, Value>&) const override
    {
        // The mouth's centre; the lips above and below it, the left corner
        // (the right one is its mirror image across the character's middle).
        std::vector<GuideJointSpec> specs;
        const int centre = kit::appendJoint(specs, -1, Vec3(0.0, -0.01, 0.105));
        kit::appendJoint(specs, centre, Vec3(0.0, 0.007, 0.006), {"lip_up"});
        kit::appendJoint(specs, centre, Vec3(0.0, -0.007, 0.005), {"lip_low"});
        kit::appendJoint(specs, centre, Vec3(0.024, 0.0, -0.014), {"corner"});
        return specs;
    }

    bool gather(const BuildContext& ctx) const override
    {
        return taggedJoint(ctx, "lip_up", "a mouth") && taggedJoint(ctx, "lip_low", "a mouth") &&
               taggedJoint(ctx, "corner", "a mouth");
    }

    void generate(BuildContext& ctx) const override
    {
        const Vec3 centre = ctx.guidePosition(ctx.structure("mouth")->front());
        const JointId corner = ctx.taggedJoints("corner").front();
        Vec3 left = ctx.guidePosition(corner);
        if (left.x < centre.x) // the rigger placed the right corner: the left is its mirror image
            left.x = 2.0 * centre.x - left.x;
        const Vec3 right(2.0 * centre.x - left.x, left.y, left.z);
        struct Part {
            std::string key;
            Vec3 at;
            JointId guide;
        };
        const std::vector<Part> parts = {{"lip_up", ctx.guidePosition(ctx.taggedJoints("lip_up").front()), ctx.taggedJoints("lip_up").front()},
                                         {"lip_low", ctx.guidePosition(ctx.taggedJoints("lip_low").front()), ctx.taggedJoints("lip_low").front()},
                                         {"corner_L", left, corner},
                                         {"corner_R", right, corner}};
        // Each part hangs from a follow group that the jaw carries part of the
        // way (configure), then its control and skin joint.
        for (const Part& part : parts) {
            const Mat4 frame = translationMatrix(part.at);
            const RigNodeIndex follow =
                kit::addSetup(ctx, RigNodeKind::Group, "mch." + part.key, part.key + "_follow", {}, ctx.hookNode(), frame, part.guide);
            const auto control = kit::addControl(ctx, part.key, part.key, {}, follow, frame, part.guide);
            kit::animate(ctx, control, kit::kTranslate | kit::kRotate); // lips and corners move, lips curl
            kit::addSkin(ctx, part.key, part.key, {}, control.ctrl, frame, part.guide);
        }
        const std::string domain = ctx.optionBool("do_ctrl") ? "ctrls." : "roots.";
        ctx.setHook(ctx.taggedJoints("lip_up").front(), *ctx.findNode(domain + "lip_up"));
        ctx.setHook(ctx.taggedJoints("lip_low").front(), *ctx.findNode(domain + "lip_low"));
        ctx.setHook(corner, *ctx.findNode(domain + (ctx.guidePosition(corner).x < centre.x ? "corner_R" : "corner_L")));
    }

    void configure(BuildContext& ctx) const override
    {
        const RigNodeIndex jaw = ctx.space("jaw");
        if (jaw == model::kNoNode)
            return; // no jaw in this rig: the mouth follows the head alone
        const std::pair<const char*, const char*> follows[] = {
            {"lip_up", "lip_up_jaw"}, {"lip_low", "lip_low_jaw"}, {"corner_L", "corner_jaw"}, {"corner_R", "corner_jaw"}};
        for (const auto& [key, option] : follows) {
            const double share = std::clamp(ctx.optionFloat(option), 0.0, 1.0);
            const auto group = ctx.findNode(std::string("mch.") + key);
            if (!group || share <= 0.0)
                continue;
            ctx.addConstraint(std::string("cns.") + key + "_jaw", {*group}, {ctx.node(*group).parent, jaw},
                              model::ParentConstraint{.weights = {1.0 - share, share}});
        }
    }
};

} // namespace

std::unique_ptr<TemplateBuilder> makeJawBuilder() { return std::make_unique<JawBuilder>(); }
std::unique_ptr<TemplateBuilder> makeEyeBuilder() { return std::make_unique<EyeBuilder>(); }
std::unique_ptr<TemplateBuilder> makeBrowBuilder() { return std::make_unique<BrowBuilder>(); }
std::unique_ptr<TemplateBuilder> makeMouthBuilder() { return std::make_unique<MouthBuilder>(); }

} // namespace rs::rigging
