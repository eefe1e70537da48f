#include "OverridesPanel.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <set>

namespace rs::widgets {

namespace {

constexpr int kEntryRole = Qt::UserRole;      // index into m_entries; -1 on instance items
constexpr int kKindRole = Qt::UserRole + 1;   // an OverrideKind on kind items; -1 on node and instance items
const QColor kOrphan(230, 140, 40);

QString number(double v) { return QString::number(v, 'g', 6); }

QString channels(const std::map<std::string, double>& values)
{
    QStringList parts;
    for (const auto& [name, value] : values)
        parts << QString::fromStdString(name) + " = " + number(value);
    return parts.join(", ");
}

// The kinds a record has, each with a line saying what it holds.
std::vector<std::pair<model::OverrideKind, QString>> kindsOf(const model::Override& o)
{
    using K = model::OverrideKind;
    std::vector<std::pair<K, QString>> kinds;
    if (o.shape) {
        QStringList what;
        if (!o.shape->edit.isIdentity()) what << QObject::tr("edited (%1 CVs moved)").arg(o.shape->edit.cvs.size());
        if (o.shape->color) what << QObject::tr("colour");
        if (o.shape->lineWidth) what << QObject::tr("line width %1").arg(number(*o.shape->lineWidth));
        if (o.shape->visible) what << (*o.shape->visible ? QObject::tr("shown") : QObject::tr("hidden"));
        kinds.push_back({K::Shapes, what.join(", ")});
    }
    if (!o.defaults.empty()) kinds.push_back({K::Defaults, channels(o.defaults)});
    if (!o.limits.empty()) {
        QStringList parts;
        for (const auto& [name, l] : o.limits) parts << QString::fromStdString(name) + " " + number(l.min) + " to " + number(l.max);
        kinds.push_back({K::Limits, parts.join(", ")});
    }
    if (!o.locks.empty()) {
        QStringList parts;
        for (const auto& [name, s] : o.locks)
            parts << QString::fromStdString(name) + " " + (s.locked ? QObject::tr("locked") : QObject::tr("unlocked")) +
                         (s.keyable ? QString() : QObject::tr(", not keyable"));
        kinds.push_back({K::Locks, parts.join("; ")});
    }
    if (o.post)
        kinds.push_back({K::Post, QObject::tr("offset %1 %2 %3, scale %4")
                                      .arg(number(o.post->translate.x), number(o.post->translate.y), number(o.post->translate.z),
                                           number(o.post->scale.x))});
    if (o.displayName) kinds.push_back({K::Names, QString::fromStdString(*o.displayName)});
    if (!o.pose.empty()) kinds.push_back({K::Pose, channels(o.pose)});
    return kinds;
}

} // namespace

QStringList OverridesPanel::describe(const model::Override& record)
{
    QStringList lines;
    for (const auto& [kind, text] : kindsOf(record))
        lines << QString(model::overrideKindName(kind)) + ": " + text;
    return lines;
}

OverridesPanel::OverridesPanel(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    m_filter = new QLineEdit(this);
    m_filter->setObjectName("overridesFilter");
    m_filter->setPlaceholderText(tr("Filter (instance, node, kind, channel)"));
    m_filter->setClearButtonEnabled(true);
    layout->addWidget(m_filter);
    m_tree = new QTreeWidget(this);
    m_tree->setObjectName("overridesTree");
    m_tree->setColumnCount(2);
    m_tree->setHeaderLabels({tr("Override"), tr("Status")});
    m_tree->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_tree->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    layout->addWidget(m_tree, 1);
    auto* buttons = new QHBoxLayout;
    auto button = [&](const char* name, const QString& text, const QString& tip) {
        auto* b = new QPushButton(text, this);
        b->setObjectName(name);
        b->setToolTip(tip);
        buttons->addWidget(b);
        return b;
    };
    m_delete = button("overridesDelete", tr("Delete"), tr("Delete the selected records, or only the selected kinds"));
    m_retarget = button("overridesRetarget", tr("Re-target..."), tr("Move the current record onto another node of the rig"));
    m_deleteOrphans = button("overridesDeleteOrphans", tr("Delete All Orphans"), tr("Delete every record whose node the rig does not make"));
    layout->addLayout(buttons);

    connect(m_filter, &QLineEdit::textChanged, this, [this] { rebuild(); });
    connect(m_delete, &QPushButton::clicked, this, &OverridesPanel::deleteSelected);
    connect(m_retarget, &QPushButton::clicked, this, &OverridesPanel::openRetargetDialog);
    connect(m_deleteOrphans, &QPushButton::clicked, this, &OverridesPanel::deleteAllOrphans);
    connect(m_tree, &QTreeWidget::itemSelectionChanged, this, &OverridesPanel::updateButtons);
    connect(m_tree, &QTreeWidget::itemClicked, this, [this](QTreeWidgetItem* item) {
        if (const Entry* e = entryOf(item); e && e->orphanReason.isEmpty())
            emit nodeActivated(e->key);
    });
    updateButtons();
}

void OverridesPanel::setFilter(const QString& text) { m_filter->setText(text); }

void OverridesPanel::refresh(std::vector<Entry> entries, std::vector<Target> targets)
{
    m_entries = std::move(entries);
    m_targets = std::move(targets);
    rebuild();
}

const OverridesPanel::Entry* OverridesPanel::entryOf(const QTreeWidgetItem* item) const
{
    if (!item) return nullptr;
    const int index = item->data(0, kEntryRole).toInt();
    return index >= 0 && std::size_t(index) < m_entries.size() ? &m_entries[index] : nullptr;
}

QTreeWidgetItem* OverridesPanel::itemOf(const NodeKey& key) const
{
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* instance = m_tree->topLevelItem(i);
        for (int j = 0; j < instance->childCount(); ++j)
            if (const Entry* e = entryOf(instance->child(j)); e && e->key == key)
                return instance->child(j);
    }
    return nullptr;
}

