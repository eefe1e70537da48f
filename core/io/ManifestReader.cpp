#include "io/ManifestReader.h"

#include "io/ManifestValidator.h"
#include "io/YamlSupport.h"
#include "templates/Condition.h"
#include "templates/Structure.h"
#include "templates/TemplateRegistry.h"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <set>

namespace rs::io {

using namespace rs::templates;

namespace {

Parameter makeOption(std::string name, Value value, std::string help,
                     std::vector<std::pair<long long, std::string>> labels = {}, bool yaml = false)
{
    Parameter p;
    p.name = std::move(name);
    p.value = std::move(value);
    p.help = std::move(help);
    p.enumLabels = std::move(labels);
    p.yaml = yaml;
    return p;
}

std::string flowText(const YAML::Node& node)
{
    YAML::Emitter out;
    out.SetSeqFormat(YAML::Flow);
    out.SetMapFormat(YAML::Flow);
    out << node;
    return out.c_str();
}

std::optional<Parameter> readParameter(YamlReader& r, const std::string& section, const std::string& name,
                                       const YAML::Node& node, const Parameter* inherited)
{
    const std::string what = section + "." + name;
    Parameter p = inherited ? *inherited : Parameter{};
    p.name = name;
    p.where = io::locationOf(node, r.file());
    if (node.IsNull()) {
        if (!inherited)
            r.error(node, what + " has no value");
        return inherited ? std::optional<Parameter>(p) : std::nullopt;
    }
    if (!node.IsMap()) { // bare scalar: `joint: on`
        auto v = io::readValue(r, node, what);
        if (!v) return std::nullopt;
        p.value = *v;
        return p;
    }
    bool ok = true;
    std::optional<YAML::Node> valueNode;
    for (const auto& kv : node) {
        const std::string key = kv.first.Scalar();
        const YAML::Node& v = kv.second;
        if (key == "value") valueNode = v;
        else if (key == "min") { if (auto d = r.number(v, what + ".min")) p.min = *d; else ok = false; }
        else if (key == "max") { if (auto d = r.number(v, what + ".max")) p.max = *d; else ok = false; }
        else if (key == "help") { if (auto s = r.string(v, what + ".help")) p.help = *s; else ok = false; }
        else if (key == "legacy") { if (auto s = r.string(v, what + ".legacy")) p.legacy = *s; else ok = false; }
        else if (key == "yaml") { if (auto b = r.boolean(v, what + ".yaml")) p.yaml = *b; else ok = false; }
        else if (key == "presets") {
            p.presets.clear();
            if (v.IsSequence())
                for (const auto& item : v) p.presets.push_back(item.IsScalar() ? item.Scalar() : flowText(item));
            else if (v.IsMap())
                for (const auto& item : v) p.presets.push_back(item.first.Scalar());
            else { r.error(v, what + ".presets must be a list or a map"); ok = false; }
        } else if (key == "enum") {
            p.enumLabels.clear();
            if (v.IsSequence()) {
                long long i = 0;
                for (const auto& item : v) {
                    if (auto s = r.string(item, what + ".enum item")) p.enumLabels.emplace_back(i++, *s);
                    else ok = false;
                }
            } else if (v.IsMap()) {
                for (const auto& item : v) {
                    auto index = r.integer(item.first, what + ".enum index");
                    auto label = r.string(item.second, what + ".enum label");
                    if (index && label) p.enumLabels.emplace_back(*index, *label);
                    else ok = false;
                }
            } else { r.error(v, what + ".enum must be a list or an index: label map"); ok = false; }
        } else r.warning(kv.first, "unknown key '" + key + "' in " + what);
    }
    if (valueNode) {
        if (p.yaml && !valueNode->IsScalar())
            p.value = flowText(*valueNode);
        else if (auto v = io::readValue(r, *valueNode, what + ".value"))
            p.value = *v;
        else ok = false;
    } else if (!inherited) {
        r.error(node, what + " has no 'value'");
        ok = false;
    }
    if (ok && p.isEnum()) { // enum values are stored as labels
        if (auto* index = std::get_if<long long>(&p.value)) {
            auto it = std::find_if(p.enumLabels.begin(), p.enumLabels.end(), [&](auto& e) { return e.first == *index; });
            if (it == p.enumLabels.end()) { r.error(valueNode ? *valueNode : node, what + ".value " + std::to_string(*index) + " is not an enum index"); ok = false; }
            else p.value = it->second;
        } else {
            const std::string label = formatValue(p.value);
            auto it = std::find_if(p.enumLabels.begin(), p.enumLabels.end(), [&](auto& e) { return e.second == label; });
            if (it == p.enumLabels.end()) { r.error(valueNode ? *valueNode : node, what + ".value '" + label + "' is not one of the enum labels"); ok = false; }
            else p.value = label;
        }
    }
    if (ok && (p.min || p.max)) {
        auto clampNumber = [&](double d) {
            double c = d;
            if (p.min && c < *p.min) c = *p.min;
            if (p.max && c > *p.max) c = *p.max;
            if (c != d) r.warning(valueNode ? *valueNode : node, what + ".value " + formatNumber(d) + " is out of range, clamped to " + formatNumber(c));
            return c;
        };
        if (auto* i = std::get_if<long long>(&p.value)) {
            const double c = clampNumber(double(*i)); // saturated: a bound may not fit a long long
            *i = c >= 9.2e18 ? std::numeric_limits<long long>::max() : c <= -9.2e18 ? std::numeric_limits<long long>::min() : static_cast<long long>(c);
        }
        else if (auto* d = std::get_if<double>(&p.value)) *d = clampNumber(*d);
        else { r.error(node, what + " has min/max but its value is not a number"); ok = false; }
    }
    return ok ? std::optional<Parameter>(p) : std::nullopt;
}

bool readParameters(YamlReader& r, const YAML::Node& node, const std::string& section,
                    std::vector<Parameter>& out, const std::vector<Parameter>* layer)
{
    if (!r.expectMap(node, section))
        return false;
    bool ok = true;
    for (const auto& kv : node) {
        const std::string name = kv.first.Scalar();
        const Parameter* inherited = nullptr;
        if (layer)
            for (const Parameter& c : *layer)
                if (c.name == name) inherited = &c;
        auto p = readParameter(r, section, name, kv.second, inherited);
        if (!p) { ok = false; continue; }
        auto existing = std::find_if(out.begin(), out.end(), [&](const Parameter& q) { return q.name == name; });
        if (existing != out.end()) *existing = *p;
        else out.push_back(*p);
    }
    return ok;
}

std::vector<std::string> stringList(YamlReader& r, const YAML::Node& node, const std::string& what, bool& ok)
{
    std::vector<std::string> items;
    if (node.IsSequence()) {
        for (const auto& item : node)
            if (auto s = r.string(item, what)) items.push_back(*s); else ok = false;
    } else if (auto s = r.string(node, what)) items.push_back(*s);
    else ok = false;
    return items;
}

// A lower-case identifier: an option's name (`aim_axis`).
bool isOptionName(const std::string& text)
{
    return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; });
}

