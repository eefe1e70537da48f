#include "edit/History.h"

#include <algorithm>

namespace rs::edit {

void History::push(std::unique_ptr<Command> command)
{
    command->redo(m_document);
    m_commands.resize(m_index);
    if (m_cleanIndex > m_index)
        m_cleanIndex = static_cast<std::size_t>(-1); // the clean state can no longer be reached
    m_commands.push_back(std::move(command));
    ++m_index;
    notify();
}

void History::undo()
{
    if (!canUndo())
        return;
    m_commands[--m_index]->undo(m_document);
    notify();
}

void History::redo()
{
    if (!canRedo())
        return;
    m_commands[m_index++]->redo(m_document);
    notify();
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
    m_document = std::move(document);
    m_commands.clear();
    m_index = m_cleanIndex = 0;
    notify();
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

void History::notify()
{
    const auto listeners = m_listeners; // a listener may remove itself
    for (const auto& [handle, listener] : listeners)
        listener();
}

} // namespace rs::edit
