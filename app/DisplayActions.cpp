// MainWindow's View > Display toggles (what the viewport draws), the
// character's weight display and skinning method, View >
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
        {"meshes", tr("Character &Meshes"), &viewport::DisplayOptions::meshes, {}},
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
    createWeightDisplayActions(display);

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

namespace {

// A submenu of exclusive choices ("weights:off"...), each setting one value.
template <class Value, class Apply>
void addChoices(MainWindow* window, QMenu* menu, const QString& prefix,
                const std::vector<std::tuple<const char*, QString, QString, Value>>& choices, Value current, Apply apply)
{
    auto* group = new QActionGroup(window);
    for (const auto& [key, text, tip, value] : choices) {
        QAction* a = makeAction(window, prefix + key, text, {});
        a->setCheckable(true);
        a->setChecked(value == current);
        a->setToolTip(tip);
        a->setStatusTip(tip);
        group->addAction(a);
        menu->addAction(a);
        const Value v = value;
        QObject::connect(a, &QAction::toggled, window, [apply, v](bool on) {
            if (on)
                apply(v);
        });
    }
}

} // namespace

// View > Display > Weights (what the character's colours show) and Skinning.
void MainWindow::createWeightDisplayActions(QMenu* display)
{
    using viewport::Skinning;
    using viewport::WeightDisplay;
    QMenu* weights = display->addMenu(tr("&Weights"));
    weights->setObjectName("weightsMenu");
    addChoices<WeightDisplay>(
        this, weights, "weights:",
        {{"off", tr("&Off (materials)"), tr("Draw the character's meshes in their materials"), WeightDisplay::Off},
         {"selected", tr("&Selected Joint"),
          tr("The selected joint's weights as a heat map, blue 0 to red 1 (a controller shows the skin joint it drives)"),
          WeightDisplay::SelectedJoint},
         {"dominant", tr("&Dominant Joint"), tr("Each vertex in the colour of the joint that weighs most on it"),
          WeightDisplay::DominantJoint}},
        m_display.weights, [this](WeightDisplay mode) {
            m_display.weights = mode;
            refreshScene();
        });
    QMenu* skinning = display->addMenu(tr("S&kinning"));
    skinning->setObjectName("skinningMenu");
    m_display.skinning = settings::isDisplayed("dualQuaternion", false) ? Skinning::DualQuaternion : Skinning::Linear;
    addChoices<Skinning>(
        this, skinning, "skinning:",
        {{"linear", tr("&Linear Blend"), tr("Blend the joints' matrices (what game engines and exporters use)"), Skinning::Linear},
         {"dualQuaternion", tr("&Dual Quaternion"),
          tr("Blend the joints' rotations: a twisted wrist keeps its volume; joint scale is ignored"), Skinning::DualQuaternion}},
        m_display.skinning, [this](Skinning mode) {
            m_display.skinning = mode;
            settings::setDisplayed("dualQuaternion", mode == Skinning::DualQuaternion);
            refreshScene();
        });
}

} // namespace rs::app