bool readShapes(YamlReader& r, const YAML::Node& node, std::vector<ShapeSpec>& out)
{
    if (!r.expectMap(node, "shapes"))
        return false;
    bool ok = true;
    for (const auto& kv : node) {
        ShapeSpec s;
        s.key = kv.first.Scalar();
        s.where = io::locationOf(kv.first, r.file());
        const std::string what = "shapes." + s.key;
        if (!r.expectMap(kv.second, what)) { ok = false; continue; }
        for (const auto& p : kv.second) {
            const std::string key = p.first.Scalar();
            const YAML::Node& v = p.second;
            auto text = [&](std::string& field) { if (auto t = r.string(v, what + "." + key)) field = *t; else ok = false; };
            if (key == "shape") text(s.shape);
            else if (key == "color") text(s.color);
            else if (key == "size") { if (auto d = r.number(v, what + ".size")) s.size = *d; else ok = false; }
            else if (key == "parent") text(s.parent);
            else if (key == "point") s.point = stringList(r, v, what + ".point", ok);
            else if (key == "aim") text(s.aim);
            else if (key == "up") text(s.up);
            else if (key == "axis") { // an axis, or an option naming one (checked by the validator)
                if (auto t = r.string(v, what + ".axis")) {
                    if (parseAxis(*t) || isOptionName(*t)) s.axis = *t;
                    else { r.error(v, what + ".axis must be an axis (x, y, z, -x, -y, -z) or an option's name, not '" + *t + "'"); ok = false; }
                } else ok = false;
            }
            else if (key == "aim_axis" || key == "up_axis") {
                std::string& field = key == "aim_axis" ? s.aimAxis : s.upAxis;
                if (auto t = r.string(v, what + "." + key)) {
                    if (parseAxis(*t)) field = *t;
                    else { r.error(v, what + "." + key + " must be an axis (x, y, z, -x, -y, -z), not '" + *t + "'"); ok = false; }
                } else ok = false;
            }
            else if (key == "clone") text(s.clone);
            else if (key == "reference") text(s.reference);
            else if (key == "do_aim" || key == "do_axis") {
                if (!r.expectMap(v, what + "." + key)) { ok = false; continue; }
                auto& conditions = key == "do_aim" ? s.doAim : s.doAxis;
                for (const auto& c : v)
                    conditions.emplace_back(c.first.Scalar(), stringList(r, c.second, what + "." + key + "." + c.first.Scalar(), ok));
            }
            else r.warning(p.first, "unknown key '" + key + "' in " + what);
        }
        if (s.shape.empty() && s.clone.empty()) { r.error(kv.first, what + " has no 'shape'"); ok = false; continue; }
        if (s.size <= 0.0) { r.error(kv.second["size"], what + ".size must be positive"); ok = false; continue; }
        out.push_back(std::move(s));
    }
    return ok;
}

