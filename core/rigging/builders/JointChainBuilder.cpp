#include "rigging/builders/Builders.h"

#include "rigging/builders/BuilderKit.h"
#include "rigging/builders/ChainOrient.h"
#include "rigging/builders/ControlNodes.h"
#include "templates/Structure.h"

#include <glm/gtc/matrix_transform.hpp>

namespace rs::rigging {

Mat4 rigidFrame(const Mat4& world)
{
    Vec3 t, s;
    Quat r;
    decompose(world, t, r, s);
    Mat4 m = glm::mat4_cast(r);
    if (s.x < 0.0) // keep mirrored frames mirrored, but unit-sized
        m[0] = -m[0];
    m[3] = Vec4(t, 1.0);
    return m;
}

namespace {

std::optional<std::vector<model::JointId>> chainOf(const BuildContext& ctx)
{
    if (ctx.manifest().structureAddress("chain"))
        return ctx.structure("chain");
    return templates::StructureResolver(ctx.manifest(), ctx.instance()).chain();
}

// One link of a chain at `frame`: an offset group, the groups and controller
// of ControlNodes.h (or none) whose `animatable` channels animators touch
// (kit::animate) and a skin joint (or none), numbered from 1 in names; the
// guide joint hooks on the controller (or the innermost group). Returns what
// the next link hangs under.
model::RigNodeIndex addLink(BuildContext& ctx, const ControlNodeOptions& options, std::size_t i, const Mat4& frame,
                            model::RigNodeIndex parent, model::JointId guide, bool skin, std::uint16_t animatable)
{
    const std::string index = std::to_string(i);
    const int number = static_cast<int>(i) + 1;
    const ControlStack stack = addControlStack(ctx, options, index, "", number, parent, frame, model::kNoId, i > 0);
    kit::animate(ctx, stack.ctrl, animatable);
    if (skin)
        ctx.createNode(model::RigNodeKind::Joint, "skin." + index, ctx.nodeName(model::NameRole::Skin, "", number), stack.skinParent, frame);
    ctx.setHook(guide, stack.ctrl);
    return stack.ctrl;
}

class JointChainBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                            const std::map<std::string, Value>& guides) const override
    {
        long long count = 3;
        double length = 0.2;
        if (auto it = guides.find("number"); it != guides.end() && std::holds_alternative<long long>(it->second))
            count = std::max(1LL, std::get<long long>(it->second));
        if (auto it = guides.find("length"); it != guides.end() && std::holds_alternative<double>(it->second))
            length = std::get<double>(it->second);
        std::vector<GuideJointSpec> joints;
        for (long long i = 0; i < count; ++i) {
            GuideJointSpec j;
            j.parent = static_cast<int>(i) - 1;
            j.local.translate = Vec3(0.0, length, 0.0);
            joints.push_back(j);
        }
        return joints;
    }

    bool gather(const BuildContext& ctx) const override
    {
        auto chain = chainOf(ctx);
        if (!chain || !readChainOrient(ctx) || !readControlNodes(ctx))
            return false;
        for (std::size_t i = 1; i < chain->size(); ++i) {
            const double length = glm::length(translationOf(ctx.guideWorldMatrix((*chain)[i])) -
                                              translationOf(ctx.guideWorldMatrix((*chain)[i - 1])));
            if (length < 1e-6)
                ctx.warning("guide joints " + std::to_string(i - 1) + " and " + std::to_string(i) +
                            " of the chain overlap (zero-length segment)");
        }
        return true;
    }

    void generate(BuildContext& ctx) const override
    {
        const auto chain = *chainOf(ctx);
        const bool skin = ctx.optionBool("do_skin");
        const auto frames = orientFrames(ctx, chain);
        const ControlNodeOptions nodes = readControlNodes(ctx).value_or(ControlNodeOptions{}); // gather checked them
        model::RigNodeIndex parent = ctx.hookNode();
        for (std::size_t i = 0; i < chain.size(); ++i) {
            // A generic chain (props, modules without a builder of their own):
            // each control slides, turns and scales its part.
            parent = addLink(ctx, nodes, i, frames[i], parent, chain[i], skin, kit::kTranslate | kit::kRotate | kit::kScale);
        }
    }
};

// core.bones: one bone per segment (chain[:-1]): each controller and skin
// joint sits on its guide joint with its aim axis (+Y by default) aimed at the
// next guide joint, as a bone is drawn and exported; `orient` only chooses its
// roll (copy: the guide's own axes turned the smallest way, as before; world:
// the world axes turned so; auto: the up axis towards up_dir or the bend). The
// last guide joint is the tip, a hook without a controller.
class BoneChainBuilder final : public TemplateBuilder {
public:
    std::vector<GuideJointSpec> createGuide(const templates::TemplateManifest& manifest,
                                            const std::map<std::string, Value>& guides) const override
    {
        return JointChainBuilder().createGuide(manifest, guides);
    }

    bool gather(const BuildContext& ctx) const override
    {
        auto chain = chainOf(ctx);
        if (!chain)
            return false;
        if (chain->size() < 2) {
            ctx.error("core.bones needs at least two guide joints (a bone goes from one to the next)");
            return false;
        }
        return JointChainBuilder().gather(ctx);
    }

    void generate(BuildContext& ctx) const override
    {
        const auto chain = *chainOf(ctx);
        const bool skin = ctx.optionBool("do_skin");
        const auto frames = orientFrames(ctx, chain, true);
        const ControlNodeOptions nodes = readControlNodes(ctx).value_or(ControlNodeOptions{}); // gather checked them
        model::RigNodeIndex parent = ctx.hookNode();
        for (std::size_t i = 0; i + 1 < chain.size(); ++i)
            parent = addLink(ctx, nodes, i, frames[i], parent, chain[i], skin, kit::kRotate); // a bone turns about its head
        // The tip keeps the last bone's orientation.
        const auto tip = ctx.createNode(model::RigNodeKind::Group, "hooks.tip", ctx.nodeName(model::NameRole::Offset, "tip"), parent,
                                        frames.back());
        ctx.setHook(chain.back(), tip);
    }

};

} // namespace

std::unique_ptr<TemplateBuilder> makeJointChainBuilder() { return std::make_unique<JointChainBuilder>(); }
std::unique_ptr<TemplateBuilder> makeBoneChainBuilder() { return std::make_unique<BoneChainBuilder>(); }

} // namespace rs::rigging
