#pragma once
// The Mods dock: the guide's mods (model/Mod.h) as a tree, Global first, then
// each owner instance, one line per mod (its kind and main node). Selecting a
// mod shows its YAML text (io/ModText.h) in the editor below; Apply reads the
// text (a mistake is shown with its line and column, and nothing changes) and
// asks for the edit. Add (a menu of kinds) puts the kind's sample in the editor
// as a new mod of the owner chosen beside it, added on Apply; Delete removes the
// selected mod. It only shows what `refresh` gives and emits requests; the app
// turns each into one undoable session edit.
#include "model/GuideDocument.h"

#include <QWidget>

#include <cstddef>
#include <optional>
#include <vector>

class QComboBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QToolButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace rs::widgets {

class ModsPanel : public QWidget {
    Q_OBJECT
public:
    explicit ModsPanel(QWidget* parent = nullptr);

    // The document's mods; keeps the selected mod (by index) when it is still there.
    void refresh(const model::GuideDocument& document);
    QTreeWidget* tree() const { return m_tree; }
    QPlainTextEdit* editor() const { return m_text; }
    QLabel* errorLabel() const { return m_error; }
    // The mod shown in the editor (nullopt: none, or a new mod not yet added).
    std::optional<std::size_t> currentMod() const { return m_current; }
    void selectMod(std::size_t index);
    // Add: the sample of `kind` in the editor, a new mod of the owner chosen in the owner box.
    void startNewMod(model::ModKind kind);
    // The owner box's choice: "Global" or an instance's name (false: no such entry).
    bool chooseOwner(const QString& name);
    // Reads the editor's text; emits the add or edit, or shows why it does not read.
    void apply();
    void deleteCurrent();

signals:
    void modAddRequested(const rs::model::Mod& mod);
    void modEditRequested(std::size_t index, const rs::model::Mod& mod);
    void modRemoveRequested(std::size_t index);

private:
    void showMod(std::optional<std::size_t> index);
    void updateButtons();
    QTreeWidgetItem* itemOf(std::size_t index) const;

    const model::GuideDocument* m_document = nullptr;
    QTreeWidget* m_tree;
    QComboBox* m_owner;
    QToolButton* m_add;
    QPushButton* m_delete;
    QPlainTextEdit* m_text;
    QLabel* m_error;
    QPushButton* m_apply;
    std::optional<std::size_t> m_current;
    std::optional<model::ModInstance> m_newOwner; // a new mod is being written (Add)
    bool m_selectAdded = false;                   // select the last mod after the next refresh
};

} // namespace rs::widgets
