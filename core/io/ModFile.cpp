// Reading mods: each kind's body, its keys and values checked (the rig id
// text of references is parsed in ModRefReader.cpp). Every problem is an
// error at the line and column of its key or value; a mod with an error is
// not read (the guide does not load).
#include "io/ModFile.h"
#include "io/ModRefReader.h"
#include "io/ModText.h"

#include <algorithm>

namespace rs::io {

using model::ModInstance;
using model::ModRef;

namespace {

// A mod's body by its kind; references are read by ModRefReader.
class ModReader : private ModRefReader {
public:
    ModReader(YamlReader& r, const model::GuideDocument& doc, ModInstance owner) : ModRefReader(r, doc, std::move(owner)) {}

    std::optional<model::ModSettings> body(model::ModKind kind, const YAML::Node& node)
    {
        switch (kind) {
        case model::ModKind::Space: return space(node);
        case model::ModKind::Constraint: return constraint(node);
        case model::ModKind::Parent: return nodeAndParent<model::ParentMod>(node, "parent");
        case model::ModKind::Hide: return hide(node);
        case model::ModKind::Plug: return plug(node);
        case model::ModKind::Drive: return drive(node);
        case model::ModKind::Vdag: return nodeAndParent<model::VdagMod>(node, "vdag");
        }
        return std::nullopt;
    }

private:
    // Calls `take(key, value)` for each key of the body; false from it: an unknown key (warned).
    template <class Take>
    bool keys(const YAML::Node& node, const std::string& kind, Take take)
    {
        if (!m_r.expectMap(node, "the " + kind + " mod"))
            return false;
        for (const auto& kv : node)
            if (!take(kv.first.Scalar(), kv.second))
                m_r.warning(kv.first, "unknown key '" + kv.first.Scalar() + "' in a " + kind + " mod (ignored)");
        return true;
    }

    template <class T>
    bool require(const std::optional<T>& value, const YAML::Node& node, const std::string& kind, const std::string& key)
    {
        if (!value)
            m_r.error(node, "the " + kind + " mod needs '" + key + "'");
        return value.has_value();
    }

    std::optional<model::ModSettings> space(const YAML::Node& node)
    {
        model::SpaceMod m;
        std::optional<ModRef> target, ctrl;
        bool ok = keys(node, "space", [&](const std::string& key, const YAML::Node& v) {
            if (key == "node") { ctrl = ref(v, "space 'node'", Want::Node); ok_ &= ctrl.has_value(); }
            else if (key == "target") { target = ref(v, "space 'target'", Want::Node); ok_ &= target.has_value(); }
            else if (key == "label" || key == "attribute") {
                auto s = m_r.string(v, "space '" + key + "'");
                if (s && s->empty()) { m_r.error(v, "space '" + key + "' is empty"); s.reset(); }
                if (s) (key == "label" ? m.label : m.attribute) = *s; else ok_ = false;
            } else return false;
            return true;
        });
        if (!finish(ok) || !require(ctrl, node, "space", "node") || !require(target, node, "space", "target"))
            return std::nullopt;
        m.node = *ctrl;
        m.target = *target;
        return m;
    }

