// arm.limb, leg.limb and quad.leg: one limb builder.
//
// Guide chain: root (clavicle or pelvis) > limb1 > limb2 > limb3 [> limb4 for a
// quad] > tip (arm) or ball > toe (legs); heel, bank_int and bank_ext are
// tagged guides under the last limb joint. Every chain is built three times:
// FK controls, an IK chain solved to the IK controller and pole, and the blend
// chain (FK/IK mixed by `ik_blend`) that skin joints and children follow.
#include "rigging/builders/Builders.h"

#include "rigging/builders/BuilderKit.h"
#include "rigging/builders/LimbBendy.h"
#include "rigging/builders/LimbParts.h"
#include "rigging/builders/LimbReverse.h"
#include "rigging/builders/LimbTwist.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace rs::rigging {

namespace {

using model::AttributeRef;
using model::JointId;
using model::RigNodeIndex;
using model::RigNodeKind;

struct LimbGuide {
    JointId root = model::kNoId;
    std::vector<JointId> limb;              // limb1..limbK
    JointId end = model::kNoId;             // arm tip or leg ball
    JointId toe = model::kNoId;             // legs: toe tip
    std::vector<Vec3> points;               // limb1..limbK then end
};

class LimbBuilder final : public TemplateBuilder {
public:
    explicit LimbBuilder(LimbKind kind) : m_kind(kind) {}

    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                            const std::map<std::string, Value>& guides) const override
    {
        std::vector<GuideJointSpec> s;
        if (m_kind == LimbKind::Arm) {
            // On the chest (about 1.45 m): clavicle, shoulder, elbow, wrist, hand tip along +X.
            const double upper = kit::guideNumber(guides, "upper", 0.28), lower = kit::guideNumber(guides, "lower", 0.26);
            int j = kit::appendJoint(s, -1, Vec3(0.03, 0.0, 0.03));
            j = kit::appendJoint(s, j, Vec3(0.15, 0.0, -0.04));
            j = kit::appendJoint(s, j, Vec3(upper, 0.0, -0.03));
            j = kit::appendJoint(s, j, Vec3(lower, 0.0, 0.03));
            kit::appendJoint(s, j, Vec3(0.09, 0.0, 0.0));
            return s;
        }
        // On the hips (1 m): pelvis, hip, knee, ankle, then the foot on the ground.
        const bool quad = m_kind == LimbKind::Quad;
        const double upper = kit::guideNumber(guides, "upper", quad ? 0.25 : 0.42);
        const double lower = kit::guideNumber(guides, "lower", quad ? 0.25 : 0.42);
        int j = kit::appendJoint(s, -1, Vec3(0.0, -0.02, 0.0));
        j = kit::appendJoint(s, j, Vec3(0.1, -0.06, 0.0));
        if (m_kind == LimbKind::Quad) {
            // Hind leg: stifle forward, hock back, then the long cannon to the fetlock.
            j = kit::appendJoint(s, j, Vec3(0.0, -upper, 0.12));
            j = kit::appendJoint(s, j, Vec3(0.0, -lower, -0.15));
            j = kit::appendJoint(s, j, Vec3(0.0, -0.2, 0.02));
        } else {
            j = kit::appendJoint(s, j, Vec3(0.0, -upper, 0.02));
            j = kit::appendJoint(s, j, Vec3(0.0, -lower, -0.02));
        }
        const Vec3 ankle(0.0, 0.0, 0.0);
        const double height = m_kind == LimbKind::Quad ? 0.04 : 0.08; // ankle height above the ground
        const int ankleIndex = j;
        j = kit::appendJoint(s, j, Vec3(0.0, -height + 0.01, 0.12));
        kit::appendJoint(s, j, Vec3(0.0, -0.01, 0.07));
        kit::appendJoint(s, ankleIndex, ankle + Vec3(0.0, -height, -0.06), {"heel"});
        kit::appendJoint(s, ankleIndex, ankle + Vec3(-0.045, -height, 0.12), {"bank_int"});
        kit::appendJoint(s, ankleIndex, ankle + Vec3(0.05, -height, 0.11), {"bank_ext"});
        return s;
    }

