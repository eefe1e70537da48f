#include "io/ManifestValidator.h"

#include "templates/Condition.h"
#include "templates/Structure.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <set>

namespace rs::io {

using namespace rs::templates;

namespace {

class Validator {
public:
    Validator(YamlReader& r, const TemplateManifest& m) : m_r(r), m_m(m) {}

    void run(const YAML::Node& root)
    {
        if (const YAML::Node structure = root["structure"]; structure && structure.IsMap())
            for (const auto& kv : structure)
                if (!kv.second.IsNull() && kv.second.IsScalar())
                    address(kv.second, "structure." + kv.first.Scalar(), kv.first.Scalar());
        checkCycles(root["structure"]);
        axisPair(root);
        if (const YAML::Node shapes = root["shapes"]; shapes && shapes.IsMap())
            for (const auto& kv : shapes) {
                if (!kv.second.IsMap()) continue;
                const std::string what = "shapes." + kv.first.Scalar();
                for (const char* key : {"parent", "point", "aim", "up"}) {
                    const YAML::Node v = kv.second[key];
                    if (!v) continue;
                    for (const YAML::Node& item : items(v))
                        if (item.IsScalar() && !((std::string(key) == "aim" || std::string(key) == "up") && parseAxis(item.Scalar())))
                            address(item, what + "." + key, {});
                }
                for (const char* key : {"do_aim", "do_axis"})
                    if (const YAML::Node conditions = kv.second[key]; conditions && conditions.IsMap())
                        for (const auto& c : conditions)
                            if (!m_m.findOpt(c.first.Scalar()))
                                m_r.warning(c.first, what + "." + key + ": no option '" + c.first.Scalar() + "' in this template");
                if (const YAML::Node axis = kv.second["axis"]; axis && axis.IsScalar() && !parseAxis(axis.Scalar()))
                    axisOption(axis, what + ".axis");
            }
        if (const YAML::Node hierarchy = root["hierarchy"]; hierarchy && hierarchy.IsMap())
            for (const auto& kv : hierarchy) {
                if (!kv.second.IsMap()) continue;
                hierarchyRule(kv.second, "hierarchy." + kv.first.Scalar());
                if (const YAML::Node opts = kv.second["opts"]; opts && opts.IsMap())
                    for (const auto& c : opts) {
                        condition(c.first, "hierarchy." + kv.first.Scalar() + ".opts");
                        if (c.second.IsMap()) hierarchyRule(c.second, "hierarchy." + kv.first.Scalar() + ".opts." + c.first.Scalar());
                    }
            }
        if (const YAML::Node hooks = root["ui"] ? root["ui"]["hooks"] : YAML::Node(); hooks && hooks.IsMap())
            for (const auto& kv : hooks)
                if (kv.second.IsScalar())
                    address(kv.second, "ui.hooks." + kv.first.Scalar(), {});
    }

private:
    // A shape `axis` naming an option: every value it can take must be an axis.
    void axisOption(const YAML::Node& node, const std::string& what)
    {
        const Parameter* opt = m_m.findOpt(node.Scalar());
        if (!opt) {
            m_r.error(node, what + ": no option '" + node.Scalar() + "' in this template");
            return;
        }
        std::vector<std::string> values{formatValue(opt->value)};
        for (const auto& label : opt->enumLabels)
            values.push_back(label.second);
        for (const std::string& value : values)
            if (!parseAxis(value)) {
                m_r.error(node, what + ": option '" + opt->name + "' can be '" + value + "', which is no axis (x, y, z, -x, -y, -z)");
                return;
            }
    }

