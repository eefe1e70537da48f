// MainWindow's View > Display toggles (what the viewport draws), View >
// Navigation (how the mouse moves the camera) and the Window menu (every dock
// and the toolbar, so a closed one comes back). Toggles and the scheme are
// kept in the settings.
#include "MainWindow.h"

#include "ActionKit.h"
#include "Settings.h"
#include "ViewportWidget.h"

#include <QActionGroup>
#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QToolBar>

namespace rs::app {

void MainWindow::createDisplayActions()
{
    QMenu* view = findChild<QMenu*>("viewMenu");
    view->addSeparator();
    QMenu* display = view->addMenu(tr("&Display"));
    display->setObjectName("displayMenu");
    using Layer = bool viewport::DisplayOptions::*;
    const std::tuple<const char*, QString, Layer, QKeySequence> layers[] = {
        {"guides", tr("&Guides"), &viewport::DisplayOptions::guides, {}},
        {"shapes", tr("&Shapes (Guide mode)"), &viewport::DisplayOptions::shapes, {}},
        {"controllers", tr("&Controllers (Rig mode)"), &viewport::DisplayOptions::controllers, {}},
        {"skinJoints", tr("S&kin Joints"), &viewport::DisplayOptions::skinJoints, {}},
        {"reference", tr("&Reference Model"), &viewport::DisplayOptions::reference, {}},
        {"labels", tr("&Labels"), &viewport::DisplayOptions::labels, {}},
        {"axes", tr("Joint &Axes"), &viewport::DisplayOptions::axes, QKeySequence(tr("Ctrl+Shift+X"))}};
    for (const auto& [key, text, layer, shortcut] : layers) {
        QAction* a = makeAction(this, QString("display:") + key, text, shortcut);
        a->setCheckable(true);
        m_display.*layer = settings::isDisplayed(key, m_display.*layer);
        a->setChecked(m_display.*layer);
        const Layer l = layer;
        const QString name = key;
        connect(a, &QAction::toggled, this, [this, l, name](bool on) {
            m_display.*l = on;
            settings::setDisplayed(name, on);
            refreshScene();
        });
        display->addAction(a);
    }
    action("display:axes")->setToolTip(tr("Draw each joint's local axes: X red, Y green, Z blue (Ctrl+Shift+X)"));

    QMenu* navigation = view->addMenu(tr("&Navigation"));
    navigation->setObjectName("navigationMenu");
    auto* schemes = new QActionGroup(this);
    const std::tuple<const char*, QString, QString, viewport::Navigation> choices[] = {
        {"maya", tr("&Maya (Alt+drag)"), tr("Alt+left drag orbits, middle drag pans, the wheel zooms"), viewport::Navigation::Maya},
        {"blender", tr("&Blender (middle drag)"), tr("Middle drag orbits, Shift+middle pans, Ctrl+middle or the wheel zooms"),
         viewport::Navigation::Blender},
        {"touchpad", tr("&Touchpad"), tr("Two-finger scroll orbits, Shift+scroll pans, Ctrl+scroll or a pinch zooms"),
         viewport::Navigation::Touchpad}};
    const QString saved = settings::navigation();
    for (const auto& [key, text, tip, scheme] : choices) {
        QAction* a = makeAction(this, QString("navigation:") + key, text, {});
        a->setCheckable(true);
        a->setToolTip(tip);
        a->setStatusTip(tip);
        schemes->addAction(a);
        navigation->addAction(a);
        const auto s = scheme;
        const QString name = key;
        connect(a, &QAction::toggled, this, [this, s, name](bool on) {
            if (!on)
                return;
            m_viewport->setNavigation(s);
            settings::setNavigation(name);
        });
        if (saved == key)
            a->setChecked(true);
    }
    if (!schemes->checkedAction())
        action("navigation:maya")->setChecked(true);

    QMenu* window = menuBar()->addMenu(tr("&Window"));
    window->setObjectName("windowMenu");
    for (QDockWidget* dock : findChildren<QDockWidget*>()) {
        QAction* toggle = dock->toggleViewAction();
        toggle->setObjectName("window:" + dock->objectName());
        window->addAction(toggle);
    }
    window->addSeparator();
    QAction* toolbar = findChild<QToolBar*>("mainToolBar")->toggleViewAction();
    toolbar->setObjectName("window:mainToolBar");
    window->addAction(toolbar);
}

} // namespace rs::app
