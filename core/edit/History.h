#pragma once
// The command history of one guide document. Every edit is a Command pushed here:
// push() applies it, undo()/redo() walk the stack. Listeners hear about every
// change with what it changed (a typed Change), so views, autosave and the
// dirty marker stay in step and refresh only that.
//
// Transactions: begin() opens one; commands pushed while it is open apply at
// once (listeners hear them as previews) and commit() makes them one undo step;
// revert() takes back what was pushed so far (a drag's next preview replaces
// the last one) and rollback() closes the transaction leaving the document as
// it was. Undo, redo, jumpTo and reset roll an open transaction back first.
#include "edit/Change.h"
#include "model/GuideDocument.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rs::edit {

class Command {
public:
    virtual ~Command() = default;
    virtual std::string text() const = 0;      // "Add template core.joints"
    virtual void redo(model::GuideDocument& document) = 0;
    virtual void undo(model::GuideDocument& document) = 0;
    // What redo() and undo() change; by default everything (Document).
    virtual Change change() const { return Change::of(ChangeKind::Document); }
};

class History {
public:
    explicit History(model::GuideDocument& document) : m_document(document) {}

    const model::GuideDocument& document() const { return m_document; }
    void push(std::unique_ptr<Command> command);

    void begin(std::string text);
    bool inTransaction() const { return m_open.has_value(); }
    void revert();
    // Records the transaction as one undo step named `text`; without a text, a
    // single command keeps its own name and several take the name given to
    // begin(). A transaction that changed nothing records nothing.
    void commit(const std::string& text = {});
    void rollback();
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
    void setClean() { m_cleanIndex = m_index; notify(Change::of(ChangeKind::History)); }
    // Unsaved whatever is undone or redone (a document recovered from an autosave).
    void setModified() { m_cleanIndex = static_cast<std::size_t>(-1); notify(Change::of(ChangeKind::History)); }

    using Listener = std::function<void(const Change&)>;
    int addListener(Listener listener);
    void removeListener(int handle);

private:
    void notify(Change change);
    struct Transaction {
        std::string text;
        std::vector<std::unique_ptr<Command>> commands;
    };
    std::optional<Transaction> m_open;

    model::GuideDocument& m_document;
    std::vector<std::unique_ptr<Command>> m_commands;
    std::size_t m_index = 0;
    std::size_t m_cleanIndex = 0;
    std::vector<std::pair<int, Listener>> m_listeners;
    int m_nextListener = 1;
};

} // namespace rs::edit
