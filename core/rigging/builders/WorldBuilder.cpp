// world.character / world.prop: the base structure of every rig (seed 004).
// world.default (Mikan's default root) is WorldDefaultBuilder below.
//
// The spaces every world template names for other templates' space switches:
//  - `world`: what carries the whole rig, following the world and move
//    controllers (and the character's scale and post scale), but no body part.
//    Limbs hang their IK and pole space groups under it, so an IK control in
//    `world` stays planted while the body moves and is carried when the
//    animator places the character. Not the scene origin (the IK would stay
//    behind when the character is placed) and not Mikan's `space.world`, the
//    world controller alone (Mikan's limbs default to their hook and offer
//    world and move apart; ours default to `world`, so moving the move
//    controller would leave hands and feet behind).
//  - `ground`: the world controller alone, what the rig travels over (a
//    wheel rolls as it moves relative to it): Mikan's `space.world`.
//  - `move`: the move controller.
//  - `root`: where children hang.
//
//   root_gp
//   ├─ ctrl_gp > world (all) > move (sub) > scale > post_transform > fly   <- children hook here
//   ├─ joint_gp > root skin joint (follows the post transform)
//   ├─ setup_gp (hidden: IK handles, spline curves, helpers)
//   └─ model_gp (meshes)
#include "rigging/builders/Builders.h"

#include "rigging/builders/BuilderKit.h"

namespace rs::rigging {

namespace {

using model::NameRole;
using model::RigNodeKind;

class WorldBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                            const std::map<std::string, Value>&) const override
    {
        // world (.) at the origin and its child root (/1), where the character hangs.
        return {GuideJointSpec{-1, {}, {}, {}}, GuideJointSpec{0, {}, {}, {}}};
    }

    bool gather(const BuildContext& ctx) const override
    {
        return ctx.structure("world") && ctx.structure("root");
    }

    void generate(BuildContext& ctx) const override
    {
        const model::JointId world = ctx.structure("world")->front();
        const model::JointId root = ctx.structure("root")->front();
        // World, move and scale stay axis-aligned: animators expect world axes here.
        const Mat4 worldFrame = kit::uprightFrame(ctx.guidePosition(world));
        const Mat4 rootFrame = kit::uprightFrame(ctx.guidePosition(root));
        const bool controllers = ctx.optionBool("do_ctrl");

        auto group = [&](const std::string& key, model::RigNodeIndex parent) {
            return ctx.createNode(RigNodeKind::Group, "grps." + key, ctx.nodeName(NameRole::Group, key), parent, worldFrame);
        };
        auto control = [&](const std::string& key, model::RigNodeIndex parent, const Mat4& frame, model::JointId source) {
            if (!controllers)
                return ctx.createNode(RigNodeKind::Group, "hooks." + key, ctx.nodeName(NameRole::Offset, key), parent, frame, source);
            return ctx.createNode(RigNodeKind::Controller, "ctrls." + key, ctx.nodeName(NameRole::Controller, key), parent, frame, source);
        };

        const auto rootGroup = group("root", model::kNoNode);
        const auto ctrlGroup = group("ctrl", rootGroup);
        const auto jointGroup = group("joint", rootGroup);
        const auto setupGroup = group("setup", rootGroup);
        ctx.setHidden(setupGroup);
        const auto modelGroup = group("model", rootGroup);

        // Seed 004: world and move translate and turn; only the scale control scales.
        const auto worldNode = control("world", ctrlGroup, worldFrame, world);
        kit::animate(ctx, worldNode, kit::kTranslate | kit::kRotate);
        const auto moveNode = control("move", worldNode, worldFrame, world);
        model::RigNodeIndex top = moveNode;
        kit::animate(ctx, top, kit::kTranslate | kit::kRotate);
        if (ctx.optionBool("do_scale")) {
            top = control("scale", top, worldFrame, world);
            kit::animate(ctx, top, kit::kTranslate | kit::kRotate | kit::kScale);
        }
        const auto post = ctx.createNode(RigNodeKind::Group, "grps.post", ctx.nodeName(NameRole::Group, "post"), top, worldFrame);
        // Seed 004's post transform: the rigger's overall scale of the character,
        // set once (not animated) and applied below the animators' controls.
        const model::AttributeRef postScale = ctx.addAttribute(post, "post_scale", 1.0, 0.0001, 1000.0);
        ctx.addConstraint("cns.post_scale", {post}, {},
                          model::DriveConstraint{.value = postScale,
                                                 .output = model::DriveOutput::Scale,
                                                 .factor = 1.0,
                                                 .response = model::DriveClamped{.low = 0.0001, .high = 1000.0}});
        model::RigNodeIndex anchor = post;
        if (ctx.optionBool("do_fly")) {
            anchor = control("fly", post, rootFrame, root);
            kit::animate(ctx, anchor, kit::kTranslate | kit::kRotate);
        }

        ctx.setHook(world, worldNode);
        ctx.setHook(root, anchor);
        ctx.defineSpace("world", post); // see the top of the file
        ctx.defineSpace("ground", worldNode);
        ctx.defineSpace("move", moveNode);
        ctx.defineSpace("root", anchor);
        ctx.defineSpace("joint", jointGroup); // where isolate_skin hangs the top skin joints (Mikan's ::bind)
        ctx.defineSpace("setup", setupGroup);
        ctx.defineSpace("model", modelGroup);
        if (ctx.optionBool("do_skin")) {
            const auto skin = ctx.createNode(RigNodeKind::Joint, "skin.root", ctx.nodeName(NameRole::Skin, "root"), jointGroup,
                                             rootFrame, root);
            ctx.addConstraint("cns.root", {skin}, {anchor}, model::ParentConstraint{});
        }
    }
};