    std::optional<model::ModSettings> constraint(const YAML::Node& node)
    {
        model::ConstraintMod m;
        std::optional<ModRef> driven;
        std::optional<YAML::Node> targets, weights;
        bool ok = keys(node, "constraint", [&](const std::string& key, const YAML::Node& v) {
            if (key == "kind") {
                const auto s = m_r.string(v, "constraint 'kind'");
                const std::pair<const char*, model::ConstraintKind> kinds[] = {
                    {"parent", model::ConstraintKind::Parent}, {"point", model::ConstraintKind::Point},
                    {"orient", model::ConstraintKind::Orient}, {"scale", model::ConstraintKind::Scale},
                    {"aim", model::ConstraintKind::Aim}};
                const auto it = std::find_if(std::begin(kinds), std::end(kinds), [&](auto& k) { return s && *s == k.first; });
                if (it != std::end(kinds)) m.kind = it->second;
                else { if (s) m_r.error(v, "constraint 'kind' '" + *s + "' is not one of parent, point, orient, scale, aim"); ok_ = false; }
            } else if (key == "node") { driven = ref(v, "constraint 'node'", Want::Node); ok_ &= driven.has_value(); }
            else if (key == "targets" || key == "target") targets = v;
            else if (key == "weights") weights = v;
            else if (key == "keep_offset") { if (auto b = m_r.boolean(v, "constraint 'keep_offset'")) m.keepOffset = *b; else ok_ = false; }
            else if (key == "aim" || key == "up") {
                const auto s = m_r.string(v, "constraint '" + key + "'");
                const auto axis = !s ? std::nullopt : *s == "x" ? std::optional(model::Axis::X) : *s == "y" ? std::optional(model::Axis::Y)
                                                    : *s == "z" ? std::optional(model::Axis::Z) : std::nullopt;
                if (axis) (key == "aim" ? m.aim : m.up) = *axis;
                else { if (s) m_r.error(v, "constraint '" + key + "' must be x, y or z"); ok_ = false; }
            } else return false;
            return true;
        });
        if (targets) m.targets = refs(*targets, "constraint 'targets'", Want::Node, ok_);
        if (weights) {
            if (m_r.expectSequence(*weights, "constraint 'weights'")) {
                for (const auto& w : *weights)
                    if (auto x = m_r.number(w, "a constraint weight")) m.weights.push_back(*x); else ok_ = false;
            } else ok_ = false;
        }
        if (!finish(ok) || !require(driven, node, "constraint", "node") || !require(targets, node, "constraint", "targets"))
            return std::nullopt;
        m.node = *driven;
        if (!m.weights.empty() && m.weights.size() != m.targets.size())
            return fail(*weights, "constraint 'weights' needs one weight per target (" + std::to_string(m.targets.size()) + ")");
        if (m.kind == model::ConstraintKind::Aim && m.targets.size() > 2)
            return fail(*targets, "an aim constraint takes an aim target and an optional up target");
        if (m.kind == model::ConstraintKind::Aim && m.aim == m.up)
            return fail(node, "an aim constraint's 'aim' and 'up' axes must differ");
        return m;
    }

    template <class T>
    std::optional<model::ModSettings> nodeAndParent(const YAML::Node& node, const std::string& kind)
    {
        std::optional<ModRef> child, parent;
        bool ok = keys(node, kind, [&](const std::string& key, const YAML::Node& v) {
            if (key == "node") { child = ref(v, kind + " 'node'", Want::Node); ok_ &= child.has_value(); }
            else if (key == "parent") { parent = ref(v, kind + " 'parent'", Want::Node); ok_ &= parent.has_value(); }
            else return false;
            return true;
        });
        if (!finish(ok) || !require(child, node, kind, "node") || !require(parent, node, kind, "parent"))
            return std::nullopt;
        return T{*child, *parent};
    }

    std::optional<model::ModSettings> hide(const YAML::Node& node)
    {
        model::HideMod m;
        m.nodes = refs(node, "hide", Want::Node, ok_);
        return finish(true) ? std::optional<model::ModSettings>(m) : std::nullopt;
    }

