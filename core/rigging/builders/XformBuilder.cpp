// core.xform (and core.group, a manifest on the same builder): one controller
// at one guide joint, for props and vehicles' parts.
#include "rigging/builders/Builders.h"

#include "rigging/builders/BuilderKit.h"

#include <algorithm>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace rs::rigging {

namespace {

class XformBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                            const std::map<std::string, Value>&) const override
    {
        return {GuideJointSpec{-1, {}, {}, {}}};
    }

    bool gather(const BuildContext& ctx) const override { return ctx.structure("xform").has_value(); }

    void generate(BuildContext& ctx) const override
    {
        const model::JointId joint = ctx.structure("xform")->front();
        // copy_orient on: the guide joint's orientation; off: the world axes at it.
        Mat4 frame = rigidFrame(ctx.guideWorldMatrix(joint));
        if (!option(ctx, "copy_orient", true))
            frame = translationMatrix(translationOf(frame));
        // flip_orient, on a mirrored branch: the controller turned half a turn
        // about its X axis (authored space, so after the mirror its Y and Z
        // point the other way), so the same values on both sides move and turn
        // them as mirror images (translations negated). The skin joint keeps
        // the exact mirror frame: what deforms stays symmetric.
        const bool flipped = option(ctx, "flip_orient", false) && ctx.mirrored();
        const Mat4 controlFrame = flipped ? frame * Mat4(glm::rotate(Mat4(1.0), glm::pi<double>(), Vec3(1.0, 0.0, 0.0))) : frame;
        const auto control = kit::addControl(ctx, "xform", "", {}, ctx.hookNode(), controlFrame, joint);
        lockWhatIsNotDone(ctx, control);
        // joint on: the xform is a joint of the exported skeleton even without
        // do_skin (core.group): a prop's root bone, carrying what hangs under it.
        if (ctx.optionBool("do_skin"))
            kit::addSkin(ctx, "xform", "", {}, control.ctrl, frame, joint);
        else if (option(ctx, "joint", false))
            ctx.createNode(model::RigNodeKind::Joint, "skin.xform", ctx.nodeName(model::NameRole::Skin), control.ctrl, frame, joint);
        ctx.setHook(joint, control.ctrl);
    }

private:
    static bool declares(const BuildContext& ctx, const std::string& option) { return ctx.manifest().findOpt(option) != nullptr; }

    // An on/off option; `fallback` for a manifest on this builder without it.
    static bool option(const BuildContext& ctx, const std::string& name, bool fallback)
    {
        return declares(ctx, name) ? ctx.optionBool(name) : fallback;
    }

    // A prop's part: moved, turned and scaled, unless its do_* options say
    // otherwise; a channel it does not do is locked (core.group, a manifest
    // on this builder without them, does them all).
    static void lockWhatIsNotDone(BuildContext& ctx, const kit::Control& control)
    {
        std::uint16_t animatable = 0;
        const std::pair<const char*, std::uint16_t> kinds[] = {
            {"do_translate", kit::kTranslate}, {"do_rotate", kit::kRotate}, {"do_scale", kit::kScale}};
        for (const auto& [name, channels] : kinds)
            if (option(ctx, name, true))
                animatable = std::uint16_t(animatable | channels);
        kit::animate(ctx, control, animatable);
        if (control.ctrl == control.offset)
            return;
        model::ChannelSettings& channels = ctx.channels(control.ctrl);
        for (int c = 0; c < model::ChannelSettings::kCount; ++c)
            if (!((animatable >> c) & 1u))
                channels.lock(c);
        if (declares(ctx, "rotate_order"))
            if (const auto order = model::parseRotateOrder(ctx.optionString("rotate_order")))
                channels.rotateOrder = *order;
    }
};

} // namespace

std::unique_ptr<TemplateBuilder> makeXformBuilder() { return std::make_unique<XformBuilder>(); }

} // namespace rs::rigging