    // An `up_axis` option whose default lies along the `aim_axis` option's default.
    void axisPair(const YAML::Node& root)
    {
        const Parameter* aim = m_m.findOpt("aim_axis");
        const Parameter* up = m_m.findOpt("up_axis");
        if (!aim || !up)
            return;
        const auto a = parseAxis(formatValue(aim->value));
        const auto u = parseAxis(formatValue(up->value));
        const YAML::Node opts = root["opts"];
        const YAML::Node at = opts && opts.IsMap() && opts["up_axis"] ? opts["up_axis"] : root;
        if (a && u && std::abs(glm::dot(*a, *u)) > 0.5)
            m_r.error(at.IsMap() && at["value"] ? at["value"] : at, "opts.up_axis: the default '" + formatValue(up->value) + "' lies along aim_axis '" +
                                     formatValue(aim->value) + "' (equal or opposite)");
    }

    static std::vector<YAML::Node> items(const YAML::Node& v)
    {
        std::vector<YAML::Node> out;
        if (v.IsSequence()) for (const auto& item : v) out.push_back(item);
        else out.push_back(v);
        return out;
    }

    void hierarchyRule(const YAML::Node& rule, const std::string& what)
    {
        if (const YAML::Node hook = rule["hook"])
            for (const YAML::Node& item : items(hook))
                if (item.IsScalar()) address(item, what + ".hook", {});
    }

    void address(const YAML::Node& node, const std::string& what, const std::string& ownTag)
    {
        const std::string text = node.Scalar();
        auto terms = parseAddress(text);
        if (!terms) {
            m_r.error(node, what + ": " + firstError(terms.diagnostics()));
            return;
        }
        if (terms->empty() && ownTag.empty())
            m_r.error(node, what + ": empty address");
        for (const AddressTerm& t : *terms)
            if (t.base != "." && t.base[0] != '/' && !m_m.structureAddress(t.base))
                m_r.warning(node, what + ": '" + t.base + "' is not a structure tag of this template"
                                  " (it can only match joints tagged '" + t.base + "' in the guide)");
    }

    void condition(const YAML::Node& node, const std::string& what)
    {
        std::map<std::string, Value> defaults;
        for (const Parameter& p : m_m.opts) defaults[p.name] = p.value;
        for (const Parameter& p : m_m.guides) defaults[p.name] = p.value;
        if (const auto holds = evaluateCondition(node.Scalar(), defaults); !holds)
            m_r.error(node, what + ": condition '" + node.Scalar() + "': " + firstError(holds.diagnostics()));
    }

    // A tag whose address leads back to itself can never resolve.
    void checkCycles(const YAML::Node& structure)
    {
        if (!structure || !structure.IsMap())
            return;
        std::set<std::string> reported;
        for (const auto& kv : structure) {
            std::vector<std::string> path{kv.first.Scalar()};
            if (!reported.count(kv.first.Scalar()) && cycleFrom(kv.first.Scalar(), path)) {
                reported.insert(path.begin(), path.end());
                std::string chain;
                for (const auto& tag : path) chain += (chain.empty() ? "" : " -> ") + tag;
                m_r.error(kv.first, "structure." + kv.first.Scalar() + ": the tag refers to itself (" + chain + ")");
            }
        }
    }

    bool cycleFrom(const std::string& tag, std::vector<std::string>& path)
    {
        auto address = m_m.structureAddress(tag);
        if (!address) return false;
        auto terms = parseAddress(*address);
        if (!terms) return false;
        for (const AddressTerm& t : *terms) {
            if (t.base == "." || t.base[0] == '/' || !m_m.structureAddress(t.base)) continue;
            if (t.base == path.front()) { path.push_back(t.base); return true; }
            if (std::find(path.begin(), path.end(), t.base) != path.end()) continue; // another tag's cycle
            path.push_back(t.base);
            if (cycleFrom(t.base, path)) return true;
            path.pop_back();
        }
        return false;
    }

    YamlReader& m_r;
    const TemplateManifest& m_m;
};

} // namespace

void validateManifest(YamlReader& reader, const TemplateManifest& manifest, const YAML::Node& root)
{
    Validator(reader, manifest).run(root);
}

} // namespace rs::io
