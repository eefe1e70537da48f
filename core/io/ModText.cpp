// Writing mods: each kind's keys in a fixed order, block style, values that
// equal the defaults left out, so a written mod reads back equal and a diff
// shows what changed. References are written with the instances' current names.
#include "io/ModFile.h"
#include "io/ModText.h"

#include <sstream>

namespace rs::io {

namespace {

class ModWriter {
public:
    ModWriter(std::ostream& out, const model::GuideDocument& doc, const model::ModInstance& owner, std::string indent)
        : m_out(out), m_doc(doc), m_owner(owner), m_indent(std::move(indent))
    {
    }

    void operator()(const model::SpaceMod& m)
    {
        begin("space");
        field("node", ref(m.node));
        field("target", ref(m.target));
        if (!m.label.empty()) field("label", quoteIfNeeded(m.label));
        if (m.attribute != "space") field("attribute", quoteIfNeeded(m.attribute));
    }
    void operator()(const model::ConstraintMod& m)
    {
        begin("constraint");
        field("kind", model::constraintKindName(m.kind));
        field("node", ref(m.node));
        field("targets", refList(m.targets));
        if (!m.weights.empty()) {
            std::string text = "[";
            for (std::size_t i = 0; i < m.weights.size(); ++i)
                text += (i ? ", " : "") + formatNumber(m.weights[i]);
            field("weights", text + "]");
        }
        if (m.kind == model::ConstraintKind::Aim) {
            field("aim", model::axisName(m.aim));
            field("up", model::axisName(m.up));
        } else if (!m.keepOffset) {
            field("keep_offset", "off");
        }
    }
    void operator()(const model::ParentMod& m) { nodeAndParent("parent", m.node, m.parent); }
    void operator()(const model::VdagMod& m) { nodeAndParent("vdag", m.node, m.parent); }
    void operator()(const model::HideMod& m) { m_out << "hide: " << refList(m.nodes) << "\n"; }
    void operator()(const model::PlugMod& m)
    {
        begin("plug");
        field("channel", ref(m.channel));
        if (m.type) field("type", model::plugTypeName(*m.type));
        if (!m.labels.empty()) {
            std::string text = "[";
            for (std::size_t i = 0; i < m.labels.size(); ++i)
                text += (i ? ", " : "") + quoteIfNeeded(m.labels[i]);
            field("labels", text + "]");
        }
        if (m.value) field("default", formatNumber(*m.value));
        if (m.min) field("min", formatNumber(*m.min));
        if (m.max) field("max", formatNumber(*m.max));
        if (m.keyable) field("keyable", *m.keyable ? "on" : "off");
        if (m.locked) field("locked", *m.locked ? "on" : "off");
        if (m.from) field("from", ref(*m.from));
        if (m.factor != 1.0) field("factor", formatNumber(m.factor));
    }
    void operator()(const model::DriveMod& m)
    {
        begin("drive");
        field("driver", ref(m.driver));
        field("driven", ref(m.driven));
        std::string keys = "{";
        for (std::size_t i = 0; i < m.keys.size(); ++i)
            keys += (i ? ", " : "") + formatNumber(m.keys[i].in) + ": " + formatNumber(m.keys[i].out);
        field("keys", keys + "}");
        if (m.smooth) field("smooth", "on");
        if (m.pre != model::CurveInfinity::Constant) field("pre", model::curveInfinityName(m.pre));
        if (m.post != model::CurveInfinity::Constant) field("post", model::curveInfinityName(m.post));
    }

private:
    void begin(const char* kind) { m_out << kind << ":\n"; }
    void field(const char* key, const std::string& text) { m_out << m_indent << "  " << key << ": " << text << "\n"; }
    void nodeAndParent(const char* kind, const model::ModRef& node, const model::ModRef& parent)
    {
        begin(kind);
        field("node", ref(node));
        field("parent", ref(parent));
    }
    std::string ref(const model::ModRef& r) const { return quoteIfNeeded(formatModRef(m_doc, r, m_owner)); }
    std::string refList(const std::vector<model::ModRef>& refs) const
    {
        std::string text = "[";
        for (std::size_t i = 0; i < refs.size(); ++i)
            text += (i ? ", " : "") + ref(refs[i]);
        return text + "]";
    }