bool readRule(YamlReader& r, const YAML::Node& node, const std::string& what, HierarchyRule& rule,
              std::vector<std::pair<std::string, HierarchyRule>>* conditional)
{
    bool ok = true;
    for (const auto& kv : node) {
        const std::string key = kv.first.Scalar();
        const YAML::Node& v = kv.second;
        // A YAML null (`hook:` with nothing after it, as in Mikan's digit.legacy)
        // means unset: no hook / no parent (which an override uses to clear the
        // base rule's), and for root and chain the value is left as it was.
        if (v.IsNull()) {
            if (key == "parent") rule.parent = std::vector<std::string>{};
            else if (key == "hook") rule.hook = std::vector<std::string>{};
            else if (key != "root" && key != "chain") r.warning(kv.first, "unknown key '" + key + "' in " + what);
            continue;
        }
        if (key == "root") { if (auto b = r.boolean(v, what + ".root")) rule.root = *b; else ok = false; }
        else if (key == "chain") { if (auto b = r.boolean(v, what + ".chain")) rule.chain = *b; else ok = false; }
        else if (key == "parent") rule.parent = stringList(r, v, what + ".parent", ok);
        else if (key == "hook") rule.hook = stringList(r, v, what + ".hook", ok);
        else if (key == "opts" && conditional) {
            if (!r.expectMap(v, what + ".opts")) { ok = false; continue; }
            for (const auto& c : v) {
                HierarchyRule overrides;
                const std::string cwhat = what + ".opts." + c.first.Scalar();
                if (!r.expectMap(c.second, cwhat) || !readRule(r, c.second, cwhat, overrides, nullptr)) { ok = false; continue; }
                conditional->emplace_back(c.first.Scalar(), overrides);
            }
        } else r.warning(kv.first, "unknown key '" + key + "' in " + what);
    }
    return ok;
}

bool readHierarchy(YamlReader& r, const YAML::Node& node, std::vector<HierarchyEntry>& out)
{
    if (!r.expectMap(node, "hierarchy"))
        return false;
    bool ok = true;
    for (const auto& kv : node) {
        HierarchyEntry e;
        e.id = kv.first.Scalar();
        e.where = io::locationOf(kv.first, r.file());
        const std::string what = "hierarchy." + e.id;
        if (kv.second.IsNull()) { out.push_back(e); continue; }
        if (!r.expectMap(kv.second, what) || !readRule(r, kv.second, what, e.base, &e.conditional)) { ok = false; continue; }
        out.push_back(std::move(e));
    }
    return ok;
}

bool readUi(YamlReader& r, const YAML::Node& node, TemplateManifest& m)
{
    if (!r.expectMap(node, "ui"))
        return false;
    bool ok = true;
    for (const auto& kv : node) {
        const std::string key = kv.first.Scalar();
        if (key == "icon") {
            if (auto s = r.string(kv.second, "ui.icon"); s && isIconName(*s)) { m.icon = *s; m.iconWhere = io::locationOf(kv.second, r.file()); }
            else if (s) { r.error(kv.second, "ui.icon must be a file name in the icons folder (letters, digits, _ - .), not a path"); ok = false; }
            else ok = false;
        }
        else if (key == "hooks") {
            if (!r.expectMap(kv.second, "ui.hooks")) { ok = false; continue; }
            for (const auto& h : kv.second)
                if (auto s = r.string(h.second, "ui.hooks." + h.first.Scalar())) m.hooks.push_back({h.first.Scalar(), *s});
                else ok = false;
        } else r.warning(kv.first, "unknown key '" + key + "' in ui");
    }
    return ok;
}

