#include "io/RigDump.h"

#include "io/YamlSupport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace rs::io {

namespace {

std::string fixed(double v)
{
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.6f", v);
    std::string text = buffer;
    if (text == "-0.000000")
        text = "0.000000";
    return text;
}

std::string channelsText(const model::ChannelSettings& c)
{
    std::string locked, limits;
    for (int i = 0; i < model::ChannelSettings::kCount; ++i) {
        if (c.isLocked(i))
            locked += std::string(locked.empty() ? "" : ", ") + model::channelName(i);
        if (c.isLimited(i))
            limits += std::string(limits.empty() ? "" : ", ") + model::channelName(i) + ": [" + fixed(c.minimum[i]) + ", " +
                      fixed(c.maximum[i]) + "]";
    }
    std::string hidden; // cleanup's lock and hide; nothing without it
    for (int i = 0; i < model::ChannelSettings::kCount; ++i)
        if (c.isHidden(i))
            hidden += std::string(hidden.empty() ? "" : ", ") + model::channelName(i);
    return std::string("{order: ") + model::rotateOrderName(c.rotateOrder) + ", locked: [" + locked + "], limits: {" + limits + "}" +
           (hidden.empty() ? "" : ", hidden: [" + hidden + "]") + "}";
}

std::string list(std::initializer_list<double> values)
{
    std::string out = "[";
    bool first = true;
    for (double v : values) {
        out += (first ? "" : ", ") + fixed(v);
        first = false;
    }
    return out + "]";
}

std::string colorText(const Vec3& c)
{
    char buffer[8];
    auto byte = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
    std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", byte(c.x), byte(c.y), byte(c.z));
    return buffer;
}

std::string nodeText(const model::Rig& rig, model::RigNodeIndex node)
{
    return node < rig.nodes.size() ? quoteIfNeeded(rig.nodes[node].path) : std::string("~");
}

std::string attributeText(const model::Rig& rig, const model::AttributeRef& a)
{
    return "{node: " + nodeText(rig, a.node) + ", attribute: " + quoteIfNeeded(a.attribute) + "}";
}

std::string attributeText(const model::Rig& rig, const std::optional<model::AttributeRef>& a)
{
    return a ? attributeText(rig, *a) : std::string("~");
}

std::string number(double v)
{
    return std::isinf(v) ? (v < 0.0 ? "-.inf" : ".inf") : fixed(v);
}

const char* boolText(bool b) { return b ? "true" : "false"; }

// The typed settings of one constraint, every field by name in declaration order
// (model/Constraint.h): absent attribute references are `~`. The fields added
// for bendy limbs (twist `bendy`, `lower`, `by_length`; IK `volume_power`) are written
// only when set off their defaults, so the dumps of rigs without them are
// byte for byte what they were.
class SettingsWriter {
public:
    SettingsWriter(std::ostream& out, const model::Rig& rig) : m_out(out), m_rig(rig) {}

