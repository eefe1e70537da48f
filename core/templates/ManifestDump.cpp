#include "templates/ManifestDump.h"

#include <sstream>

namespace rs::templates {

namespace {

std::string quoted(const std::string& text)
{
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '\n') { out += "\\n"; continue; }
        out += c;
    }
    return out + "\"";
}

std::string list(const std::vector<std::string>& items)
{
    std::string out = "[";
    for (std::size_t i = 0; i < items.size(); ++i)
        out += (i ? ", " : "") + items[i];
    return out + "]";
}

void describeParameter(std::ostream& out, const Parameter& p)
{
    out << "  " << p.name << ": " << typeName(typeOf(p.value)) << ' ' << formatValue(p.value);
    if (p.min) out << " min " << formatNumber(*p.min);
    if (p.max) out << " max " << formatNumber(*p.max);
    if (p.isEnum()) {
        out << " enum {";
        for (std::size_t i = 0; i < p.enumLabels.size(); ++i)
            out << (i ? ", " : "") << p.enumLabels[i].first << ": " << p.enumLabels[i].second;
        out << '}';
    }
    if (p.yaml) out << " yaml";
    if (!p.presets.empty()) out << " presets " << list(p.presets);
    if (!p.legacy.empty()) out << " legacy " << p.legacy;
    if (!p.help.empty()) out << " help " << quoted(p.help);
    out << '\n';
}

void describeRule(std::ostream& out, const HierarchyRule& rule)
{
    if (rule.root) out << " root " << (*rule.root ? "on" : "off");
    if (rule.parent) out << " parent " << list(*rule.parent);
    if (rule.hook) out << " hook " << list(*rule.hook);
    if (rule.chain) out << " chain " << (*rule.chain ? "on" : "off");
}

} // namespace

std::string describeManifest(const TemplateManifest& m)
{
    std::ostringstream out;
    out << "id: " << m.id << '\n';
    out << "name: " << m.name << '\n';
    if (!m.desc.empty()) out << "desc: " << quoted(m.desc) << '\n';
    if (!m.help.empty()) out << "help: " << quoted(m.help) << '\n';
    if (!m.base.empty()) out << "base: " << m.base << '\n';
    out << "names:\n";
    for (const auto& [token, name] : m.names)
        out << "  " << token << ": " << name << '\n';
    out << "structure:\n";
    for (const auto& [tag, address] : m.structure)
        out << "  " << tag << ": " << (address.empty() ? "(explicit tag)" : address) << '\n';
    out << "guides:\n";
    for (const Parameter& p : m.guides)
        describeParameter(out, p);
    out << "opts:\n";
    for (const Parameter& p : m.opts)
        describeParameter(out, p);
    out << "shapes:\n";
    for (const ShapeSpec& s : m.shapes) {
        out << "  " << s.key << ':';
        if (!s.shape.empty()) out << " shape " << s.shape;
        if (!s.color.empty()) out << " color " << s.color;
        out << " size " << formatNumber(s.size);
        if (!s.parent.empty()) out << " parent " << s.parent;
        if (!s.point.empty()) out << " point " << list(s.point);
        if (!s.aim.empty()) out << " aim " << s.aim;
        if (!s.up.empty()) out << " up " << s.up;
        out << " aim_axis " << s.aimAxis;
        if (!s.upAxis.empty()) out << " up_axis " << s.upAxis;
        for (const auto& [option, values] : s.doAim)
            out << " do_aim " << option << '=' << list(values);
        if (!s.clone.empty()) out << " clone " << s.clone;
        if (!s.reference.empty()) out << " reference " << s.reference;
        if (!s.axis.empty()) out << " axis " << s.axis;
        for (const auto& [option, values] : s.doAxis)
            out << " do_axis " << option << '=' << list(values);
        out << '\n';
    }
    out << "hierarchy:\n";
    for (const HierarchyEntry& e : m.hierarchy) {
        out << "  " << e.id << ": domain " << e.domain();
        describeRule(out, e.base);
        out << '\n';
        for (const auto& [expression, rule] : e.conditional) {
            out << "    if " << expression << ':';
            describeRule(out, rule);
            out << '\n';
        }
    }
    out << "ui:\n";
    out << "  icon: " << (m.icon.empty() ? "(none)" : m.icon) << '\n';
    for (const UiHook& h : m.hooks)
        out << "  hook " << h.label << ": " << h.structure << '\n';
    return out.str();
}

} // namespace rs::templates