bool readStringMap(YamlReader& r, const YAML::Node& node, const std::string& section,
                   std::vector<std::pair<std::string, std::string>>& out, bool allowEmpty)
{
    if (!r.expectMap(node, section))
        return false;
    bool ok = true;
    for (const auto& kv : node) {
        if (allowEmpty && kv.second.IsNull()) { out.emplace_back(kv.first.Scalar(), ""); continue; }
        if (auto s = r.string(kv.second, section + "." + kv.first.Scalar())) out.emplace_back(kv.first.Scalar(), *s);
        else ok = false;
    }
    return ok;
}

} // namespace

const std::vector<Parameter>& commonOptions()
{
    static const std::vector<Parameter> options = {
        makeOption("branches", std::string("[]"), "Mirrored copies of this template, e.g. [L, R].", {}, true),
        makeOption("sym", std::string("parent"), "Mirror plane of the branches.",
                   {{0, "parent"}, {1, "x"}, {2, "y"}, {3, "z"}}),
        makeOption("group", std::string(""), "Controller group this template's controllers join."),
        makeOption("parent", std::string("parent"), "How the group relates to the parent template's group.",
                   {{0, "parent"}, {1, "merge up"}, {2, "merge down"}}),
        makeOption("do_ctrl", true, "Build controllers."),
        makeOption("do_skin", true, "Build skin joints."),
        makeOption("virtual_parent", std::string(""), "Attach the virtual hierarchy to the closest node of this template instead."),
        makeOption("isolate_skin", false, "Build a separate clean skin skeleton."),
    };
    return options;
}

Result<TemplateManifest> readManifestText(const std::string& text, const std::string& displayName,
                                          const std::string& category, const std::string& module)
{
    auto yaml = io::loadYamlText(text, displayName);
    if (!yaml)
        return Result<TemplateManifest>::failure(yaml.takeDiagnostics());
    Diagnostics diagnostics;
    YamlReader r(displayName, diagnostics);
    TemplateManifest m;
    m.category = category;
    m.module = module;
    m.id = category + "." + module;
    m.file = displayName;
    m.directory = std::filesystem::path(displayName).parent_path().string();
    m.name = module;
    m.opts = commonOptions();

    const YAML::Node root = *yaml;
    if (root.IsNull()) {
        r.error(root, "the manifest is empty (a template.yml needs at least a name)");
        return Result<TemplateManifest>::failure(diagnostics);
    }
    if (!root.IsMap()) {
        r.error(root, "a template manifest must be a map of keys (name, desc, structure, ...)");
        return Result<TemplateManifest>::failure(diagnostics);
    }
    std::vector<Parameter> ownOpts;
    bool haveOpts = false;
    for (const auto& kv : root) {
        const std::string key = kv.first.Scalar();
        const YAML::Node& v = kv.second;
        auto text = [&](std::string& field) { if (auto s = r.string(v, key)) field = *s; };
        if (key == "name") text(m.name);
        else if (key == "desc") text(m.desc);
        else if (key == "help") text(m.help);
        else if (key == "base") text(m.base);
        else if (key == "names") readStringMap(r, v, "names", m.names, false);
        else if (key == "structure") readStringMap(r, v, "structure", m.structure, true);
        else if (key == "guides") readParameters(r, v, "guides", m.guides, nullptr);
        else if (key == "opts") { haveOpts = true; readParameters(r, v, "opts", ownOpts, &m.opts); }
        else if (key == "shapes") readShapes(r, v, m.shapes);
        else if (key == "hierarchy") readHierarchy(r, v, m.hierarchy);
        else if (key == "ui") readUi(r, v, m);
        else r.warning(kv.first, "unknown key '" + key + "' (ignored)");
    }
    if (haveOpts) { // own opts first, then the common ones they did not override
        std::vector<Parameter> merged = ownOpts;
        for (const Parameter& c : m.opts)
            if (std::none_of(ownOpts.begin(), ownOpts.end(), [&](const Parameter& o) { return o.name == c.name; }))
                merged.push_back(c);
        m.opts = std::move(merged);
    }
    if (!hasErrors(diagnostics))
        validateManifest(r, m, root);
    if (hasErrors(diagnostics))
        return Result<TemplateManifest>::failure(diagnostics);
    return Result<TemplateManifest>(std::move(m), std::move(diagnostics));
}

Result<TemplateManifest> readManifest(const std::string& file, const std::string& category, const std::string& module)
{
    auto text = io::readTextFile(file);
    if (!text)
        return Result<TemplateManifest>::failure(text.takeDiagnostics());
    return readManifestText(*text, file, category, module);
}

} // namespace rs::io