    std::optional<model::ModSettings> plug(const YAML::Node& node)
    {
        model::PlugMod m;
        std::optional<ModRef> channel;
        std::optional<YAML::Node> labels;
        bool ok = keys(node, "plug", [&](const std::string& key, const YAML::Node& v) {
            auto number = [&](std::optional<double>& out) { out = m_r.number(v, "plug '" + key + "'"); ok_ &= out.has_value(); };
            auto boolean = [&](std::optional<bool>& out) { out = m_r.boolean(v, "plug '" + key + "'"); ok_ &= out.has_value(); };
            if (key == "channel") { channel = ref(v, "plug 'channel'", Want::Channel); ok_ &= channel.has_value(); }
            else if (key == "from") { m.from = ref(v, "plug 'from'", Want::Channel); ok_ &= m.from.has_value(); }
            else if (key == "type") {
                const auto s = m_r.string(v, "plug 'type'");
                m.type = s ? model::parsePlugType(*s) : std::nullopt;
                if (!m.type) { if (s) m_r.error(v, "plug 'type' '" + *s + "' is not one of float, bool, enum"); ok_ = false; }
            } else if (key == "default") number(m.value);
            else if (key == "min") number(m.min);
            else if (key == "max") number(m.max);
            else if (key == "factor") { std::optional<double> f; number(f); if (f) m.factor = *f; }
            else if (key == "keyable") boolean(m.keyable);
            else if (key == "locked") boolean(m.locked);
            else if (key == "labels") labels = v;
            else return false;
            return true;
        });
        if (labels) {
            if (m_r.expectSequence(*labels, "plug 'labels'")) {
                for (const auto& l : *labels)
                    if (auto s = m_r.string(l, "a plug label"); s && !s->empty()) m.labels.push_back(*s);
                    else { if (s) m_r.error(l, "a plug label is empty"); ok_ = false; }
            } else ok_ = false;
        }
        if (!finish(ok) || !require(channel, node, "plug", "channel"))
            return std::nullopt;
        m.channel = *channel;
        if (m.min && m.max && *m.min > *m.max)
            return fail(node, "plug 'min' is above 'max'");
        const bool isEnum = m.type == model::PlugType::Enum;
        if (isEnum != !m.labels.empty())
            return fail(labels ? *labels : node, isEnum ? "an enum plug needs 'labels'" : "'labels' are for an enum plug (type: enum)");
        return m;
    }

    std::optional<model::ModSettings> drive(const YAML::Node& node)
    {
        model::DriveMod m;
        std::optional<ModRef> driver, driven;
        std::optional<YAML::Node> keysNode;
        bool ok = keys(node, "drive", [&](const std::string& key, const YAML::Node& v) {
            if (key == "driver") { driver = ref(v, "drive 'driver'", Want::Channel); ok_ &= driver.has_value(); }
            else if (key == "driven") { driven = ref(v, "drive 'driven'", Want::Channel); ok_ &= driven.has_value(); }
            else if (key == "keys") keysNode = v;
            else if (key == "smooth") { if (auto b = m_r.boolean(v, "drive 'smooth'")) m.smooth = *b; else ok_ = false; }
            else if (key == "pre" || key == "post") {
                const auto s = m_r.string(v, "drive '" + key + "'");
                const auto mode = !s ? std::nullopt : *s == "constant" ? std::optional(model::CurveInfinity::Constant)
                                 : *s == "linear" ? std::optional(model::CurveInfinity::Linear)
                                 : *s == "cycle" ? std::optional(model::CurveInfinity::Cycle) : std::nullopt;
                if (mode) (key == "pre" ? m.pre : m.post) = *mode;
                else { if (s) m_r.error(v, "drive '" + key + "' must be constant, linear or cycle"); ok_ = false; }
            } else return false;
            return true;
        });
        if (keysNode && m_r.expectMap(*keysNode, "drive 'keys' (driver value: driven value)")) {
            for (const auto& kv : *keysNode) {
                const auto in = m_r.number(kv.first, "a drive key's driver value");
                const auto out = m_r.number(kv.second, "a drive key's driven value");
                if (in && out) m.keys.push_back({*in, *out}); else ok_ = false;
            }
        } else if (keysNode) ok_ = false;
        if (!finish(ok) || !require(driver, node, "drive", "driver") || !require(driven, node, "drive", "driven") ||
            !require(keysNode, node, "drive", "keys"))
            return std::nullopt;
        m.driver = *driver;
        m.driven = *driven;
        std::sort(m.keys.begin(), m.keys.end(), [](auto& a, auto& b) { return a.in < b.in; });
        if (m.keys.empty())
            return fail(*keysNode, "drive 'keys' needs at least one key (driver value: driven value)");
        for (std::size_t k = 1; k < m.keys.size(); ++k)
            if (m.keys[k].in == m.keys[k - 1].in)
                return fail(*keysNode, "drive 'keys' gives driver value " + formatNumber(m.keys[k].in) + " twice");
        return m;
    }

