#include "ModsPanel.h"

#include "io/ModText.h"

#include <QComboBox>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <map>

namespace rs::widgets {

namespace {

constexpr int kIndexRole = Qt::UserRole; // the mod's index; -1 on owner items

// The node a mod is mainly about, as its rig id.
const model::ModRef* mainRef(const model::Mod& mod)
{
    return std::visit(
        [](const auto& m) -> const model::ModRef* {
            using T = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<T, model::HideMod>) return m.nodes.empty() ? nullptr : &m.nodes.front();
            else if constexpr (std::is_same_v<T, model::PlugMod>) return &m.channel;
            else if constexpr (std::is_same_v<T, model::DriveMod>) return &m.driven;
            else return &m.node;
        },
        mod.settings);
}

QString ownerLabel(const model::GuideDocument& d, const model::Mod& mod)
{
    if (mod.isGlobal())
        return QObject::tr("Global");
    const QString name = QString::fromStdString(io::modInstanceName(d, mod.owner));
    return d.instance(mod.owner.id) ? name : QObject::tr("%1 (not in the guide)").arg(name);
}

} // namespace

ModsPanel::ModsPanel(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    m_tree = new QTreeWidget(this);
    m_tree->setObjectName("modsTree");
    m_tree->setHeaderLabels({tr("Mod")});
    m_tree->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    layout->addWidget(m_tree, 1);

    auto* row = new QHBoxLayout;
    m_owner = new QComboBox(this);
    m_owner->setObjectName("modOwner");
    m_owner->setToolTip(tr("Whose mod Add makes: a global one, or an instance's (a bare tag is that instance's node)"));
    row->addWidget(m_owner, 1);
    m_add = new QToolButton(this);
    m_add->setObjectName("modAdd");
    m_add->setText(tr("Add"));
    m_add->setPopupMode(QToolButton::InstantPopup);
    auto* kinds = new QMenu(m_add);
    for (int k = 0; k < model::kModKindCount; ++k) {
        const auto kind = model::ModKind(k);
        QAction* a = kinds->addAction(QString(model::modKindName(kind)));
        a->setObjectName(QString("modAdd:") + model::modKindName(kind));
        connect(a, &QAction::triggered, this, [this, kind] { startNewMod(kind); });
    }
    m_add->setMenu(kinds);
    row->addWidget(m_add);
    m_delete = new QPushButton(tr("Delete"), this);
    m_delete->setObjectName("modDelete");
    row->addWidget(m_delete);
    layout->addLayout(row);

    m_text = new QPlainTextEdit(this);
    m_text->setObjectName("modText");
    m_text->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_text->setPlaceholderText(tr("Select a mod, or Add one"));
    layout->addWidget(m_text, 1);
    m_error = new QLabel(this);
    m_error->setObjectName("modError");
    m_error->setStyleSheet("color: #e06040");
    m_error->setWordWrap(true);
    m_error->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_error);
    m_apply = new QPushButton(tr("Apply"), this);
    m_apply->setObjectName("modApply");
    m_apply->setToolTip(tr("Read the text into the mod (Ctrl+Return)"));
    m_apply->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Return));
    layout->addWidget(m_apply);

    connect(m_tree, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        const int index = item ? item->data(0, kIndexRole).toInt() : -1;
        showMod(index >= 0 ? std::optional<std::size_t>(std::size_t(index)) : std::nullopt);
    });
    connect(m_apply, &QPushButton::clicked, this, &ModsPanel::apply);
    connect(m_delete, &QPushButton::clicked, this, &ModsPanel::deleteCurrent);
    connect(m_text, &QPlainTextEdit::textChanged, this, &ModsPanel::updateButtons);
    updateButtons();
}