    bool gather(const BuildContext& ctx) const override { return guideOf(ctx).has_value(); }

    void generate(BuildContext& ctx) const override;
    void configure(BuildContext& ctx) const override;

private:
    bool legLike() const { return m_kind != LimbKind::Arm; }
    std::size_t limbCount() const { return m_kind == LimbKind::Quad ? 4 : 3; }
    std::string rootOption() const { return m_kind == LimbKind::Arm ? "clavicle" : "pelvis"; }

    std::optional<LimbGuide> guideOf(const BuildContext& ctx) const
    {
        LimbGuide g;
        auto root = ctx.structure(rootOption());
        if (!root)
            return std::nullopt;
        g.root = root->front();
        for (std::size_t i = 1; i <= limbCount(); ++i) {
            auto joint = ctx.structure("limb" + std::to_string(i));
            if (!joint)
                return std::nullopt;
            g.limb.push_back(joint->front());
        }
        auto end = ctx.structure(legLike() ? "ball" : "tip");
        if (!end)
            return std::nullopt;
        g.end = end->front();
        if (legLike()) {
            auto toe = ctx.structure("toe");
            if (!toe)
                return std::nullopt;
            g.toe = toe->front();
        }
        std::vector<JointId> all = g.limb;
        all.push_back(g.end);
        if (g.toe != model::kNoId)
            all.push_back(g.toe);
        g.points = *kit::positions(ctx, g.limb);
        g.points.push_back(ctx.guidePosition(g.end));
        kit::checkSpacing(ctx, all, "limb");
        return g;
    }

    // The bend normal of the limb (Z of every segment frame) and the pole direction.
    void bendOf(const BuildContext& ctx, const LimbGuide& g, Vec3& normal, Vec3& poleDirection) const;
    // The reverse lock's pivots (LimbReverse.h): the leg's foot, the arm's hand.
    limb::ReversePivots pivotsOf(const BuildContext& ctx, const LimbGuide& g, const Vec3& normal, const Vec3& poleDirection) const
    {
        const Vec3 end = g.points[limbCount() - 1], tip = ctx.guidePosition(g.end);
        if (!legLike())
            return limb::handPivots(ctx, end, tip, normal, poleDirection, g.limb.back(), g.end);
        return limb::footPivots(ctx, end, tip, ctx.guidePosition(g.toe), normal, g.limb.back(), g.end, g.toe);
    }

    LimbKind m_kind;
};

void LimbBuilder::bendOf(const BuildContext& ctx, const LimbGuide& g, Vec3& normal, Vec3& poleDirection) const
{
    // Arms bend with the elbow behind, legs with the knee in front.
    const Vec3 fallbackNormal = legLike() ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, -1.0, 0.0);
    const Vec3 fallbackPole = legLike() ? Vec3(0.0, 0.0, 1.0) : Vec3(0.0, 0.0, -1.0);
    const Vec3 a = g.points[0], b = g.points[1], c = g.points[2];
    if (auto n = kit::planeNormal(a, b, c)) {
        normal = *n;
        const Vec3 axis = glm::normalize(c - a);
        const Vec3 off = (b - a) - axis * glm::dot(b - a, axis);
        poleDirection = glm::normalize(off);
        return;
    }
    ctx.warning("limb1, limb2 and limb3 guides are in a straight line, so the bend direction is unknown; the pole goes " +
                std::string(legLike() ? "in front (+Z)" : "behind (-Z)") + ": move the " +
                (legLike() ? "knee" : "elbow") + " guide off the line");
    const Vec3 along = glm::length(c - a) > 1e-9 ? glm::normalize(c - a) : Vec3(0.0, -1.0, 0.0);
    poleDirection = fallbackPole - along * glm::dot(fallbackPole, along);
    if (glm::length(poleDirection) < 1e-6)
        poleDirection = Vec3(1.0, 0.0, 0.0) - along * along.x;
    poleDirection = glm::normalize(poleDirection);
    normal = glm::normalize(glm::cross(along, poleDirection));
    if (glm::dot(normal, fallbackNormal) < 0.0) // keep the side convention of bent limbs
        normal = -normal;
}

