#pragma once
// The command history of one guide document. Every edit is a Command pushed here:
// push() applies it, undo()/redo() walk the stack. Listeners hear about every
// change, so views, autosave and the dirty marker stay in step.
#include "model/GuideDocument.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rs::edit {

class Command {
public:
    virtual ~Command() = default;
    virtual std::string text() const = 0;      // "Add template core.joints"
    virtual void redo(model::GuideDocument& document) = 0;
    virtual void undo(model::GuideDocument& document) = 0;
};

class History {
public:
    explicit History(model::GuideDocument& document) : m_document(document) {}

    const model::GuideDocument& document() const { return m_document; }
    void push(std::unique_ptr<Command> command);
    bool canUndo() const { return m_index > 0; }
    bool canRedo() const { return m_index < m_commands.size(); }
    void undo();
    void redo();
    std::string undoText() const;
    std::string redoText() const;
    std::size_t size() const { return m_commands.size(); }
    std::size_t index() const { return m_index; }
    // The text of command i (0 <= i < size()); commands at or past index() are undone.
    std::string textAt(std::size_t i) const;
    // Undoes or redoes until `index` commands are applied (clamped to size()).
    void jumpTo(std::size_t index);

    // Replaces the document wholesale (File > Open) and forgets the stack.
    void reset(model::GuideDocument document);
    bool isClean() const { return m_cleanIndex == m_index; }
    void setClean() { m_cleanIndex = m_index; notify(); }
    // Unsaved whatever is undone or redone (a document recovered from an autosave).
    void setModified() { m_cleanIndex = static_cast<std::size_t>(-1); notify(); }

    using Listener = std::function<void()>;
    int addListener(Listener listener);
    void removeListener(int handle);

private:
    void notify();

    model::GuideDocument& m_document;
    std::vector<std::unique_ptr<Command>> m_commands;
    std::size_t m_index = 0;
    std::size_t m_cleanIndex = 0;
    std::vector<std::pair<int, Listener>> m_listeners;
    int m_nextListener = 1;
};

} // namespace rs::edit