// world.default, Mikan's default root: a world controller and a move
// controller under it at the one guide joint, nothing else. It names the
// spaces of the top of the file: `world` and `root` are the move control (or
// the hook group), `ground` the world control, `move` the move control. With
// the `hook` option the children hang under a group beside the controls that
// follows the move control (Mikan's hook_move: a flat hierarchy), otherwise
// under the move control itself.
class WorldDefaultBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                            const std::map<std::string, Value>&) const override
    {
        return {GuideJointSpec{-1, {}, {}, {}}};
    }

    bool gather(const BuildContext& ctx) const override { return ctx.structure("world").has_value(); }

    void generate(BuildContext& ctx) const override
    {
        const model::JointId world = ctx.structure("world")->front();
        const Mat4 frame = kit::uprightFrame(ctx.guidePosition(world));
        const auto worldNode = control(ctx, "world", ctx.hookNode(), frame, world);
        const auto moveNode = control(ctx, "move", worldNode, frame, world);
        model::RigNodeIndex anchor = moveNode;
        if (ctx.optionBool("hook")) {
            anchor = ctx.createNode(RigNodeKind::Group, "hooks.root", ctx.nodeName(NameRole::Group, "hook_move"), ctx.hookNode(),
                                    frame, world);
            ctx.addConstraint("cns.hook", {anchor}, {moveNode}, model::ParentConstraint{});
        }
        ctx.setHook(world, anchor);
        ctx.defineSpace("world", anchor); // see the top of the file
        ctx.defineSpace("ground", worldNode);
        ctx.defineSpace("move", moveNode);
        ctx.defineSpace("root", anchor);
        if (ctx.optionBool("do_skin")) // the export skeleton's one root, which child templates' skin joints hang under
            ctx.createNode(RigNodeKind::Joint, "skin.root", ctx.nodeName(NameRole::Skin, "root"), anchor, frame, world);
    }

private:
    static model::RigNodeIndex control(BuildContext& ctx, const std::string& key, model::RigNodeIndex parent, const Mat4& frame,
                                       model::JointId source)
    {
        if (!ctx.optionBool("do_ctrl"))
            return ctx.createNode(RigNodeKind::Group, "hooks." + key, ctx.nodeName(NameRole::Offset, key), parent, frame, source);
        return ctx.createNode(RigNodeKind::Controller, "ctrls." + key, ctx.nodeName(NameRole::Controller, key), parent, frame, source);
    }
};

} // namespace

std::unique_ptr<TemplateBuilder> makeWorldBuilder() { return std::make_unique<WorldBuilder>(); }
std::unique_ptr<TemplateBuilder> makeWorldDefaultBuilder() { return std::make_unique<WorldDefaultBuilder>(); }

} // namespace rs::rigging
