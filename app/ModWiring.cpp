// Mods in the editor (issue 23 item 3): the Mods dock lists the guide's mods by
// owner and edits one mod's YAML text; each add, edit and delete is one session
// command (one undo step), and the live rig is rebuilt with it.
#include "MainWindow.h"
#include "ModsPanel.h"

#include <QDockWidget>

namespace rs::app {

void MainWindow::createModsDock(QDockWidget* tabWith)
{
    m_modsPanel = new widgets::ModsPanel(this);
    m_modsPanel->setObjectName("modsPanel");
    QDockWidget* dock = addDock(m_modsPanel, tr("Mods"), "modsDock", Qt::BottomDockWidgetArea);
    tabifyDockWidget(tabWith, dock);
    connect(m_modsPanel, &widgets::ModsPanel::modAddRequested, this,
            [this](const model::Mod& mod) { logStatus(m_session.addMod(mod)); });
    connect(m_modsPanel, &widgets::ModsPanel::modEditRequested, this,
            [this](std::size_t index, const model::Mod& mod) { logStatus(m_session.setMod(index, mod)); });
    connect(m_modsPanel, &widgets::ModsPanel::modRemoveRequested, this,
            [this](std::size_t index) { logStatus(m_session.removeMod(index)); });
    refreshModsPanel();
}

void MainWindow::refreshModsPanel()
{
    m_modsPanel->refresh(m_session.document());
}

} // namespace rs::app
