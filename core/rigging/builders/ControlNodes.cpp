#include "rigging/builders/ControlNodes.h"

#include "templates/Manifest.h"
#include "templates/NodeNames.h"

#include <algorithm>

namespace rs::rigging {

namespace {

bool declares(const BuildContext& ctx, const char* name) { return ctx.manifest().findOpt(name) != nullptr; }

// rotate_order auto, for a chain whose joints aim aim_axis down it and bend
// about up_axis (a curl, a bend towards up_dir): the twist turns first, the
// side swing next and the bend last, outermost, so the chain bends all the way
// without gimbal lock (only the seldom-used swing sits in the middle). From
// the template's aim_axis / up_axis (x / z where it has none); signs do not matter.
std::string autoRotateOrder(const BuildContext& ctx)
{
    auto letter = [&](const char* option, char fallback) {
        if (!declares(ctx, option))
            return fallback;
        const std::string axis = ctx.optionString(option);
        return axis.empty() ? fallback : axis.back();
    };
    const char aim = letter("aim_axis", 'x'), up = letter("up_axis", 'z');
    std::string order{aim};
    for (const char third : {'x', 'y', 'z'})
        if (third != aim && third != up)
            order += third;
    return order + up;
}

// The add_nodes list split at `c`; false (reported) when a name is bad.
bool readAddNodes(const BuildContext& ctx, ControlNodeOptions& o)
{
    const auto names = ctx.optionList("add_nodes");
    if (!names)
        return false;
    bool ok = true;
    for (const std::string& problem : templates::addNodesProblems(*names)) {
        ctx.error("add_nodes " + problem, "add_nodes");
        ok = false;
    }
    bool pastController = false;
    for (const std::string& name : *names) {
        if (name == "c")
            pastController = true;
        else
            (pastController ? o.below : o.above).push_back(name);
    }
    return ok;
}

} // namespace

bool ControlNodeOptions::hasPose() const { return std::find(above.begin(), above.end(), "pose") != above.end(); }

std::optional<ControlNodeOptions> readControlNodes(const BuildContext& ctx)
{
    ControlNodeOptions o;
    bool ok = true;
    if (declares(ctx, "add_nodes"))
        ok = readAddNodes(ctx, o);
    if (declares(ctx, "do_pose") && ctx.optionBool("do_pose")) {
        if (std::find(o.below.begin(), o.below.end(), "pose") != o.below.end()) {
            ctx.error("add_nodes puts 'pose' under the controller and do_pose puts it above; drop one", "add_nodes");
            ok = false;
        } else if (!o.hasPose()) {
            o.above.insert(o.above.begin(), "pose"); // right under the offset, as Mikan's do_pose
        }
    }
    if (declares(ctx, "parent_scale"))
        o.parentScale = ctx.optionBool("parent_scale");
    if (declares(ctx, "flip_orient"))
        o.flipOrient = ctx.optionBool("flip_orient");
    if (declares(ctx, "rotate_order")) {
        const std::string text = ctx.optionString("rotate_order");
        if (const auto order = model::parseRotateOrder(text == "auto" ? autoRotateOrder(ctx) : text)) {
            o.rotateOrder = *order;
        } else {
            ctx.error("'" + text + "' is no rotate order (xyz, yzx, zxy, xzy, yxz, zyx, auto)", "rotate_order");
            ok = false;
        }
    }
    if (!ok)
        return std::nullopt;
    return o;
}

ControlStack addControlStack(BuildContext& ctx, const ControlNodeOptions& o, const std::string& key, const std::string& token,
                             std::optional<int> index, model::RigNodeIndex parent, const Mat4& world, model::JointId source,
                             bool chained)
{
    ControlStack s;
    s.flipped = o.flipOrient && ctx.mirrored();
    // createNode maps W to M W M; W M comes out as M W, the reflected frame.
    const Mat4 frame = s.flipped ? world * ctx.mirrorMatrix() : world;
    s.offset = ctx.createNode(model::RigNodeKind::Group, "roots." + key, ctx.nodeName(model::NameRole::Offset, token, index), parent,
                              frame, source);
    if (chained && !o.parentScale && parent != model::kNoNode && ctx.node(parent).kind == model::RigNodeKind::Controller)
        ctx.setScaleCompensate(s.offset, true);
    model::RigNodeIndex inner = s.offset;
    for (const std::string& name : o.above) {
        inner = ctx.createNode(model::RigNodeKind::Group, "nodes." + name + "." + key, ctx.markedName(name, token, index), inner, frame,
                               source);
        if (name == "pose")
            s.pose = inner;
    }
    s.ctrl = inner;
    if (ctx.optionBool("do_ctrl")) {
        s.ctrl = ctx.createNode(model::RigNodeKind::Controller, "ctrls." + key, ctx.nodeName(model::NameRole::Controller, token, index),
                                inner, frame, source);
        ctx.channels(s.ctrl).rotateOrder = o.rotateOrder;
    }
    s.skinParent = s.ctrl;
    for (const std::string& name : o.below)
        s.skinParent = ctx.createNode(model::RigNodeKind::Group, "nodes." + name + "." + key, ctx.markedName(name, token, index),
                                      s.skinParent, world, source);
    return s;
}

double driveFactor(const BuildContext& ctx, const ControlStack& stack, model::DriveOutput output, double factor)
{
    if (!stack.flipped || output == model::DriveOutput::Scale)
        return factor;
    const Mat4& m = ctx.mirrorMatrix();
    const int axis = static_cast<int>(output);
    return factor * m[(axis + 1) % 3][(axis + 1) % 3] * m[(axis + 2) % 3][(axis + 2) % 3];
}

} // namespace rs::rigging