void ModsPanel::refresh(const model::GuideDocument& document)
{
    m_document = &document;
    const QString owner = m_owner->currentText();
    m_owner->clear();
    m_owner->addItem(tr("Global"), 0u);
    for (const model::TemplateInstance& i : document.instances())
        m_owner->addItem(QString::fromStdString(i.name), i.id);
    chooseOwner(owner);

    std::optional<std::size_t> keep = m_current;
    if (m_selectAdded && !document.mods.empty())
        keep = document.mods.size() - 1;
    m_selectAdded = false;
    const QSignalBlocker block(m_tree);
    m_tree->clear();
    std::map<QString, QTreeWidgetItem*> owners;
    auto ownerItem = [&](const QString& label) {
        auto& item = owners[label];
        if (!item) {
            item = new QTreeWidgetItem(m_tree, {label});
            item->setData(0, kIndexRole, -1);
            item->setExpanded(true);
        }
        return item;
    };
    ownerItem(tr("Global"));
    for (std::size_t i = 0; i < document.mods.size(); ++i) {
        const model::Mod& mod = document.mods[i];
        const model::ModRef* ref = mainRef(mod);
        QString line = model::modKindName(mod.kind());
        if (ref)
            line += "  " + QString::fromStdString(io::formatModRef(document, *ref, mod.owner));
        auto* item = new QTreeWidgetItem(ownerItem(ownerLabel(document, mod)), {line});
        item->setData(0, kIndexRole, int(i));
        item->setToolTip(0, QString::fromStdString(io::writeModText(document, mod)));
    }
    m_tree->expandAll();
    if (m_newOwner && !keep) {
        updateButtons(); // a new mod is being written: its text stays
        return;
    }
    m_newOwner.reset();
    if (keep && *keep < document.mods.size()) {
        m_tree->setCurrentItem(itemOf(*keep));
        showMod(keep);
    } else {
        showMod(std::nullopt);
    }
}

QTreeWidgetItem* ModsPanel::itemOf(std::size_t index) const
{
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it)
        if ((*it)->data(0, kIndexRole).toInt() == int(index))
            return *it;
    return nullptr;
}

void ModsPanel::selectMod(std::size_t index)
{
    if (QTreeWidgetItem* item = itemOf(index))
        m_tree->setCurrentItem(item);
}

bool ModsPanel::chooseOwner(const QString& name)
{
    const int at = m_owner->findText(name);
    if (at >= 0)
        m_owner->setCurrentIndex(at);
    return at >= 0;
}

void ModsPanel::showMod(std::optional<std::size_t> index)
{
    m_newOwner.reset();
    m_current = m_document && index && *index < m_document->mods.size() ? index : std::nullopt;
    m_text->setPlainText(m_current ? QString::fromStdString(io::writeModText(*m_document, m_document->mods[*m_current])) : QString());
    m_error->clear();
    updateButtons();
}

void ModsPanel::startNewMod(model::ModKind kind)
{
    if (!m_document)
        return;
    const auto id = model::InstanceId(m_owner->currentData().toUInt());
    const model::TemplateInstance* instance = m_document->instance(id);
    m_newOwner = instance ? model::ModInstance{instance->id, instance->name} : model::ModInstance{};
    m_current.reset();
    {
        const QSignalBlocker block(m_tree);
        m_tree->setCurrentItem(nullptr);
    }
    m_text->setPlainText(QString::fromStdString(io::modSample(kind, instance != nullptr)));
    m_error->setText(tr("A new %1 mod of %2: edit the sample, then Apply")
                         .arg(model::modKindName(kind), instance ? QString::fromStdString(instance->name) : tr("the rig (global)")));
    m_text->setFocus();
    updateButtons();
}

void ModsPanel::apply()
{
    if (!m_document || (!m_current && !m_newOwner))
        return;
    const model::ModInstance owner = m_newOwner ? *m_newOwner : m_document->mods[*m_current].owner;
    auto mod = io::readModText(*m_document, owner, m_text->toPlainText().toStdString(), "mod");
    if (!mod) {
        QStringList lines;
        for (const Diagnostic& d : mod.diagnostics())
            if (d.severity == Severity::Error)
                lines << tr("line %1, column %2: %3").arg(d.where.line).arg(d.where.column).arg(QString::fromStdString(d.message));
        m_error->setText(lines.join("\n"));
        return;
    }
    m_error->clear();
    if (m_newOwner) {
        m_selectAdded = true;
        m_newOwner.reset();
        emit modAddRequested(*mod);
    } else {
        emit modEditRequested(*m_current, *mod);
    }
}

void ModsPanel::deleteCurrent()
{
    if (m_current)
        emit modRemoveRequested(*m_current);
}

void ModsPanel::updateButtons()
{
    m_delete->setEnabled(m_current.has_value());
    m_apply->setEnabled((m_current || m_newOwner) && !m_text->toPlainText().trimmed().isEmpty());
    m_text->setReadOnly(!m_current && !m_newOwner);
}

} // namespace rs::widgets