    void operator()(const model::ParentConstraint& s) { weighted(s.weights, s.keepOffset); }
    void operator()(const model::OrientConstraint& s) { weighted(s.weights, s.keepOffset); }
    void operator()(const model::PointConstraint& s) { weighted(s.weights, s.keepOffset); }
    void operator()(const model::ScaleConstraint& s) { weighted(s.weights, s.keepOffset); }
    void operator()(const model::BlendConstraint& s)
    {
        field("weight", attributeText(m_rig, s.weight));
        field("keep_offset", boolText(s.keepOffset));
    }
    void operator()(const model::IkConstraint& s)
    {
        field("stretch", attributeText(m_rig, s.stretch));
        field("soft", attributeText(m_rig, s.soft));
        field("volume", attributeText(m_rig, s.volume));
        field("pin", attributeText(m_rig, s.pin));
        if (s.volumePower != model::IkConstraint{}.volumePower) // written when set, so older dumps stay as they were
            field("volume_power", number(s.volumePower));
    }
    void operator()(const model::TwistConstraint& s)
    {
        field("fraction", number(s.fraction));
        field("non_rolling", boolText(s.nonRolling));
        if (s.bendy) { // written when set, so the dumps of straight limbs stay as they were
            field("bendy", boolText(s.bendy));
            field("lower", boolText(s.lower));
            field("by_length", boolText(s.byLength));
        }
        if (s.bias) // written when set (advanced_twist), so older dumps stay as they were
            field("bias", attributeText(m_rig, s.bias));
    }
    void operator()(const model::VisibilityConstraint& s)
    {
        field("value", attributeText(m_rig, s.value));
        field("when", model::showWhenName(s.when));
        field("threshold", number(s.threshold));
    }
    void operator()(const model::RollConstraint& s)
    {
        field("axle", model::axisName(s.axle));
        field("forward", model::axisName(s.forward));
        field("radius", number(s.radius));
        field("amount", attributeText(m_rig, s.amount));
        field("mode", model::rollModeName(s.mode));
        field("jump", number(s.jump));
    }
    void operator()(const model::SplineConstraint& s)
    {
        field("stretch", attributeText(m_rig, s.stretch));
        field("volume", attributeText(m_rig, s.volume));
        field("slide", attributeText(m_rig, s.slide));
        // Written only when set, so rigs without them dump as before.
        if (s.rigidityStart)
            field("rigidity_start", attributeText(m_rig, s.rigidityStart));
        if (s.rigidityEnd)
            field("rigidity_end", attributeText(m_rig, s.rigidityEnd));
        if (s.scaleStretch)
            field("stretch_mode", "scale");
    }
    void operator()(const model::SpaceConstraint& s)
    {
        field("choice", attributeText(m_rig, s.choice));
        field("orient_only", boolText(s.orientOnly));
        field("keep_offset", boolText(s.keepOffset));
    }
    void operator()(const model::DriveConstraint& s)
    {
        field("value", attributeText(m_rig, s.value));
        field("output", model::driveOutputName(s.output));
        field("factor", number(s.factor));
        if (const auto* clamped = std::get_if<model::DriveClamped>(&s.response)) {
            field("response", "clamped");
            field("low", number(clamped->low));
            field("high", number(clamped->high));
        } else if (const auto* up = std::get_if<model::DriveUpToBreak>(&s.response)) {
            field("response", "up_to_break");
            field("break", attributeText(m_rig, up->breakAngle));
        } else if (const auto* past = std::get_if<model::DrivePastBreak>(&s.response)) {
            field("response", "past_break");
            field("break", attributeText(m_rig, past->breakAngle));
        }
    }
    void operator()(const model::CarryConstraint& s)
    {
        std::string carried = "[";
        for (std::size_t i = 0; i < s.carried.size(); ++i)
            carried += (i ? ", " : "") + nodeText(m_rig, s.carried[i]);
        field("carried", carried + "]");
    }
    void operator()(const model::AimConstraint& s)
    {
        field("aim", model::axisName(s.aim));
        field("up", model::axisName(s.up));
        if (s.weight) // written when set, so the dumps of full aims stay as they were
            field("weight", attributeText(m_rig, s.weight));
    }

    void operator()(const model::DrivenKeyConstraint& s)
    {
        auto channel = [&](const model::ChannelRef& c) {
            return "{node: " + nodeText(m_rig, c.node) + ", channel: " + quoteIfNeeded(c.channel) + "}";
        };
        field("driver_channel", channel(s.driver)); // "driven" is the constraint's driven nodes
        field("driven_channel", channel(s.driven));
        std::string keys = "[";
        for (std::size_t i = 0; i < s.keys.size(); ++i)
            keys += (i ? ", [" : "[") + number(s.keys[i].in) + ", " + number(s.keys[i].out) + "]";
        field("keys", keys + "]");
        field("smooth", boolText(s.smooth));
        field("pre", model::curveInfinityName(s.pre));
        field("post", model::curveInfinityName(s.post));
    }

private:
    void field(const char* name, const std::string& text) { m_out << "    " << name << ": " << text << "\n"; }
    void weighted(const std::vector<double>& weights, bool keepOffset)
    {
        std::string text = "[";
        for (std::size_t i = 0; i < weights.size(); ++i)
            text += (i ? ", " : "") + number(weights[i]);
        field("weights", text + "]");
        field("keep_offset", boolText(keepOffset));
    }

    std::ostream& m_out;
    const model::Rig& m_rig;
};

} // namespace

