#pragma once
// The template library dock (issue 7): the templates by category (the folder
// names), each with its icon, `desc` as the tooltip and its `help` link in the
// context menu. Double-click (or Enter) asks to add the template at the
// selected guide joint.
#include "templates/TemplateRegistry.h"

#include <QTreeWidget>

namespace rs::widgets {

class TemplateLibrary : public QTreeWidget {
    Q_OBJECT
public:
    explicit TemplateLibrary(QWidget* parent = nullptr);
    void refresh(const templates::TemplateRegistry& templates);
    // The item of a template id (tests), null when not listed.
    QTreeWidgetItem* itemOf(const QString& templateId) const;

signals:
    void templateActivated(const QString& templateId);
};

} // namespace rs::widgets