void OverridesPanel::rebuild()
{
    // Keep what was selected and open across a refresh, by node key and kind.
    std::set<std::pair<NodeKey, int>> selected;
    for (QTreeWidgetItem* item : m_tree->selectedItems())
        if (const Entry* e = entryOf(item)) selected.insert({e->key, item->data(0, kKindRole).toInt()});
    std::set<QString> collapsed;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i)
        if (!m_tree->topLevelItem(i)->isExpanded()) collapsed.insert(m_tree->topLevelItem(i)->text(0));

    m_tree->clear();
    const QString filter = m_filter->text().trimmed();
    std::map<QString, QTreeWidgetItem*> instances;
    std::vector<QTreeWidgetItem*> reselect;
    for (std::size_t i = 0; i < m_entries.size(); ++i) {
        const Entry& e = m_entries[i];
        const auto kinds = kindsOf(e.record);
        const QString tag = QString::fromStdString(e.key.tag);
        const QString branch = QString::fromStdString(e.key.branch);
        if (!filter.isEmpty()) {
            QStringList haystack{e.instance, e.node, tag, branch, e.orphanReason, e.orphanReason.isEmpty() ? QString() : tr("orphan")};
            for (const auto& [kind, text] : kinds) haystack << model::overrideKindName(kind) << text;
            if (!haystack.join('\n').contains(filter, Qt::CaseInsensitive))
                continue;
        }
        QTreeWidgetItem*& parent = instances[e.instance];
        if (!parent) {
            parent = new QTreeWidgetItem(m_tree, {e.instance});
            parent->setData(0, kEntryRole, -1);
            parent->setData(0, kKindRole, -1);
            parent->setExpanded(!collapsed.count(e.instance));
            QFont bold = parent->font(0);
            bold.setBold(true);
            parent->setFont(0, bold);
        }
        const QString label = e.node + (e.node != tag ? " (" + (branch.isEmpty() ? QString() : branch + " ") + tag + ")" : QString());
        auto* node = new QTreeWidgetItem(parent, {label, e.orphanReason.isEmpty() ? tr("applied") : tr("orphan: %1").arg(e.orphanReason)});
        node->setData(0, kEntryRole, int(i));
        node->setData(0, kKindRole, -1);
        node->setToolTip(0, describe(e.record).join('\n'));
        if (!e.orphanReason.isEmpty()) {
            for (int c = 0; c < 2; ++c) node->setForeground(c, kOrphan);
            node->setToolTip(1, e.orphanReason);
            parent->setForeground(0, kOrphan);
        }
        if (selected.count({e.key, -1})) reselect.push_back(node);
        for (const auto& [kind, text] : kinds) {
            auto* item = new QTreeWidgetItem(node, {QString(model::overrideKindName(kind)), text});
            item->setData(0, kEntryRole, int(i));
            item->setData(0, kKindRole, int(kind));
            item->setToolTip(1, text);
            if (selected.count({e.key, int(kind)})) reselect.push_back(item);
        }
        node->setExpanded(true);
    }
    m_tree->clearSelection(); // only what was selected before, nothing Qt picks by itself
    for (QTreeWidgetItem* item : reselect)
        item->setSelected(true);
    updateButtons();
}

