#include "TemplateLibrary.h"

#include <QDesktopServices>
#include <QHeaderView>
#include <QIcon>
#include <QMenu>
#include <QUrl>

#include <map>

namespace rs::widgets {

namespace {

constexpr int kIdRole = Qt::UserRole + 1;
constexpr int kHelpRole = Qt::UserRole + 2;

} // namespace

TemplateLibrary::TemplateLibrary(QWidget* parent) : QTreeWidget(parent)
{
    setObjectName("templateLibrary");
    setHeaderHidden(true);
    setContextMenuPolicy(Qt::CustomContextMenu);
    connect(this, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
        if (const QString id = item->data(0, kIdRole).toString(); !id.isEmpty())
            emit templateActivated(id);
    });
    connect(this, &QWidget::customContextMenuRequested, this, [this](const QPoint& at) {
        QTreeWidgetItem* item = itemAt(at);
        if (!item || item->data(0, kIdRole).toString().isEmpty())
            return;
        QMenu menu(this);
        const QString id = item->data(0, kIdRole).toString();
        menu.addAction(tr("Add at the selected joint"), this, [this, id] { emit templateActivated(id); });
        const QString help = item->data(0, kHelpRole).toString();
        QAction* open = menu.addAction(tr("Open help"), this, [help] { QDesktopServices::openUrl(QUrl(help)); });
        open->setEnabled(!help.isEmpty());
        menu.exec(viewport()->mapToGlobal(at));
    });
}

void TemplateLibrary::refresh(const templates::TemplateRegistry& templates)
{
    clear();
    std::map<std::string, QTreeWidgetItem*> categories;
    for (const templates::TemplateManifest* m : templates.all()) {
        QTreeWidgetItem*& category = categories[m->category];
        if (!category) {
            category = new QTreeWidgetItem(this, {QString::fromStdString(m->category)});
            category->setFlags(Qt::ItemIsEnabled);
        }
        auto* item = new QTreeWidgetItem(category, {QString::fromStdString(m->module)});
        item->setIcon(0, QIcon(QString::fromStdString(templates.iconPath(*m))));
        item->setData(0, kIdRole, QString::fromStdString(m->id));
        item->setData(0, kHelpRole, QString::fromStdString(m->help));
        QString tip = QStringLiteral("<b>%1</b>").arg(QString::fromStdString(m->id).toHtmlEscaped());
        if (!m->desc.empty())
            tip += "<br>" + QString::fromStdString(m->desc).toHtmlEscaped();
        if (!m->help.empty())
            tip += "<br><i>" + QString::fromStdString(m->help).toHtmlEscaped() + "</i>";
        item->setToolTip(0, tip);
    }
    expandAll();
}

QTreeWidgetItem* TemplateLibrary::itemOf(const QString& templateId) const
{
    for (int c = 0; c < topLevelItemCount(); ++c)
        for (int i = 0; i < topLevelItem(c)->childCount(); ++i)
            if (topLevelItem(c)->child(i)->data(0, kIdRole).toString() == templateId)
                return topLevelItem(c)->child(i);
    return nullptr;
}

} // namespace rs::widgets
