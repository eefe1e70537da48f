#include "rigging/builders/BuilderKit.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace rs::rigging::kit {

std::pair<Vec3, std::size_t> alongChain(const std::vector<Vec3>& points, double share)
{
    double total = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i)
        total += glm::length(points[i] - points[i - 1]);
    double left = std::clamp(share, 0.0, 1.0) * total;
    for (std::size_t i = 1; i < points.size(); ++i) {
        const double span = glm::length(points[i] - points[i - 1]);
        if (left <= span || i + 1 == points.size())
            return {span > 1e-12 ? glm::mix(points[i - 1], points[i], std::min(left / span, 1.0)) : points[i], i - 1};
        left -= span;
    }
    return {points.empty() ? Vec3(0.0) : points.front(), 0};
}

Vec3 positionOf(const Mat4& m) { return Vec3(m[3]); }

Vec3 guideAxis(const BuildContext& ctx, model::JointId joint, int column, const Vec3& fallback)
{
    const Vec3 axis = Vec3(ctx.guideWorldMatrix(joint)[column]);
    return glm::length(axis) > 1e-9 ? glm::normalize(axis) : fallback;
}

Mat4 aimFrame(const Vec3& origin, const Vec3& aim, const Vec3& normal)
{
    Vec3 x = glm::length(aim) > 1e-12 ? glm::normalize(aim) : Vec3(1.0, 0.0, 0.0);
    Vec3 z = normal - x * glm::dot(normal, x);
    if (glm::length(z) < 1e-9) { // normal along the aim: any perpendicular will do
        z = std::abs(x.y) < 0.9 ? glm::cross(x, Vec3(0.0, 1.0, 0.0)) : glm::cross(x, Vec3(1.0, 0.0, 0.0));
    }
    z = glm::normalize(z);
    const Vec3 y = glm::cross(z, x);
    Mat4 m(1.0);
    m[0] = Vec4(x, 0.0);
    m[1] = Vec4(y, 0.0);
    m[2] = Vec4(z, 0.0);
    m[3] = Vec4(origin, 1.0);
    return m;
}

std::optional<Vec3> planeNormal(const Vec3& a, const Vec3& b, const Vec3& c)
{
    const Vec3 u = b - a, v = c - b;
    const double lu = glm::length(u), lv = glm::length(v);
    if (lu < 1e-9 || lv < 1e-9)
        return std::nullopt;
    const Vec3 n = glm::cross(u, v);
    if (glm::length(n) < 1e-4 * lu * lv) // under ~0.006 degrees: straight
        return std::nullopt;
    return glm::normalize(n);
}

std::vector<Mat4> chainFrames(const std::vector<Vec3>& points, const Vec3& fallbackNormal)
{
    std::vector<Mat4> frames;
    Vec3 normal = fallbackNormal;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (i + 1 >= points.size()) {
            Mat4 last = frames.empty() ? uprightFrame(points[i]) : frames.back();
            last[3] = Vec4(points[i], 1.0);
            frames.push_back(last);
            break;
        }
        if (i + 2 < points.size())
            if (auto n = planeNormal(points[i], points[i + 1], points[i + 2]))
                normal = *n;
        const Vec3 aim = points[i + 1] - points[i];
        if (glm::length(aim) < 1e-9 && !frames.empty()) { // overlapping guides: keep the previous orientation
            Mat4 same = frames.back();
            same[3] = Vec4(points[i], 1.0);
            frames.push_back(same);
            continue;
        }
        frames.push_back(aimFrame(points[i], aim, normal));
    }
    return frames;
}

Mat4 uprightFrame(const Vec3& origin) { return translationMatrix(origin); }

std::vector<Mat4> sideFrames(const std::vector<Vec3>& points, const Vec3& side)
{
    std::vector<Mat4> frames;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (i + 1 < points.size()) {
            frames.push_back(aimFrame(points[i], points[i + 1] - points[i], side));
        } else {
            Mat4 last = frames.empty() ? uprightFrame(points[i]) : frames.back();
            last[3] = Vec4(points[i], 1.0);
            frames.push_back(last);
        }
    }
    return frames;
}

Control addControl(BuildContext& ctx, const std::string& key, const std::string& token, std::optional<int> index,
                   model::RigNodeIndex parent, const Mat4& world, model::JointId source)
{
    Control c;
    c.offset = ctx.createNode(model::RigNodeKind::Group, "roots." + key, ctx.nodeName(model::NameRole::Offset, token, index),
                              parent, world, source);
    c.ctrl = c.offset;
    if (ctx.optionBool("do_ctrl"))
        c.ctrl = ctx.createNode(model::RigNodeKind::Controller, "ctrls." + key,
                                ctx.nodeName(model::NameRole::Controller, token, index), c.offset, world, source);
    return c;
}

void animate(BuildContext& ctx, model::RigNodeIndex node, std::uint16_t channels)
{
    if (node != model::kNoNode && ctx.node(node).kind == model::RigNodeKind::Controller)
        ctx.channels(node).animatable = channels;
}

void animate(BuildContext& ctx, const Control& control, std::uint16_t channels)
{
    if (control.ctrl != control.offset)
        animate(ctx, control.ctrl, channels);
}

model::RigNodeIndex addSkin(BuildContext& ctx, const std::string& key, const std::string& token, std::optional<int> index,
                            model::RigNodeIndex parent, const Mat4& world, model::JointId source)
{
    if (!ctx.optionBool("do_skin"))
        return model::kNoNode;
    return ctx.createNode(model::RigNodeKind::Joint, "skin." + key, ctx.nodeName(model::NameRole::Skin, token, index), parent,
                         world, source);
}