    std::ostream& m_out;
    const model::GuideDocument& m_doc;
    const model::ModInstance& m_owner;
    std::string m_indent;
};

void writeBody(std::ostream& out, const model::GuideDocument& doc, const model::Mod& mod, const std::string& indent)
{
    std::visit(ModWriter(out, doc, mod.owner, indent), mod.settings);
}

} // namespace

std::string modInstanceName(const model::GuideDocument& doc, const model::ModInstance& instance)
{
    if (const model::TemplateInstance* i = doc.instance(instance.id))
        return i->name;
    return instance.name.empty() && instance.id != kNoId ? "#" + std::to_string(instance.id) : instance.name;
}

std::string formatModRef(const model::GuideDocument& doc, const model::ModRef& ref, const model::ModInstance& owner)
{
    std::string text;
    const bool own = !owner.isNone() && ref.instance == owner && !ref.branch;
    if (!own) {
        text = modInstanceName(doc, ref.instance);
        if (ref.branch)
            text += "." + *ref.branch;
        text += "::";
    }
    text += ref.tag;
    if (!ref.channel.empty())
        text += "@" + ref.channel;
    return text;
}

std::string writeModText(const model::GuideDocument& doc, const model::Mod& mod)
{
    std::ostringstream out;
    writeBody(out, doc, mod, "");
    return out.str();
}

void writeMods(std::ostream& out, const model::GuideDocument& doc)
{
    if (doc.mods.empty())
        return;
    out << "mods:\n";
    for (const model::Mod& mod : doc.mods) {
        out << "  - ";
        if (!mod.isGlobal())
            out << "instance: " << quoteIfNeeded(modInstanceName(doc, mod.owner)) << "\n    ";
        writeBody(out, doc, mod, "    ");
    }
}

std::string modSample(model::ModKind kind, bool ofInstance)
{
    const std::string own = ofInstance ? "" : "arm.L::"; // a global mod names the instance
    switch (kind) {
    case model::ModKind::Space:
        return "space:\n  node: " + own + "ctrls.ik\n  target: \"spine::ctrls.chest\"\n  label: chest\n";
    case model::ModKind::Constraint:
        return "constraint:\n  kind: parent  # parent, point, orient, scale or aim\n  node: " + own +
               "roots.ik\n  targets: [\"spine::ctrls.chest\"]\n  weights: [1]\n  keep_offset: on\n";
    case model::ModKind::Parent:
        return "parent:\n  node: " + own + "roots.ik\n  parent: \"spine::ctrls.chest\"\n";
    case model::ModKind::Hide:
        return "hide: [" + (ofInstance ? std::string("ctrls.pv") : std::string("\"arm.L::ctrls.pv\"")) + "]\n";
    case model::ModKind::Plug:
        return "plug:\n  channel: " + own + "ctrls.ik@fist  # created when the node has no such channel\n"
               "  type: float  # float, bool or enum (with labels: [a, b])\n  default: 0\n  min: 0\n  max: 10\n  keyable: on\n";
    case model::ModKind::Drive:
        return "drive:\n  driver: " + own + "ctrls.fk.1@rz\n  driven: " + own +
               "ctrls.fk.0@ry\n  keys: {0: 0, 90: 30}  # driver value: driven value\n  smooth: off\n  pre: constant  # constant, linear or cycle\n  post: constant\n";
    case model::ModKind::Vdag:
        return "vdag:\n  node: " + own + "ctrls.ik\n  parent: \"spine::ctrls.chest\"\n";
    }
    return {};
}

} // namespace rs::io
