#include "build/builders/Builders.h"

namespace rs::build {

namespace {

class WorldBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                            const std::map<std::string, Value>&) const override
    {
        // world (.) at the origin and its child root (/1), where the character hangs.
        return {GuideJointSpec{-1, {}, {}}, GuideJointSpec{0, {}, {}}};
    }

    bool gather(const BuildContext& ctx) const override
    {
        return ctx.structure("world") && ctx.structure("root");
    }

    void generate(BuildContext& ctx) const override
    {
        const model::JointId world = ctx.structure("world")->front();
        const model::JointId root = ctx.structure("root")->front();
        // World and move stay axis-aligned: animators expect world-space axes here.
        const Mat4 worldMatrix = translationMatrix(translationOf(ctx.guideWorldMatrix(world)));
        const Mat4 rootMatrix = translationMatrix(translationOf(ctx.guideWorldMatrix(root)));
        const bool controllers = ctx.optionBool("do_ctrl");
        const auto kind = controllers ? model::RigNodeKind::Controller : model::RigNodeKind::Group;
        const auto role = controllers ? model::NameRole::Controller : model::NameRole::Offset;

        const auto worldNode = ctx.createNode(kind, controllers ? "ctrls.world" : "hooks.world",
                                              ctx.nodeName(role, "world"), model::kNoNode, worldMatrix);
        const auto moveNode = ctx.createNode(kind, controllers ? "ctrls.move" : "hooks.move",
                                             ctx.nodeName(role, "move"), worldNode, rootMatrix);
        ctx.setHook(world, worldNode);
        ctx.setHook(root, moveNode);
        if (ctx.optionBool("do_skin"))
            ctx.createNode(model::RigNodeKind::Joint, "skin.root", ctx.nodeName(model::NameRole::Skin, "root"), moveNode, rootMatrix);
    }
};

} // namespace

std::unique_ptr<TemplateBuilder> makeWorldBuilder() { return std::make_unique<WorldBuilder>(); }

} // namespace rs::build