void OverridesPanel::updateButtons()
{
    const auto items = m_tree->selectedItems();
    bool any = false;
    for (QTreeWidgetItem* item : items) any = any || entryOf(item);
    m_delete->setEnabled(any);
    m_retarget->setEnabled(entryOf(m_tree->currentItem()) && !m_targets.empty());
    bool orphans = false;
    for (const Entry& e : m_entries) orphans = orphans || !e.orphanReason.isEmpty();
    m_deleteOrphans->setEnabled(orphans);
}

void OverridesPanel::deleteSelected()
{
    std::map<NodeKey, model::Override> records;
    std::set<NodeKey> whole;
    for (QTreeWidgetItem* item : m_tree->selectedItems()) {
        const Entry* e = entryOf(item);
        if (!e) continue;
        const int kind = item->data(0, kKindRole).toInt();
        if (kind < 0) {
            whole.insert(e->key);
            records[e->key] = {};
        } else if (!whole.count(e->key)) {
            auto [it, fresh] = records.try_emplace(e->key, e->record);
            it->second.clear(model::OverrideKind(kind));
        }
    }
    if (records.empty()) return;
    emit recordsEditRequested(records, records.size() == 1 && whole.size() == 1 ? tr("Delete override") : tr("Delete overrides"));
}

void OverridesPanel::deleteAllOrphans()
{
    std::map<NodeKey, model::Override> records;
    for (const Entry& e : m_entries)
        if (!e.orphanReason.isEmpty()) records[e.key] = {};
    if (!records.empty())
        emit recordsEditRequested(records, tr("Delete all orphans"));
}

void OverridesPanel::openRetargetDialog()
{
    const Entry* from = entryOf(m_tree->currentItem());
    if (!from || m_targets.empty()) return;
    auto* dialog = new QDialog(this);
    dialog->setObjectName("retargetDialog");
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(tr("Re-target the overrides of %1").arg(from->node));
    auto* layout = new QVBoxLayout(dialog);
    auto* filter = new QLineEdit(dialog);
    filter->setObjectName("retargetFilter");
    filter->setPlaceholderText(tr("Filter nodes"));
    layout->addWidget(filter);
    auto* list = new QListWidget(dialog);
    list->setObjectName("retargetList");
    for (std::size_t i = 0; i < m_targets.size(); ++i) {
        if (m_targets[i].key == from->key) continue;
        auto* item = new QListWidgetItem(m_targets[i].label, list);
        item->setData(Qt::UserRole, int(i));
    }
    layout->addWidget(list, 1);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, dialog);
    layout->addWidget(buttons);
    auto* ok = buttons->button(QDialogButtonBox::Ok);
    ok->setEnabled(false);
    connect(filter, &QLineEdit::textChanged, list, [list](const QString& text) {
        for (int i = 0; i < list->count(); ++i)
            list->item(i)->setHidden(!list->item(i)->text().contains(text, Qt::CaseInsensitive));
    });
    connect(list, &QListWidget::currentItemChanged, ok, [ok](QListWidgetItem* item) { ok->setEnabled(item); });
    connect(list, &QListWidget::itemDoubleClicked, dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::accepted, dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::reject);
    const NodeKey key = from->key;
    connect(dialog, &QDialog::accepted, this, [this, list, key] {
        if (QListWidgetItem* item = list->currentItem()) {
            const int i = item->data(Qt::UserRole).toInt();
            if (i >= 0 && std::size_t(i) < m_targets.size())
                emit retargetRequested(key, m_targets[i].key);
        }
    });
    dialog->resize(360, 420);
    dialog->open();
}

} // namespace rs::widgets