    bool finish(bool ok)
    {
        const bool result = ok && ok_;
        ok_ = true;
        return result;
    }
    std::optional<model::ModSettings> fail(const YAML::Node& node, const std::string& message)
    {
        m_r.error(node, message);
        return std::nullopt;
    }

    bool ok_ = true; // cleared by a bad value inside a body
};

} // namespace

std::optional<model::Mod> readMod(YamlReader& r, const YAML::Node& node, const model::GuideDocument& doc,
                                  const model::ModInstance& owner, bool allowOwner)
{
    if (!r.expectMap(node, "a mod"))
        return std::nullopt;
    model::Mod mod;
    mod.where = locationOf(node, r.file());
    mod.owner = owner;
    if (const model::TemplateInstance* i = doc.instance(owner.id))
        mod.owner.name = i->name;
    std::optional<std::pair<model::ModKind, YAML::Node>> body;
    bool ok = true;
    for (const auto& kv : node) {
        const std::string key = kv.first.Scalar();
        if (key == "instance" && allowOwner) {
            const auto name = r.string(kv.second, "mod 'instance'");
            if (!name || name->empty()) { if (name) r.error(kv.second, "mod 'instance' is empty"); ok = false; continue; }
            const model::TemplateInstance* i = doc.instanceNamed(*name);
            mod.owner = {i ? i->id : kNoId, *name}; // unknown: kept, reported by a build
        } else if (const auto kind = model::parseModKind(key)) {
            if (body) { r.error(kv.first, "a mod has one kind; '" + key + "' follows '" + model::modKindName(body->first) + "' (start a new mod with '-')"); ok = false; }
            else body.emplace(*kind, kv.second);
        } else {
            r.error(kv.first, "unknown mod kind '" + key + "' (known: space, constraint, parent, hide, plug, drive, vdag)");
            ok = false;
        }
    }
    if (!body) {
        if (ok) r.error(node, "a mod needs its kind as a key (space, constraint, parent, hide, plug, drive, vdag)");
        return std::nullopt;
    }
    ModReader reader(r, doc, mod.owner);
    auto settings = reader.body(body->first, body->second);
    if (!settings || !ok)
        return std::nullopt;
    mod.settings = std::move(*settings);
    return mod;
}

void readMods(YamlReader& r, const YAML::Node& node, model::GuideDocument& doc)
{
    if (node.IsNull() || !r.expectSequence(node, "mods"))
        return;
    for (const auto& item : node)
        if (auto mod = readMod(r, item, doc, {}, true))
            doc.mods.push_back(std::move(*mod));
}

Result<model::Mod> readModText(const model::GuideDocument& doc, const model::ModInstance& owner, const std::string& text,
                               const std::string& displayName)
{
    auto yaml = loadYamlText(text, displayName);
    if (!yaml)
        return Result<model::Mod>::failure(yaml.takeDiagnostics());
    Diagnostics diagnostics;
    YamlReader r(displayName, diagnostics);
    if (yaml->IsNull()) {
        r.error(*yaml, "a mod is one key, its kind (space, constraint, parent, hide, plug, drive, vdag), with its settings");
        return Result<model::Mod>::failure(diagnostics);
    }
    auto mod = readMod(r, *yaml, doc, owner, false);
    if (!mod || hasErrors(diagnostics))
        return Result<model::Mod>::failure(diagnostics);
    mod->where = {};
    return Result<model::Mod>(std::move(*mod), std::move(diagnostics));
}

} // namespace rs::io
