#include "OutlinerView.h"

#include "eval/Pickwalk.h"

#include "build/RigBuilder.h"

#include <QHeaderView>
#include <QIcon>
#include <QInputDialog>
#include <QKeyEvent>
#include <QMenu>
#include <QStandardItemModel>

#include <algorithm>
#include <map>

namespace rs::widgets {

namespace {
constexpr int kInstanceRole = Qt::UserRole + 1;

QIcon cachedIcon(const std::string& path)
{
    static std::map<std::string, QIcon> cache;
    auto it = cache.find(path);
    if (it == cache.end())
        it = cache.emplace(path, QIcon(QString::fromStdString(path))).first;
    return it->second;
}
} // namespace

OutlinerView::OutlinerView(QWidget* parent) : QTreeView(parent), m_model(new QStandardItemModel(this))
{
    setObjectName("outliner");
    setModel(m_model);
    setHeaderHidden(true);
    setContextMenuPolicy(Qt::CustomContextMenu);
    setEditTriggers(QAbstractItemView::EditKeyPressed | QAbstractItemView::DoubleClicked);
    connect(selectionModel(), &QItemSelectionModel::currentChanged, this, [this](const QModelIndex& current) {
        if (!m_refreshing && current.isValid())
            emit instanceSelected(current.data(kInstanceRole).toUInt());
    });
    connect(this, &QWidget::customContextMenuRequested, this, [this](const QPoint& pos) {
        const QModelIndex index = indexAt(pos);
        QMenu* menu = createContextMenu(index.isValid() ? index.data(kInstanceRole).toUInt() : model::kNoId, this);
        menu->exec(viewport()->mapToGlobal(pos));
        menu->deleteLater();
    });
    connect(m_model, &QStandardItemModel::itemChanged, this, [this](QStandardItem* item) {
        if (m_refreshing)
            return;
        const auto id = item->data(kInstanceRole).toUInt();
        const auto* instance = m_document ? m_document->instance(id) : nullptr;
        if (instance && item->text().toStdString() != instance->name)
            emit renameRequested(id, item->text());
    });
}

void OutlinerView::refresh(const model::GuideDocument& document, const templates::TemplateRegistry& templates)
{
    m_document = &document;
    m_templates = &templates;
    const model::InstanceId selected = selectedInstance();
    m_refreshing = true;
    m_model->clear();
    std::map<model::InstanceId, QStandardItem*> items;
    for (const auto& instance : document.instances()) {
        auto* item = new QStandardItem(QString::fromStdString(instance.name));
        item->setData(instance.id, kInstanceRole);
        const templates::TemplateManifest* manifest = templates.find(instance.templateId);
        item->setIcon(cachedIcon(manifest ? templates.iconPath(*manifest) : std::string()));
        item->setToolTip(QString::fromStdString(instance.templateId + (manifest && !manifest->desc.empty() ? "\n" + manifest->desc : "")));
        auto parent = items.find(instance.parent);
        (parent == items.end() ? m_model->invisibleRootItem() : parent->second)->appendRow(item);
        items[instance.id] = item;
    }
    expandAll();
    m_refreshing = false;
    selectInstance(selected);
}

void OutlinerView::selectInstance(model::InstanceId id)
{
    const QModelIndexList found = m_model->match(m_model->index(0, 0), kInstanceRole, id, 1, Qt::MatchRecursive);
    m_refreshing = true;
    if (found.isEmpty())
        selectionModel()->clearSelection();
    else
        setCurrentIndex(found.front());
    m_refreshing = false;
}

model::InstanceId OutlinerView::selectedInstance() const
{
    const QModelIndex current = currentIndex();
    return current.isValid() ? current.data(kInstanceRole).toUInt() : model::kNoId;
}

std::vector<model::InstanceId> OutlinerView::selectedInstances() const
{
    std::vector<model::InstanceId> out;
    for (const QModelIndex& index : selectionModel()->selectedRows())
        if (const auto id = index.data(kInstanceRole).toUInt(); id != model::kNoId &&
                                                                std::find(out.begin(), out.end(), id) == out.end())
            out.push_back(id);
    return out;
}

void OutlinerView::addTemplateEntries(QMenu* menu, model::JointId hookJoint)
{
    std::map<std::string, QMenu*> categories;
    for (const templates::TemplateManifest* m : m_templates->all()) {
        QMenu*& category = categories[m->category];
        if (!category)
            category = menu->addMenu(QString::fromStdString(m->category));
        QAction* action = category->addAction(cachedIcon(m_templates->iconPath(*m)), QString::fromStdString(m->module));
        action->setObjectName(QString::fromStdString("add:" + m->id));
        action->setToolTip(QString::fromStdString(m->desc));
        const QString id = QString::fromStdString(m->id);
        connect(action, &QAction::triggered, this, [this, id, hookJoint] { emit addTemplateRequested(id, hookJoint); });
    }
}

QMenu* OutlinerView::createContextMenu(model::InstanceId id, QWidget* parent)
{
    auto* menu = new QMenu(parent);
    if (!m_document || !m_templates)
        return menu;
    QMenu* add = menu->addMenu(tr("Add template"));
    add->setObjectName("addTemplate");
    const model::TemplateInstance* instance = m_document->instance(id);
    if (!instance) {
        addTemplateEntries(add, model::kNoId);
        return menu;
    }
    const templates::TemplateManifest* manifest = m_templates->find(instance->templateId);
    std::vector<build::HookPoint> hooks;
    if (manifest)
        hooks = build::hookPoints(*manifest, *instance);
    else
        hooks.push_back({"default", instance->joints.front().id});
    for (const build::HookPoint& hook : hooks) {
        QMenu* at = add->addMenu(QIcon(), QString::fromStdString(hook.label));
        at->setObjectName(QString::fromStdString("hook:" + hook.label));
        addTemplateEntries(at, hook.joint);
    }
    menu->addSeparator();
    QAction* rename = menu->addAction(tr("Rename..."));
    connect(rename, &QAction::triggered, this, [this, id, name = QString::fromStdString(instance->name)] {
        bool ok = false;
        const QString text = QInputDialog::getText(this, tr("Rename"), tr("Name:"), QLineEdit::Normal, name, &ok);
        if (ok && text != name)
            emit renameRequested(id, text);
    });
    QAction* mirror = menu->addAction(tr("Mirror (L/R branches)"));
    mirror->setObjectName("mirror");
    mirror->setCheckable(true);
    const auto stored = instance->options.find("branches");
    const Value* branches = stored != instance->options.end() ? &stored->second : nullptr;
    if (!branches && manifest)
        if (const templates::Parameter* p = manifest->findOpt("branches"))
            branches = &p->value;
    const bool mirrored = branches && std::holds_alternative<std::string>(*branches) &&
                          std::get<std::string>(*branches).find_first_not_of("[] ") != std::string::npos;
    mirror->setChecked(mirrored);
    connect(mirror, &QAction::triggered, this,
            [this, id](bool on) { emit branchesRequested(id, on ? QStringLiteral("[L, R]") : QStringLiteral("[]")); });
    QAction* reset = menu->addAction(tr("Reset options"));
    reset->setObjectName("resetOptions");
    reset->setEnabled(!instance->options.empty());
    connect(reset, &QAction::triggered, this, [this, id] { emit resetOptionsRequested(id); });
    QAction* remove = menu->addAction(tr("Delete"));
    remove->setObjectName("delete");
    connect(remove, &QAction::triggered, this, [this, id] { emit removeRequested(id); });
    return menu;
}

void OutlinerView::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_Delete && selectedInstance() != model::kNoId) {
        emit removeRequested(selectedInstance());
        return;
    }
    // Pickwalk, as in the viewport: Up parent, Down first child, Left/Right siblings.
    const std::pair<int, eval::WalkDirection> walks[] = {{Qt::Key_Up, eval::WalkDirection::Up},
                                                         {Qt::Key_Down, eval::WalkDirection::Down},
                                                         {Qt::Key_Left, eval::WalkDirection::Left},
                                                         {Qt::Key_Right, eval::WalkDirection::Right}};
    for (const auto& [key, direction] : walks)
        if (event->key() == key && event->modifiers() == Qt::NoModifier && selectedInstance() != model::kNoId) {
            emit walkRequested(int(direction));
            return;
        }
    QTreeView::keyPressEvent(event);
}

} // namespace rs::widgets
