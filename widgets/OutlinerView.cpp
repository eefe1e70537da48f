#include "OutlinerView.h"

#include "eval/Pickwalk.h"

#include "base/Paths.h"
#include "templates/HookPoints.h"

#include <QHeaderView>
#include <QIcon>
#include <QInputDialog>
#include <QDropEvent>
#include <QKeyEvent>
#include <QMenu>
#include <QStandardItemModel>

#include <algorithm>
#include <map>
#include <set>

namespace rs::widgets {

namespace {
constexpr int kInstanceRole = Qt::UserRole + 1; // the instance (a hook item's owner)
constexpr int kHookRole = Qt::UserRole + 2;     // a hook pseudo-item's joint

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
    setSelectionMode(QAbstractItemView::ExtendedSelection);
    setDragEnabled(true);
    setAcceptDrops(true);
    setDropIndicatorShown(true);
    setDragDropMode(QAbstractItemView::DragDrop);
    setDefaultDropAction(Qt::MoveAction);
    connect(selectionModel(), &QItemSelectionModel::currentChanged, this, [this](const QModelIndex& current) {
        if (m_refreshing || !current.isValid())
            return;
        if (const auto hook = current.data(kHookRole).toUInt())
            emit hookSelected(current.data(kInstanceRole).toUInt(), hook);
        else
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
    std::map<model::JointId, QStandardItem*> hooks;
    std::set<model::JointId> used; // joints something hangs under
    for (const auto& instance : document.instances())
        used.insert(instance.parentJoint);
    const QIcon hookIcon = cachedIcon(iconsDirectory() + "/hook.svg");
    for (const auto& instance : document.instances()) {
        auto* item = new QStandardItem(QString::fromStdString(instance.name));
        item->setData(instance.id, kInstanceRole);
        item->setDropEnabled(true);
        const templates::TemplateManifest* manifest = templates.find(instance.templateId);
        item->setIcon(cachedIcon(manifest ? templates.iconPath(*manifest) : std::string()));
        item->setToolTip(QString::fromStdString(instance.templateId + (manifest && !manifest->desc.empty() ? "\n" + manifest->desc : "")));
        auto hook = hooks.find(instance.parentJoint);
        auto parent = items.find(instance.parent);
        QStandardItem* under = hook != hooks.end() ? hook->second : parent != items.end() ? parent->second : m_model->invisibleRootItem();
        under->appendRow(item);
        items[instance.id] = item;
        if (!manifest)
            continue;
        const std::vector<templates::HookPoint> points = templates::hookPoints(*manifest, instance);
        for (const templates::HookPoint& point : points) {
            const bool named = std::any_of(points.begin(), points.end(), [&](const templates::HookPoint& other) {
                return other.joint == point.joint && other.label != "default";
            });
            const bool indexed = point.label.find('[') != std::string::npos; // one of a chain's joints
            const bool unused = !used.count(point.joint);
            if (manifest->hooks.empty() || hooks.count(point.joint) || (point.label == "default" && (named || unused)) ||
                (indexed && unused))
                continue; // named hooks once each, default and chain hooks when used (the menu offers every hook)
            auto* hookItem = new QStandardItem(hookIcon, QString::fromStdString(point.label));
            hookItem->setData(instance.id, kInstanceRole);
            hookItem->setData(point.joint, kHookRole);
            hookItem->setEditable(false);
            hookItem->setDragEnabled(false);
            hookItem->setForeground(QColor(150, 160, 175));
            QFont italic = hookItem->font();
            italic.setItalic(true);
            hookItem->setFont(italic);
            hookItem->setToolTip(tr("Hook %1 of %2: drop templates here").arg(QString::fromStdString(point.label),
                                                                          QString::fromStdString(instance.name)));
            item->appendRow(hookItem);
            hooks[point.joint] = hookItem;
        }
    }
    expandAll();
    m_refreshing = false;
    selectInstance(selected);
}

void OutlinerView::selectInstance(model::InstanceId id)
{
    if (id != model::kNoId && selectedInstance() == id)
        return; // keeps a multi-selection made here

    QModelIndexList found = m_model->match(m_model->index(0, 0), kInstanceRole, id, -1, Qt::MatchRecursive);
    found.removeIf([](const QModelIndex& index) { return index.data(kHookRole).toUInt() != 0; });
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
        if (const auto id = index.data(kInstanceRole).toUInt();
            id != model::kNoId && !index.data(kHookRole).toUInt() && std::find(out.begin(), out.end(), id) == out.end())
            out.push_back(id);
    return out;
}

std::vector<model::InstanceId> OutlinerView::topSelectedInstances() const
{
    std::vector<model::InstanceId> ids = selectedInstances();
    std::erase_if(ids, [&](model::InstanceId id) {
        for (auto* i = m_document->instance(id); i && i->parent != model::kNoId; i = m_document->instance(i->parent))
            if (std::find(ids.begin(), ids.end(), i->parent) != ids.end())
                return true;
        return false;
    });
    return ids;
}

std::vector<model::InstanceId> OutlinerView::actedOn(model::InstanceId clicked) const
{
    std::vector<model::InstanceId> ids = topSelectedInstances();
    if (std::find(ids.begin(), ids.end(), clicked) == ids.end())
        ids = {clicked};
    return ids;
}

model::JointId OutlinerView::dropTarget(const QPoint& pos) const
{
    const QModelIndex index = indexAt(pos);
    if (!index.isValid())
        return model::kNoId;
    if (const auto hook = index.data(kHookRole).toUInt())
        return hook;
    const model::TemplateInstance* instance = m_document ? m_document->instance(index.data(kInstanceRole).toUInt()) : nullptr;
    if (!instance)
        return model::kNoId;
    const templates::TemplateManifest* manifest = m_templates->find(instance->templateId);
    return manifest ? templates::hookPoints(*manifest, *instance).front().joint : instance->joints.front().id;
}

void OutlinerView::dropEvent(QDropEvent* event)
{
    // The tree is a view of the document: the drop becomes re-hang requests and
    // the refresh after the edit moves the items, never Qt's own row move.
    const model::JointId target = dropTarget(event->position().toPoint());
    const std::vector<model::InstanceId> dragged = topSelectedInstances();
    event->setDropAction(Qt::IgnoreAction);
    event->accept();
    for (model::InstanceId id : dragged)
        emit reparentRequested(id, target);
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
    std::vector<templates::HookPoint> hooks;
    if (manifest)
        hooks = templates::hookPoints(*manifest, *instance);
    else
        hooks.push_back({"default", instance->joints.front().id});
    for (const templates::HookPoint& hook : hooks) {
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
    QAction* duplicate = menu->addAction(tr("Duplicate"));
    duplicate->setObjectName("duplicate");
    connect(duplicate, &QAction::triggered, this, [this, id] {
        const std::vector<model::InstanceId> ids = actedOn(id);
        emit duplicateRequested(QList<quint32>(ids.begin(), ids.end()));
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
    connect(remove, &QAction::triggered, this, [this, id] {
        const auto ids = actedOn(id);
        emit removeRequested(QList<quint32>(ids.begin(), ids.end()));
    });
    return menu;
}

void OutlinerView::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_Delete && !selectedInstances().empty()) {
        const auto ids = topSelectedInstances();
        emit removeRequested(QList<quint32>(ids.begin(), ids.end()));
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
