// Each mod kind applied to one copy, with the rig's own mechanisms: a space is
// one more target (and label) of the control's space constraint, a constraint
// is a typed RigConstraint, a plug is a custom attribute or a controller's
// channel settings, a connection and driven keys are DrivenKeyConstraints,
// hide is the node's `hidden` flag (and its curves), vdag its virtual parent.
#include "rigging/ModStage.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace rs::rigging {

using model::kNoNode;
using model::RigNodeIndex;

namespace {

constexpr std::size_t kMaxSpaceTargets = 16; // the evaluator's limit

model::RigAttribute* attributeOf(model::RigNode& node, const std::string& name)
{
    auto it = std::find_if(node.attributes.begin(), node.attributes.end(), [&](auto& x) { return x.name == name; });
    return it == node.attributes.end() ? nullptr : &*it;
}

// A space's label when the mod gives none: the target tag's last segment
// ("ctrls.chest": "chest"), with the one before for an index ("ctrls.fk.2": "fk2").
std::string defaultLabel(const std::string& tag)
{
    const auto dot = tag.rfind('.');
    if (dot == std::string::npos || dot == 0)
        return tag;
    const std::string last = tag.substr(dot + 1);
    if (last.empty() || !std::all_of(last.begin(), last.end(), [](unsigned char c) { return std::isdigit(c); }))
        return last;
    const auto before = tag.rfind('.', dot - 1);
    return tag.substr(before == std::string::npos ? 0 : before + 1, dot - (before == std::string::npos ? 0 : before + 1)) + last;
}

} // namespace

bool ModApplication::hasChannel(RigNodeIndex node, const std::string& channel, const std::string& role)
{
    model::RigNode& n = a.rig.nodes[node];
    if (model::channelIndex(channel) >= 0 && n.kind == model::RigNodeKind::Controller)
        return true;
    if (attributeOf(n, channel))
        return true;
    warn(role + " '" + n.path + "@" + channel + "': the node has no channel '" + channel + "'" +
             (model::channelIndex(channel) >= 0 ? " (only controllers have transform channels)" : "") +
             "; the mod is kept in the guide",
         Subject::ofNode(n.key));
    return false;
}

void ModApplication::lockChannel(RigNodeIndex node, const std::string& channel)
{
    model::RigNode& n = a.rig.nodes[node];
    if (const int t = model::channelIndex(channel); t >= 0)
        n.channels.lock(t);
    else if (model::RigAttribute* attribute = attributeOf(n, channel))
        attribute->locked = true;
}

bool ModApplication::addDrivenKey(model::DrivenKeyConstraint settings, const std::string& what)
{
    // A loop: the driver is (through other driven keys) computed from the driven channel.
    std::vector<model::ChannelRef> upstream{settings.driver};
    for (std::size_t k = 0; k < upstream.size() && k < 100000; ++k) {
        if (upstream[k] == settings.driven) {
            warn(what + " would make a loop of driven keys (" + a.rig.nodes[settings.driven.node].path + "@" +
                     settings.driven.channel + " drives its own driver); the mod is kept in the guide",
                 Subject::ofNode(a.rig.nodes[settings.driven.node].key));
            return false;
        }
        for (const model::RigConstraint& c : a.rig.constraints)
            if (const auto* key = std::get_if<model::DrivenKeyConstraint>(&c.settings); key && key->driven == upstream[k])
                upstream.push_back(key->driver);
    }
    model::RigConstraint c;
    c.key = constraintKey(what);
    c.path = constraintPath(what);
    c.owner = c.key.instance;
    c.driven = {settings.driven.node};
    c.targets = {settings.driver.node};
    lockChannel(settings.driven.node, settings.driven.channel);
    c.settings = std::move(settings);
    a.rig.constraints.push_back(std::move(c));
    return true;
}

void ModApplication::space(const model::SpaceMod& m)
{
    const auto ctrl = resolve(m.node, "node");
    const auto target = resolve(m.target, "target");
    if (!ctrl || !target)
        return;
    const std::string label = m.label.empty() ? defaultLabel(a.rig.nodes[*target].key.tag) : m.label;
    auto it = std::find_if(a.rig.constraints.begin(), a.rig.constraints.end(), [&](const model::RigConstraint& c) {
        const auto* s = std::get_if<model::SpaceConstraint>(&c.settings);
        return s && s->choice.node == *ctrl && s->choice.attribute == m.attribute;
    });
    if (it != a.rig.constraints.end())
        addSpace(*it, *ctrl, *target, label, m);
    else
        makeSpaceSwitch(*ctrl, *target, label, m);
}