std::string writeRigDump(const model::Rig& rig)
{
    std::ostringstream out;
    out << "# Rigsmith rig dump: rest pose, metres, quaternions as [x, y, z, w].\n";
    out << "rigsmith_rig: 1\n";
    out << "nodes:\n";
    for (const auto& n : rig.nodes) {
        out << "  - id: " << quoteIfNeeded(n.path) << "\n";
        out << "    name: " << quoteIfNeeded(n.name) << "\n";
        out << "    kind: " << model::kindName(n.kind) << "\n";
        if (n.parent != model::kNoNode)
            out << "    parent: " << quoteIfNeeded(rig.nodes[n.parent].path) << "\n";
        if (n.isInVirtualHierarchy())
            out << "    virtual_parent: "
                << (n.virtualParent == model::kNoNode ? std::string("~") : quoteIfNeeded(rig.nodes[n.virtualParent].path)) << "\n";
        Vec3 t, s;
        Quat r;
        decompose(n.worldMatrix, t, r, s);
        if (r.w < 0.0)
            r = -r;
        out << "    t: " << list({t.x, t.y, t.z}) << "\n";
        out << "    r: " << list({r.x, r.y, r.z, r.w}) << "\n";
        if (glm::length(s - Vec3(1.0)) > 1e-9)
            out << "    s: " << list({s.x, s.y, s.z}) << "\n";
        if (n.guide != model::kNoId)
            out << "    guide: " << n.guide << "\n";
        if (n.hidden)
            out << "    hidden: true\n";
        for (std::size_t i = 0; i < n.attributes.size(); ++i) {
            const auto& a = n.attributes[i];
            out << (i == 0 ? "    attributes:\n" : "") << "      - {name: " << quoteIfNeeded(a.name) << ", value: " << fixed(a.value)
                << ", min: " << fixed(a.min) << ", max: " << fixed(a.max);
            for (std::size_t l = 0; l < a.labels.size(); ++l)
                out << (l == 0 ? ", labels: [" : ", ") << quoteIfNeeded(a.labels[l]) << (l + 1 == a.labels.size() ? "]" : "");
            out << "}\n";
        }
        model::ChannelSettings shown = n.channels; // what builders declare animatable shows as cleanup's locks
        shown.animatable = model::ChannelSettings::controllerDefaults().animatable;
        if (n.kind == model::RigNodeKind::Controller && shown != model::ChannelSettings::controllerDefaults())
            out << "    channels: " << channelsText(n.channels) << "\n";
        for (std::size_t i = 0; i < n.defaultValues.size(); ++i)
            out << (i == 0 ? "    defaults: {" : ", ") << quoteIfNeeded(n.defaultValues[i].first) << ": "
                << fixed(n.defaultValues[i].second) << (i + 1 == n.defaultValues.size() ? "}\n" : "");
        if (n.scaleCompensate)
            out << "    scale_compensate: true\n";
        if (n.twin != model::kNoNode)
            out << "    twin: " << quoteIfNeeded(rig.nodes[n.twin].path) << "\n";
        if (!n.shape.empty()) {
            out << "    shape: " << quoteIfNeeded(n.shape) << "\n";
            out << "    curves:\n";
            for (const auto& c : n.curves) {
                Vec3 lo(1e300), hi(-1e300);
                for (const Vec3& p : c.points) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
                out << "      - {points: " << c.points.size() << ", color: \"" << colorText(c.color)
                    << "\", min: " << list({lo.x, lo.y, lo.z}) << ", max: " << list({hi.x, hi.y, hi.z}) << "}\n";
            }
        }
    }
    auto ids = [&](const std::vector<model::RigNodeIndex>& nodes) {
        std::string text = "[";
        for (std::size_t i = 0; i < nodes.size(); ++i)
            text += (i ? ", " : "") + quoteIfNeeded(rig.nodes[nodes[i]].path);
        return text + "]";
    };
    out << "constraints:" << (rig.constraints.empty() ? " []\n" : "\n");
    for (const auto& c : rig.constraints) {
        out << "  - id: " << quoteIfNeeded(c.path) << "\n";
        out << "    kind: " << model::constraintKindName(c.kind()) << "\n";
        out << "    driven: " << ids(c.driven) << "\n";
        out << "    targets: " << ids(c.targets) << "\n";
        std::visit(SettingsWriter(out, rig), c.settings);
    }
    out << "sets:" << (rig.sets.empty() ? " {}\n" : "\n");
    for (const auto& [name, members] : rig.sets)
        out << "  " << quoteIfNeeded(name) << ": " << ids(members) << "\n";
    out << "groups:" << (rig.groups.empty() ? " []\n" : "\n");
    for (const auto& g : rig.groups) {
        out << "  - {name: " << quoteIfNeeded(g.name);
        if (g.parent != model::ControllerGroup::kNoGroup)
            out << ", parent: " << quoteIfNeeded(rig.groups[g.parent].name);
        out << ", controllers: " << ids(g.controllers) << "}\n";
    }
    out << "diagnostics:" << (rig.diagnostics.empty() ? " []\n" : "\n");
    for (const auto& d : rig.diagnostics)
        out << "  - " << quoteIfNeeded(d.format()) << "\n";
    return out.str();
}

} // namespace rs::io
