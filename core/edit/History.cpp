#include "edit/History.h"

#include <algorithm>

namespace rs::edit {

namespace {

// A committed transaction: its commands as one undo step.
class MacroCommand final : public Command {
public:
    MacroCommand(std::string text, std::vector<std::unique_ptr<Command>> commands)
        : m_text(std::move(text)), m_commands(std::move(commands)) {}
    std::string text() const override { return m_text; }
    void redo(model::GuideDocument& d) override
    {
        for (auto& c : m_commands)
            c->redo(d);
    }
    void undo(model::GuideDocument& d) override
    {
        for (auto it = m_commands.rbegin(); it != m_commands.rend(); ++it)
            (*it)->undo(d);
    }
    Change change() const override
    {
        Change out;
        for (const auto& c : m_commands)
            out.merge(c->change());
        return out;
    }

private:
    std::string m_text;
    std::vector<std::unique_ptr<Command>> m_commands;
};

} // namespace

bool Change::touchesGuide() const
{
    return hasAny(ChangeKind::Document | ChangeKind::Instances | ChangeKind::Joints | ChangeKind::Options |
                  ChangeKind::Shapes | ChangeKind::Names | ChangeKind::Overrides | ChangeKind::Mods | ChangeKind::Build);
}

void Change::merge(const Change& other)
{
    // Weights with an empty binding list mean every binding, and stay so.
    const bool hadWeights = has(ChangeKind::Weights);
    if (other.has(ChangeKind::Weights)) {
        if (!hadWeights)
            bindings = other.bindings;
        else if (bindings.empty() || other.bindings.empty())
            bindings.clear();
        else
            for (std::size_t b : other.bindings)
                if (std::find(bindings.begin(), bindings.end(), b) == bindings.end())
                    bindings.push_back(b);
    }
    kinds |= other.kinds;
    for (InstanceId id : other.instances)
        if (std::find(instances.begin(), instances.end(), id) == instances.end())
            instances.push_back(id);
    for (JointId id : other.joints)
        if (std::find(joints.begin(), joints.end(), id) == joints.end())
            joints.push_back(id);
    preview = preview || other.preview;
}

void History::push(std::unique_ptr<Command> command)
{
    command->redo(m_document);
    Change change = command->change();
    if (m_open) {
        m_open->commands.push_back(std::move(command));
        change.preview = true;
        notify(std::move(change));
        return;
    }
    m_commands.resize(m_index);
    if (m_cleanIndex > m_index)
        m_cleanIndex = static_cast<std::size_t>(-1); // the clean state can no longer be reached
    m_commands.push_back(std::move(command));
    ++m_index;
    change.add(ChangeKind::History);
    notify(std::move(change));
}

void History::begin(std::string text)
{
    rollback();
    m_open = Transaction{std::move(text), {}};
}

void History::revert()
{
    if (!m_open || m_open->commands.empty())
        return;
    Change change;
    for (auto it = m_open->commands.rbegin(); it != m_open->commands.rend(); ++it) {
        (*it)->undo(m_document);
        change.merge((*it)->change());
    }
    m_open->commands.clear();
    change.preview = true;
    notify(std::move(change));
}

void History::commit(const std::string& text)
{
    if (!m_open)
        return;
    Transaction t = std::move(*m_open);
    m_open.reset();
    if (t.commands.empty())
        return;
    auto macro = t.commands.size() == 1 && text.empty()
                     ? std::move(t.commands.front())
                     : std::make_unique<MacroCommand>(text.empty() ? t.text : text, std::move(t.commands));
    Change change = macro->change();
    m_commands.resize(m_index);
    if (m_cleanIndex > m_index)
        m_cleanIndex = static_cast<std::size_t>(-1);
    m_commands.push_back(std::move(macro));
    ++m_index;
    change.add(ChangeKind::History);
    notify(std::move(change));
}

void History::rollback()
{
    if (!m_open)
        return;
    const bool changed = !m_open->commands.empty();
    Change change;
    for (auto it = m_open->commands.rbegin(); it != m_open->commands.rend(); ++it) {
        (*it)->undo(m_document);
        change.merge((*it)->change());
    }
    m_open.reset();
    if (changed)
        notify(std::move(change)); // no longer a preview: views show the document as it is
}

void History::undo()
{
    rollback();
    if (!canUndo())
        return;
    Change change = m_commands[--m_index]->change();
    m_commands[m_index]->undo(m_document);
    change.add(ChangeKind::History);
    notify(std::move(change));
}

void History::redo()
{
    rollback();
    if (!canRedo())
        return;
    Change change = m_commands[m_index]->change();
    m_commands[m_index++]->redo(m_document);
    change.add(ChangeKind::History);
    notify(std::move(change));
}

std::string History::undoText() const { return canUndo() ? m_commands[m_index - 1]->text() : std::string(); }
std::string History::redoText() const { return canRedo() ? m_commands[m_index]->text() : std::string(); }
std::string History::textAt(std::size_t i) const { return i < m_commands.size() ? m_commands[i]->text() : std::string(); }

void History::jumpTo(std::size_t index)
{
    index = std::min(index, m_commands.size());
    while (m_index > index)
        undo();
    while (m_index < index)
        redo();
}

void History::reset(model::GuideDocument document)
{
    m_open.reset(); // its commands belong to the document being replaced
    m_document = std::move(document);
    m_commands.clear();
    m_index = m_cleanIndex = 0;
    notify(Change::of(ChangeKind::Document | ChangeKind::History));
}

int History::addListener(Listener listener)
{
    m_listeners.emplace_back(m_nextListener, std::move(listener));
    return m_nextListener++;
}

void History::removeListener(int handle)
{
    std::erase_if(m_listeners, [&](const auto& l) { return l.first == handle; });
}

void History::notify(Change change)
{
    const auto listeners = m_listeners; // a listener may remove itself
    for (const auto& [handle, listener] : listeners)
        listener(change);
}

} // namespace rs::edit