void ModApplication::addSpace(model::RigConstraint& spaces, RigNodeIndex ctrl, RigNodeIndex target, const std::string& label,
                              const model::SpaceMod& m)
{
    const model::RigNode& node = a.rig.nodes[ctrl];
    model::RigAttribute* choice = attributeOf(a.rig.nodes[ctrl], m.attribute);
    if (!choice || std::count(choice->labels.begin(), choice->labels.end(), label) > 0 || spaces.targets.size() >= kMaxSpaceTargets) {
        warn("'" + node.path + "' " + (choice && spaces.targets.size() >= kMaxSpaceTargets ? "has 16 spaces already"
                                                                                            : "already has a space '" + label + "'") +
                 "; give another label",
             Subject::ofNode(node.key));
        return;
    }
    if (dependsOn(target, spaces.driven.front())) {
        warn("'" + text(m.target) + "' follows '" + node.path + "' itself; it cannot be its space", Subject::ofNode(node.key));
        return;
    }
    spaces.targets.push_back(target);
    choice->labels.push_back(label);
    choice->max = double(choice->labels.size() - 1);
}

// No switch yet: one on the control's offset group, the group's own parent being space 0.
void ModApplication::makeSpaceSwitch(RigNodeIndex ctrl, RigNodeIndex target, const std::string& label, const model::SpaceMod& m)
{
    model::Rig& rig = a.rig;
    const Subject subject = Subject::ofNode(rig.nodes[ctrl].key);
    const RigNodeIndex group = rig.nodes[ctrl].parent;
    std::string problem;
    if (rig.nodes[ctrl].kind != model::RigNodeKind::Controller || group == kNoNode || group == 0 ||
        rig.nodes[group].kind != model::RigNodeKind::Group)
        problem = "'" + rig.nodes[ctrl].path + "' is not a controller under an offset group; it cannot have a space switch";
    else if (attributeOf(rig.nodes[ctrl], m.attribute))
        problem = "'" + rig.nodes[ctrl].path + "' has a channel '" + m.attribute + "' that is not a space switch";
    else if (dependsOn(target, group))
        problem = "'" + text(m.target) + "' follows '" + rig.nodes[ctrl].path + "' itself; it cannot be its space";
    for (const model::RigConstraint& c : rig.constraints)
        if (problem.empty() && c.kind() != model::ConstraintKind::Visibility && c.kind() != model::ConstraintKind::DrivenKey &&
            std::count(c.driven.begin(), c.driven.end(), group) > 0)
            problem = "its offset group '" + rig.nodes[group].path + "' is already placed by constraint '" + c.path +
                      "'; a space switch would fight it";
    if (!problem.empty()) {
        warn(problem, subject);
        return;
    }
    model::RigAttribute choice;
    choice.name = m.attribute;
    choice.max = 1.0;
    choice.labels = {"parent", label};
    rig.nodes[ctrl].attributes.push_back(choice);
    model::RigConstraint c;
    c.key = constraintKey("space");
    c.path = constraintPath("space");
    c.owner = c.key.instance;
    c.driven = {group};
    c.targets = {rig.nodes[group].parent, target};
    c.settings = model::SpaceConstraint{.choice = {ctrl, m.attribute}};
    rig.constraints.push_back(std::move(c));
}

void ModApplication::constraint(const model::ConstraintMod& m)
{
    const auto driven = resolve(m.node, "node");
    std::vector<RigNodeIndex> targets;
    bool ok = driven.has_value();
    for (const model::ModRef& t : m.targets)
        if (auto node = resolve(t, "target")) targets.push_back(*node);
        else ok = false;
    if (!ok)
        return;
    const model::RigNode& node = a.rig.nodes[*driven];
    if (*driven == 0) {
        warn("the rig root cannot be constrained", Subject::ofNode(node.key));
        return;
    }
    for (RigNodeIndex t : targets)
        if (dependsOn(t, *driven)) {
            warn("target '" + a.rig.nodes[t].path + "' follows '" + node.path + "' itself (a cycle); the mod is kept in the guide",
                 Subject::ofNode(node.key));
            return;
        }
    model::RigConstraint c;
    c.key = constraintKey(model::constraintKindName(m.kind));
    c.path = constraintPath(model::constraintKindName(m.kind));
    c.owner = c.key.instance;
    c.driven = {*driven};
    c.targets = targets;
    switch (m.kind) {
    case model::ConstraintKind::Point: c.settings = model::PointConstraint{m.weights, m.keepOffset}; break;
    case model::ConstraintKind::Orient: c.settings = model::OrientConstraint{m.weights, m.keepOffset}; break;
    case model::ConstraintKind::Scale: c.settings = model::ScaleConstraint{m.weights, m.keepOffset}; break;
    case model::ConstraintKind::Aim: c.settings = model::AimConstraint{m.aim, m.up}; break;
    default: c.settings = model::ParentConstraint{m.weights, m.keepOffset}; break;
    }
    a.rig.constraints.push_back(std::move(c));
}

