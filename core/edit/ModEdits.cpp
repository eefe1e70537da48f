#include "edit/ModEdits.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace rs::edit {

namespace {

// Mod `index` replaced: `from` nullopt inserts, `to` nullopt removes.
class SetMod final : public Command {
public:
    SetMod(std::size_t index, std::optional<model::Mod> from, std::optional<model::Mod> to, std::string what)
        : m_index(index), m_from(std::move(from)), m_to(std::move(to)), m_what(std::move(what))
    {
        m_change = Change::of(ChangeKind::Mods);
        for (const auto* mod : {&m_from, &m_to})
            if (*mod && (*mod)->owner.id != kNoId &&
                std::find(m_change.instances.begin(), m_change.instances.end(), (*mod)->owner.id) == m_change.instances.end())
                m_change.instances.push_back((*mod)->owner.id);
    }
    std::string text() const override { return m_what; }
    void redo(model::GuideDocument& d) override { apply(d, m_from, m_to); }
    void undo(model::GuideDocument& d) override { apply(d, m_to, m_from); }
    Change change() const override { return m_change; }

private:
    void apply(model::GuideDocument& d, const std::optional<model::Mod>& before, const std::optional<model::Mod>& after) const
    {
        if (!before) d.mods.insert(d.mods.begin() + std::ptrdiff_t(m_index), *after);
        else if (!after) d.mods.erase(d.mods.begin() + std::ptrdiff_t(m_index));
        else d.mods[m_index] = *after;
    }
    std::size_t m_index;
    std::optional<model::Mod> m_from, m_to;
    std::string m_what;
    Change m_change;
};

std::string refProblem(const model::ModRef& ref, bool channel)
{
    if (ref.tag.empty()) return "a mod's node needs a tag";
    if (channel && ref.channel.empty()) return "'" + ref.tag + "' needs a channel";
    if (!channel && !ref.channel.empty()) return "'" + ref.tag + "' takes a node, not a channel";
    return {};
}

// The first problem of several (each empty when there is none).
std::string firstOf(std::initializer_list<std::string> problems)
{
    for (const std::string& p : problems)
        if (!p.empty()) return p;
    return {};
}

std::string problemOf(const model::SpaceMod& m)
{
    return firstOf({refProblem(m.node, false), refProblem(m.target, false), m.attribute.empty() ? "a space switch needs an attribute name" : ""});
}
std::string problemOf(const model::ParentMod& m) { return firstOf({refProblem(m.node, false), refProblem(m.parent, false)}); }
std::string problemOf(const model::VdagMod& m) { return firstOf({refProblem(m.node, false), refProblem(m.parent, false)}); }
std::string problemOf(const model::HideMod& m)
{
    std::string out = m.nodes.empty() ? "a hide mod needs a node" : "";
    for (const model::ModRef& r : m.nodes) out = firstOf({out, refProblem(r, false)});
    return out;
}
std::string problemOf(const model::ConstraintMod& m)
{
    std::string out = refProblem(m.node, false);
    if (m.targets.empty()) out = firstOf({out, "a constraint needs a target"});
    for (const model::ModRef& r : m.targets) out = firstOf({out, refProblem(r, false)});
    if (!m.weights.empty() && m.weights.size() != m.targets.size()) out = firstOf({out, "a constraint needs one weight per target"});
    for (double w : m.weights) if (!std::isfinite(w)) out = firstOf({out, "a weight must be a finite number"});
    const auto k = m.kind;
    if (k != model::ConstraintKind::Parent && k != model::ConstraintKind::Point && k != model::ConstraintKind::Orient &&
        k != model::ConstraintKind::Scale && k != model::ConstraintKind::Aim)
        out = firstOf({out, "a constraint mod is parent, point, orient, scale or aim"});
    if (k == model::ConstraintKind::Aim && (m.aim == m.up || m.targets.size() > 2)) out = firstOf({out, "an aim needs two different axes and one or two targets"});
    return out;
}
std::string problemOf(const model::PlugMod& m)
{
    std::string out = firstOf({refProblem(m.channel, true), m.from ? refProblem(*m.from, true) : ""});
    for (const auto* v : {&m.value, &m.min, &m.max}) if (*v && !std::isfinite(**v)) out = firstOf({out, "a plug's values must be finite"});
    if (m.min && m.max && *m.min > *m.max) out = firstOf({out, "a plug's min is above its max"});
    if (!std::isfinite(m.factor)) out = firstOf({out, "a plug's factor must be finite"});
    if ((m.type == model::PlugType::Enum) != !m.labels.empty()) out = firstOf({out, "an enum plug, and only one, has labels"});
    return out;
}
std::string problemOf(const model::DriveMod& m)
{
    std::string out = firstOf({refProblem(m.driver, true), refProblem(m.driven, true)});
    if (m.keys.empty()) out = firstOf({out, "a drive needs at least one key"});
    for (std::size_t k = 0; k < m.keys.size(); ++k) {
        if (!std::isfinite(m.keys[k].in) || !std::isfinite(m.keys[k].out)) { out = firstOf({out, "a drive's keys must be finite"}); break; }
        if (k > 0 && !(m.keys[k].in > m.keys[k - 1].in)) { out = firstOf({out, "a drive's keys must be sorted by driver value, each once"}); break; }
    }
    return out;
}

} // namespace

std::string modProblem(const model::Mod& mod)
{
    return std::visit([](const auto& m) { return problemOf(m); }, mod.settings);
}

Status addMod(History& history, model::Mod mod, std::optional<std::size_t> index, const std::string& what)
{
    if (const std::string problem = modProblem(mod); !problem.empty())
        return Status::refused(problem);
    const std::size_t at = std::min(index.value_or(history.document().mods.size()), history.document().mods.size());
    const std::string text = what.empty() ? std::string("Add ") + model::modKindName(mod.kind()) + " mod" : what;
    history.push(std::make_unique<SetMod>(at, std::nullopt, std::move(mod), text));
    return {};
}

Status setMod(History& history, std::size_t index, model::Mod mod, const std::string& what)
{
    const model::Mods& mods = history.document().mods;
    if (index >= mods.size())
        return Status::refused("there is no mod " + std::to_string(index + 1));
    if (const std::string problem = modProblem(mod); !problem.empty())
        return Status::refused(problem);
    if (mods[index] == mod)
        return {};
    const std::string text = what.empty() ? std::string("Edit ") + model::modKindName(mod.kind()) + " mod" : what;
    history.push(std::make_unique<SetMod>(index, mods[index], std::move(mod), text));
    return {};
}

Status removeMod(History& history, std::size_t index, const std::string& what)
{
    const model::Mods& mods = history.document().mods;
    if (index >= mods.size())
        return Status::refused("there is no mod " + std::to_string(index + 1));
    const std::string text = what.empty() ? std::string("Remove ") + model::modKindName(mods[index].kind()) + " mod" : what;
    history.push(std::make_unique<SetMod>(index, mods[index], std::nullopt, text));
    return {};
}

} // namespace rs::edit