// Where the pole and the switch control sit, as shares of the limb's chain
// length (limb1 to limbK). The pole: three quarters of it out from the elbow or
// knee. The switch: beside the wrist or ankle, 0.12 m on the biped's arm
// (0.54 m) and leg (0.84 m), as when it was fixed in metres.
constexpr double kPoleDistance = 0.75;
constexpr double kArmSwitchDistance = 0.22;
constexpr double kLegSwitchDistance = 0.14;

// Spaces an IK control can follow: the world first, then the rig's named spaces.
const std::vector<std::string> kArmSpaces = {"world", "root", "cog", "chest", "head"};
// A front leg on a quadruped's chest follows the chest.
const std::vector<std::string> kLegSpaces = {"world", "root", "cog", "hips", "chest"};

void LimbBuilder::configure(BuildContext& ctx) const
{
    limb::addSpaceSwitches(ctx, legLike() ? kLegSpaces : kArmSpaces, legLike());
}

void LimbBuilder::generate(BuildContext& ctx) const
{
    const LimbGuide g = *guideOf(ctx);
    const std::size_t k = limbCount();
    Vec3 normal, poleDirection;
    bendOf(ctx, g, normal, poleDirection);
    const auto frames = limb::orientEffector(ctx, kit::chainFrames(g.points, normal), k); // limb1..limbK, end
    const RigNodeIndex world = ctx.space("world") != model::kNoNode ? ctx.space("world") : ctx.hookNode();

    // Clavicle / pelvis.
    RigNodeIndex attach = ctx.hookNode(), rootCtrl = model::kNoNode;
    limb::AutoClavicle autoClavicle;
    const Vec3 rootPosition = ctx.guidePosition(g.root);
    if (ctx.optionBool(rootOption())) {
        const Vec3 aim = g.points[0] - rootPosition;
        const Mat4 frame = kit::aimFrame(rootPosition, glm::length(aim) > 1e-9 ? aim : frames[0][0], normal);
        if (!legLike()) { // the clavicle hangs under the auto-clavicle's follow group
            autoClavicle = limb::addAutoClavicleGroups(ctx, attach, rootPosition, g.points[0], g.points[k - 1], g.root);
            if (autoClavicle.follow != model::kNoNode)
                attach = autoClavicle.follow;
        }
        const kit::Control root = kit::addControl(ctx, rootOption(), rootOption(), {}, attach, frame, g.root);
        kit::animate(ctx, root, kit::kRotate); // a clavicle or pelvis turns
        attach = root.ctrl;
        rootCtrl = attach;
        kit::addSkin(ctx, rootOption(), rootOption(), {}, attach, frame, g.root);
    }
    ctx.setHook(g.root, attach);
    const auto limbGroup = ctx.createNode(RigNodeKind::Group, "grps.limb", ctx.nodeName(model::NameRole::Group, "limb"), attach,
                                          frames[0], g.limb[0]);

    // FK controls.
    std::vector<RigNodeIndex> fk;
    RigNodeIndex parent = limb::addFkSpaceGroup(ctx, limbGroup, frames[0], g.limb[0]); // fk_space (configure())
    for (std::size_t i = 0; i < k; ++i) {
        const kit::Control control = kit::addControl(ctx, "fk." + std::to_string(i), "", int(i) + 1, parent, frames[i], g.limb[i]);
        kit::animate(ctx, control, kit::kRotate); // FK: rotation only
        parent = control.ctrl;
        fk.push_back(parent);
    }

    // IK controller, pole vector and the reverse foot.
    const Mat4 ikFrame = limb::ikControlFrame(ctx, g.points[k - 1], frames[k - 1], g.limb[k - 1]);
    // The IK control hangs under a space group that follows the space `ik_space` picks.
    const auto ikSpace = ctx.createNode(RigNodeKind::Group, "spaces.ik", ctx.nodeName(model::NameRole::Group, "ik_space"), world,
                                        ikFrame, g.limb[k - 1]);
    const kit::Control ikControl = kit::addControl(ctx, "ik", "ik", {}, ikSpace, ikFrame, g.limb[k - 1]);
    kit::animate(ctx, ikControl, kit::kTranslate | kit::kRotate);
    const auto ikCtrl = ikControl.ctrl;
    double chainLength = 0.0;
    for (std::size_t i = 1; i < k; ++i)
        chainLength += glm::length(g.points[i] - g.points[i - 1]);
    // Offsets are shares of the limb's own length, so a centimetre character's controls sit where a metre one's do.
    const Mat4 poleFrame = kit::uprightFrame(g.points[1] + poleDirection * (chainLength * kPoleDistance));
    // The pole hangs under a space group that follows the space `pv_space` picks (configure()).
    const auto poleSpace = limb::addPoleSpaceGroups(ctx, world, limbGroup, ikCtrl, poleFrame, g.limb[1]);
    const auto poleCtrl = kit::addControl(ctx, "pole", "pole", {}, poleSpace, poleFrame, g.limb[1]).ctrl;
    if (ctx.node(poleCtrl).kind == model::RigNodeKind::Controller)
        ctx.channels(poleCtrl).lock(3, 6); // only its position matters
    kit::animate(ctx, poleCtrl, kit::kTranslate);
    const auto pinCtrl = limb::addPinControl(ctx, poleSpace, g.points[1], g.limb[1]);
    RigNodeIndex effector = ikCtrl, toeTap = model::kNoNode;
    if (limb::hasReverseLock(ctx, legLike())) {
        const limb::ReverseLock lock = limb::addReverseLock(ctx, pivotsOf(ctx, g, normal, poleDirection), ikCtrl, legLike());
        effector = lock.effector;
        toeTap = lock.toeTap;
    }

    // IK chain (setup joints) and the blend chain everything else follows.
    std::vector<RigNodeIndex> ik, blend;
    RigNodeIndex ikParent = limbGroup, blendParent = limbGroup;
    for (std::size_t i = 0; i < k; ++i) {
        const std::string index = std::to_string(i);
        ikParent = kit::addSetup(ctx, RigNodeKind::Joint, "ik." + index, "ik", int(i) + 1, ikParent, frames[i], g.limb[i]);
        ik.push_back(ikParent);
        blendParent = kit::addSetup(ctx, RigNodeKind::Joint, "blend." + index, "blend", int(i) + 1, blendParent, frames[i], g.limb[i]);
        blend.push_back(blendParent);
    }
    // The FK/IK blend lives on one switch controller, which rides on the limb's end (wrist or ankle), off the side away from the pole.
    Mat4 switchFrame = frames[k - 1];
    const double switchDistance = chainLength * (legLike() ? kLegSwitchDistance : kArmSwitchDistance);
    switchFrame[3] = Vec4(g.points[k - 1] - poleDirection * switchDistance, 1.0);
    const auto settings = kit::addControl(ctx, "switch", "switch", {}, blend.back(), switchFrame, g.limb[k - 1]).ctrl;
    if (ctx.node(settings).kind == model::RigNodeKind::Controller)
        ctx.channels(settings).lock(0, model::ChannelSettings::kCount); // a settings holder: custom channels only
    kit::animate(ctx, settings, kit::kNothing);
    const AttributeRef weight = ctx.addAttribute(settings, "ik_blend", ctx.optionFloat("ik_blend"), 0.0, 1.0);
    // What only the IK does lives on the IK control: stretch, soft IK, volume and the pin.
    const AttributeRef stretch = ctx.addAttribute(ikCtrl, "stretch", ctx.optionBool("stretch") ? 1.0 : 0.0, 0.0, 1.0);
    const AttributeRef soft = ctx.addAttribute(ikCtrl, "soft_ik", ctx.optionFloat("soft_ik"), 0.0, 1.0);
    const AttributeRef volume = ctx.addAttribute(ikCtrl, "volume", ctx.optionBool("volume") ? 1.0 : 0.0, 0.0, 1.0);
    model::IkConstraint solver{.stretch = stretch, .soft = soft, .volume = volume, .volumePower = ctx.optionFloat("stomp_power")};
    std::vector<RigNodeIndex> ikTargets = {effector, poleCtrl};
    std::vector<RigNodeIndex> ikShown = {ikCtrl, poleCtrl};
    if (pinCtrl != model::kNoNode) {
        solver.pin = ctx.addAttribute(ikCtrl, "pin", 0.0, 0.0, 1.0);
        ikTargets.push_back(pinCtrl);
        ikShown.push_back(pinCtrl);
    }
    ctx.addConstraint("cns.ik", ik, ikTargets, solver);
    limb::connectAutoClavicle(ctx, autoClavicle, rootCtrl, ikCtrl, weight);
    for (std::size_t i = 0; i < k; ++i)
        ctx.addConstraint("cns.blend." + std::to_string(i), {blend[i]}, {fk[i], ik[i]}, model::BlendConstraint{.weight = weight});
    std::vector<RigNodeIndex> fkShown = fk;
    RigNodeIndex end = blend.back();
    if (legLike()) { // the ball joint: FK toe control or the reverse foot's toe tap
        const kit::Control toeControl = kit::addControl(ctx, "fk.ball", "toe", {}, fk.back(), frames[k], g.end);
        kit::animate(ctx, toeControl, kit::kRotate);
        const auto toeFk = toeControl.ctrl;
        fkShown.push_back(toeFk);
        const auto ikBall = kit::addSetup(ctx, RigNodeKind::Joint, "ik.ball", "ik_toe", {}, ik.back(), frames[k], g.end);
        ctx.addConstraint("cns.ik_ball", {ikBall}, {toeTap != model::kNoNode ? toeTap : ikCtrl}, model::OrientConstraint{});
        end = kit::addSetup(ctx, RigNodeKind::Joint, "blend.ball", "blend_toe", {}, blend.back(), frames[k], g.end);
        ctx.addConstraint("cns.blend.ball", {end}, {toeFk, ikBall}, model::BlendConstraint{.weight = weight});
    }

    // Skin: one joint per segment, twist joints spread along the upper and
    // lower segments, and blend joints halfway between segments at the bends.
    std::vector<RigNodeIndex> skin;
    for (std::size_t i = 0; i < k; ++i)
        skin.push_back(kit::addSkin(ctx, "limb." + std::to_string(i), "", int(i) + 1, blend[i], frames[i], g.limb[i]));
    if (legLike())
        kit::addSkin(ctx, "ball", "toe", {}, end, frames[k], g.end);
    limb::addBlendVisibility(ctx, weight, fkShown, ikShown);
    if (ctx.optionBool("do_skin")) {
        const limb::BendControls bend = limb::addBendControls(ctx, g.points, frames, g.limb, blend, limbGroup);
        const limb::AdvancedTwist advanced = limb::addAdvancedTwistAttributes(ctx, settings);
        const limb::TwistJoints twist =
            limb::addTwistJoints(ctx, g.points, frames, g.limb, blend, skin, limbGroup, bend.curveTargets, advanced.bias);
        limb::addAdvancedTwistRolls(ctx, advanced, twist, skin);
        limb::addTwistChains(ctx, twist, g.limb);
        if (ctx.optionBool("blend_joints"))
            for (std::size_t i = 1; i < k; ++i) {
                const auto joint = kit::addSkin(ctx, "mid." + std::to_string(i - 1), "mid", int(i), skin[i - 1], frames[i], g.limb[i]);
                ctx.addConstraint("cns.mid." + std::to_string(i - 1), {joint}, {blend[i - 1], blend[i]},
                                  model::OrientConstraint{.weights = {0.5, 0.5}}); // halfway
            }
    }

    for (std::size_t i = 0; i < k; ++i)
        ctx.setHook(g.limb[i], blend[i]);
    ctx.setHook(g.end, end);
    if (g.toe != model::kNoId)
        ctx.setHook(g.toe, end);
    for (const char* tag : {"heel", "bank_int", "bank_ext"})
        for (JointId j : ctx.taggedJoints(tag))
            ctx.setHook(j, blend.back());
}

} // namespace

std::unique_ptr<TemplateBuilder> makeLimbBuilder(LimbKind kind) { return std::make_unique<LimbBuilder>(kind); }

} // namespace rs::rigging