bool ModApplication::parent(const model::ParentMod& m)
{
    const auto child = resolve(m.node, "node");
    const auto parent = resolve(m.parent, "parent");
    if (!child || !parent)
        return false;
    model::RigNode& node = a.rig.nodes[*child];
    if (*child == 0 || *child == *parent || dependsOn(*parent, *child)) {
        warn(*child == 0 ? "the rig root has no parent"
                         : "'" + a.rig.nodes[*parent].path + "' follows '" + node.path + "' (a cycle); it cannot be its parent",
             Subject::ofNode(node.key));
        return false;
    }
    node.parent = *parent;       // the world rest placement stays; its local matrix follows
    node.scaleCompensate = false; // it compensated its former parent's scale
    return *parent > *child;
}

void ModApplication::hide(const model::HideMod& m)
{
    for (const model::ModRef& ref : m.nodes)
        if (const auto node = resolve(ref, "node")) {
            if (*node == 0) warn("the rig root cannot be hidden", Subject::ofNode(a.rig.nodes[0].key));
            else a.rig.nodes[*node].hidden = true;
        }
}

void ModApplication::hideCurves(const model::HideMod& m)
{
    for (const model::ModRef& ref : m.nodes)
        if (const auto node = resolve(ref, "node"); node && *node != 0)
            for (model::ControllerCurve& curve : a.rig.nodes[*node].curves)
                curve.visible = false;
}

void ModApplication::plug(const model::PlugMod& m)
{
    const auto index = resolve(m.channel, "channel");
    if (!index)
        return;
    const std::string& name = m.channel.channel;
    if (const int t = model::channelIndex(name); t >= 0) {
        if (!plugTransform(*index, t, m))
            return;
    } else {
        plugAttribute(*index, m);
    }
    if (!m.from)
        return;
    const auto source = resolve(*m.from, "from");
    if (!source || !hasChannel(*source, m.from->channel, "from"))
        return;
    model::DrivenKeyConstraint settings;
    settings.driver = {*source, m.from->channel};
    settings.driven = {*index, name};
    settings.keys = {{0.0, 0.0}, {1.0, m.factor * channelSign(*source, m.from->channel) * channelSign(*index, name)}};
    settings.pre = settings.post = model::CurveInfinity::Linear;
    addDrivenKey(std::move(settings), "plug");
}

bool ModApplication::plugTransform(RigNodeIndex index, int t, const model::PlugMod& m)
{
    model::RigNode& node = a.rig.nodes[index];
    const std::string& name = m.channel.channel;
    const Subject subject = Subject::ofNode(node.key);
    if (node.kind != model::RigNodeKind::Controller) {
        warn("'" + node.path + "' is not a controller: it has no transform channel '" + name + "'", subject);
        return false;
    }
    if (m.type || !m.labels.empty())
        warn("'" + name + "' is a transform channel: its type is fixed ('type' and 'labels' are ignored)", subject);
    const double sign = channelSign(index, name); // the mirror image's value on a mirrored copy
    if (m.min.has_value() != m.max.has_value())
        warn("a transform channel's limit needs both 'min' and 'max' (the limit is ignored)", subject);
    else if (m.min)
        node.channels.limit(t, sign > 0 ? *m.min : -*m.max, sign > 0 ? *m.max : -*m.min);
    if (m.value) {
        const double value = sign * *m.value;
        const double kept = node.channels.isLimited(t) ? std::clamp(value, node.channels.minimum[t], node.channels.maximum[t]) : value;
        if (kept != value)
            warn("the default " + formatNumber(value) + " of '" + name + "' is outside its limits; using " + formatNumber(kept), subject);
        node.channels.defaults[t] = kept;
    }
    const auto bit = std::uint16_t(1u << t);
    if (m.keyable) node.channels.unkeyable = std::uint16_t(*m.keyable ? node.channels.unkeyable & ~bit : node.channels.unkeyable | bit);
    if (m.locked) node.channels.locked = std::uint16_t(*m.locked ? node.channels.locked | bit : node.channels.locked & ~bit);
    return true;
}