model::RigNodeIndex addSetup(BuildContext& ctx, model::RigNodeKind kind, const std::string& tag, const std::string& token,
                             std::optional<int> index, model::RigNodeIndex parent, const Mat4& world, model::JointId source)
{
    const auto role = kind == model::RigNodeKind::Joint ? model::NameRole::Skin : model::NameRole::Group;
    std::string name = ctx.nodeName(role, token, index);
    if (kind == model::RigNodeKind::Joint) // setup joints never look like skin joints
        name = ctx.nodeName(model::NameRole::Group, token, index);
    const auto node = ctx.createNode(kind, tag, name, parent, world, source);
    ctx.setHidden(node);
    return node;
}

std::optional<std::vector<Vec3>> positions(const BuildContext& ctx, const std::vector<model::JointId>& joints)
{
    std::vector<Vec3> out;
    out.reserve(joints.size());
    for (auto j : joints)
        out.push_back(ctx.guidePosition(j));
    return out;
}

std::optional<std::vector<model::JointId>> chainOfAtLeast(const BuildContext& ctx, std::size_t minimum, const std::string& what,
                                                          const std::string& parts)
{
    auto chain = ctx.structure("chain");
    if (!chain)
        return std::nullopt;
    if (chain->size() < minimum) {
        ctx.error(what + " needs at least " + std::to_string(minimum) + " guide joints" + parts + "; it has " +
                  std::to_string(chain->size()), "number");
        return std::nullopt;
    }
    std::string name = what;
    if (name.rfind("the ", 0) == 0) name = name.substr(4);
    else if (name.rfind("a ", 0) == 0) name = name.substr(2);
    checkSpacing(ctx, *chain, name);
    return chain;
}

bool checkSpacing(const BuildContext& ctx, const std::vector<model::JointId>& joints, const std::string& what)
{
    bool ok = true;
    for (std::size_t i = 1; i < joints.size(); ++i)
        if (glm::length(ctx.guidePosition(joints[i]) - ctx.guidePosition(joints[i - 1])) < 1e-3) {
            ctx.warning(what + ": guide joints " + std::to_string(i - 1) + " and " + std::to_string(i) +
                        " overlap (closer than 1 mm); move one of them");
            ok = false;
        }
    return ok;
}

int appendChain(std::vector<GuideJointSpec>& specs, int count, const Vec3& first, const Vec3& step, int parent)
{
    for (int i = 0; i < count; ++i)
        parent = appendJoint(specs, parent, i == 0 ? first : step);
    return parent;
}

int appendJoint(std::vector<GuideJointSpec>& specs, int parent, const Vec3& translate, std::vector<std::string> tags,
                std::string name)
{
    GuideJointSpec j;
    j.parent = parent;
    j.local.translate = translate;
    j.tags = std::move(tags);
    j.name = std::move(name);
    specs.push_back(std::move(j));
    return static_cast<int>(specs.size()) - 1;
}

double guideNumber(const std::map<std::string, Value>& guides, const std::string& name, double fallback)
{
    auto it = guides.find(name);
    if (it == guides.end())
        return fallback;
    if (auto* d = std::get_if<double>(&it->second)) return *d;
    if (auto* i = std::get_if<long long>(&it->second)) return static_cast<double>(*i);
    return fallback;
}

void addSpaceSwitch(BuildContext& ctx, model::RigNodeIndex group, model::RigNodeIndex control, const std::string& option,
                    const std::string& tag, model::RigNodeIndex first, const std::vector<std::string>& spaces, bool orientOnly,
                    const std::string& attribute)
{
    std::vector<Space> named;
    for (std::size_t i = 0; i < spaces.size(); ++i)
        named.push_back({spaces[i], i == 0 ? first : model::kNoNode});
    addSpaceSwitch(ctx, group, control, option, tag, named, orientOnly, attribute);
}

void addSpaceSwitch(BuildContext& ctx, model::RigNodeIndex group, model::RigNodeIndex control, const std::string& option,
                    const std::string& tag, const std::vector<Space>& spaces, bool orientOnly, const std::string& attribute)
{
    // Only the spaces this rig has are offered: an entry that resolved to
    // nothing would follow entry 0 while the menu said otherwise.
    const std::string chosen = ctx.optionString(option);
    const std::string menu = "the '" + attribute + "' menu of " + ctx.node(control).name;
    std::vector<model::RigNodeIndex> targets;
    std::vector<std::string> labels;
    int index = 0;
    for (std::size_t i = 0; i < spaces.size(); ++i) {
        const model::RigNodeIndex target = spaces[i].node != model::kNoNode ? spaces[i].node : ctx.space(spaces[i].name);
        if (target == model::kNoNode) {
            // A space the template merely offers is left out quietly (a rig
            // without a spine has no chest to follow); the one the option
            // picks is the rigger's (or the template's) choice, so say so.
            if (spaces[i].name == chosen)
                ctx.warning("the default space '" + chosen + "' is not a space of this rig, so " + menu +
                                " leaves it out and the control follows '" + spaces.front().name + "' by default",
                            option);
            continue;
        }
        if (spaces[i].name == chosen)
            index = int(targets.size());
        targets.push_back(target);
        labels.push_back(spaces[i].name);
    }
    const model::AttributeRef choice = ctx.addEnumAttribute(control, attribute, index, labels);
    ctx.addConstraint(tag, {group}, targets, model::SpaceConstraint{.choice = choice, .orientOnly = orientOnly});
}

} // namespace rs::rigging::kit