void ModApplication::plugAttribute(RigNodeIndex index, const model::PlugMod& m)
{
    model::RigNode& node = a.rig.nodes[index];
    const std::string& name = m.channel.channel;
    const Subject subject = Subject::ofNode(node.key);
    model::RigAttribute* attribute = attributeOf(node, name);
    if (!attribute) {
        model::RigAttribute created;
        created.name = name;
        created.labels = m.labels;
        if (!m.labels.empty()) created.max = double(m.labels.size() - 1);
        node.attributes.push_back(std::move(created));
        attribute = &node.attributes.back();
    } else if (m.type || !m.labels.empty()) {
        warn("'" + node.path + "' already has a channel '" + name + "': its type is kept", subject);
    }
    if (attribute->labels.empty() && m.type != model::PlugType::Bool) {
        if (m.min) attribute->min = *m.min;
        if (m.max) attribute->max = *m.max;
        if (attribute->min > attribute->max)
            attribute->max = attribute->min;
    }
    if (m.value) {
        attribute->value = std::clamp(*m.value, attribute->min, attribute->max);
        if (attribute->value != *m.value)
            warn("the default " + formatNumber(*m.value) + " of '" + name + "' is outside [" + formatNumber(attribute->min) + ", " +
                     formatNumber(attribute->max) + "]; using " + formatNumber(attribute->value), subject);
    }
    if (!attribute->labels.empty()) attribute->value = std::round(attribute->value);
    if (m.keyable) attribute->keyable = *m.keyable;
    if (m.locked) attribute->locked = *m.locked;
}

void ModApplication::drive(const model::DriveMod& m)
{
    const auto driver = resolve(m.driver, "driver");
    const auto driven = resolve(m.driven, "driven");
    if (!driver || !driven || !hasChannel(*driver, m.driver.channel, "driver") || !hasChannel(*driven, m.driven.channel, "driven"))
        return;
    model::DrivenKeyConstraint settings;
    settings.driver = {*driver, m.driver.channel};
    settings.driven = {*driven, m.driven.channel};
    settings.keys = m.keys;
    settings.smooth = m.smooth;
    settings.pre = m.pre;
    settings.post = m.post;
    // A mirrored copy: the curve of the mirror image (a negated driver reverses the keys, and pre and post).
    const double in = channelSign(*driver, m.driver.channel), out = channelSign(*driven, m.driven.channel);
    for (model::CurveKey& key : settings.keys) {
        key.in *= in;
        key.out *= out;
    }
    if (in < 0.0) {
        std::reverse(settings.keys.begin(), settings.keys.end());
        std::swap(settings.pre, settings.post);
    }
    addDrivenKey(std::move(settings), "drive");
}

void ModApplication::vdag(const model::VdagMod& m)
{
    const auto child = resolve(m.node, "node");
    const auto parent = resolve(m.parent, "parent");
    if (!child || !parent)
        return;
    model::Rig& rig = a.rig;
    model::RigNode& node = rig.nodes[*child];
    if (node.domain() != rig.nodes[*parent].domain()) {
        warn("'" + rig.nodes[*parent].path + "' is in the " + rig.nodes[*parent].domain() + " hierarchy, '" + node.path +
                 "' in the " + node.domain() + " one; a virtual parent must be of the same domain", Subject::ofNode(node.key));
        return;
    }
    for (RigNodeIndex up = *parent, guard = 0; up != kNoNode && guard < rig.nodes.size(); up = rig.nodes[up].virtualParent, ++guard)
        if (up == *child) {
            warn("'" + rig.nodes[*parent].path + "' hangs below '" + node.path + "' in the virtual hierarchy (a cycle)",
                 Subject::ofNode(node.key));
            return;
        }
    node.virtualParent = *parent;
    node.setInVirtualHierarchy(true);
    rig.nodes[*parent].setInVirtualHierarchy(true);
}

} // namespace rs::rigging
