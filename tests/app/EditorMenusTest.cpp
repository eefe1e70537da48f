// Issue 18, items 18-20: the transform panel and joint axes, framing, the
// Display, Edit, File, Help and Window menus, the navigation preference and
// the status bar after a build, driven through the real widgets.
#include "EditorTestSupport.h"

#include "Settings.h"
#include "TransformPanel.h"

#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QMenu>
#include <QStatusBar>
#include <QTextBrowser>
#include <QWheelEvent>

#include <set>

using namespace rs;
using namespace rs::test;

namespace {

model::JointId jointOf(app::MainWindow& w, const std::string& instance, std::size_t index)
{
    return w.session().document().instanceNamed(instance)->joints.at(index).id;
}

Vec3 worldPosition(app::MainWindow& w, model::JointId joint)
{
    return translationOf(w.session().document().jointWorldMatrix(joint));
}

} // namespace

TEST(NewUser, TransformPanelTypesAGuideJointsPositionAsOneUndoStep)
{
    Editor e;
    app::MainWindow& w = e.window;
    widgets::TransformPanel* panel = w.transformPanel();
    const model::JointId elbow = jointOf(w, "arm", 1);
    w.session().selectGuideJoints({elbow}, false);
    ASSERT_TRUE(panel->field(0, 0)->isEnabled());

    panel->setSpace(widgets::TransformPanel::Space::Local);
    const Transform before = w.session().document().joint(elbow)->local;
    EXPECT_DOUBLE_EQ(panel->field(0, 0)->value(), before.translate.x);
    panel->field(0, 0)->setValue(0.5); // as if typed and entered
    EXPECT_DOUBLE_EQ(w.session().document().joint(elbow)->local.translate.x, 0.5);
    EXPECT_EQ(w.session().document().joint(elbow)->local.translate.y, before.translate.y);
    EXPECT_EQ(w.session().history().undoText(), "Set transform of guide joint of arm");
    w.action("undo")->trigger();
    EXPECT_EQ(w.session().document().joint(elbow)->local, before);
    EXPECT_DOUBLE_EQ(panel->field(0, 0)->value(), before.translate.x) << "the panel follows undo";

    panel->setSpace(widgets::TransformPanel::Space::World);
    panel->field(0, 1)->setValue(1.25);
    EXPECT_NEAR(worldPosition(w, elbow).y, 1.25, 1e-6);
    w.action("undo")->trigger();

    // Relative, world: two selected joints move up 10 cm together, one step.
    const model::JointId knee = jointOf(w, "leg", 1);
    w.session().selectGuideJoints({elbow, knee}, false);
    const Vec3 elbowAt = worldPosition(w, elbow), kneeAt = worldPosition(w, knee);
    const std::size_t steps = w.session().history().index();
    panel->setRelative(true);
    panel->field(0, 1)->setValue(0.1);
    EXPECT_EQ(panel->field(0, 1)->value(), 0.0) << "an offset is applied once";
    EXPECT_NEAR(worldPosition(w, elbow).y, elbowAt.y + 0.1, 1e-6);
    EXPECT_NEAR(worldPosition(w, knee).y, kneeAt.y + 0.1, 1e-6);
    EXPECT_EQ(w.session().history().index(), steps + 1);
    EXPECT_EQ(w.session().history().undoText(), "Move 2 guide joints");
}

TEST(NewUser, AxesToggleDrawsEveryGuideJointsAxes)
{
    Editor e;
    app::MainWindow& w = e.window;
    QAction* axes = w.action("display:axes");
    ASSERT_NE(axes, nullptr);
    axes->setChecked(false);
    EXPECT_TRUE(w.viewportWidget()->scene().axes.empty());
    axes->setChecked(true);
    std::size_t joints = 0;
    for (const auto& instance : w.session().document().instances())
        joints += instance.joints.size();
    EXPECT_EQ(w.viewportWidget()->scene().axes.size(), 3 * joints);
    w.grab().save(QString::fromStdString(outputPath("guide-axes.png")));
    axes->setChecked(false);
}

TEST(NewUser, FramingFillsTheViewWithoutCuttingTheSubject)
{
    Editor e;
    app::MainWindow& w = e.window;
    viewport::ViewportWidget* view = w.viewportWidget();
    for (const QSize size : {QSize(900, 500), QSize(300, 700)}) { // wide, then narrow
        view->setFixedSize(size);
        QApplication::processEvents();
        view->frameAll();
        QRect seen;
        for (const auto& j : view->scene().guideJoints)
            seen |= QRect(view->toWidgetPixels(j.position), QSize(1, 1));
        EXPECT_TRUE(view->rect().contains(seen)) << "cut: " << seen.x() << "," << seen.y() << " " << seen.width() << "x" << seen.height();
        EXPECT_TRUE(seen.height() > 0.7 * view->height() || seen.width() > 0.7 * view->width())
            << "small: " << seen.width() << "x" << seen.height() << " in " << view->width() << "x" << view->height();
    }
    view->setMinimumSize(320, 240);
    view->setMaximumSize(QWIDGETSIZE_MAX, QWIDGETSIZE_MAX);
}

TEST(NewUser, DisplayMenuHidesLayersAndAStaleRigIsNotDrawnOverTheGuide)
{
    Editor e;
    app::MainWindow& w = e.window;
    w.action("build")->trigger();
    w.action("modeGuide")->trigger();
    const auto& scene = [&]() -> const viewport::Scene& { return w.viewportWidget()->scene(); };
    EXPECT_FALSE(scene().curves.empty());
    w.action("display:shapes")->setChecked(false);
    EXPECT_TRUE(scene().curves.empty());
    w.action("display:shapes")->setChecked(true);
    w.action("display:guides")->setChecked(false);
    EXPECT_TRUE(scene().guideJoints.empty());
    w.action("display:guides")->setChecked(true);
    w.action("display:labels")->setChecked(true);
    EXPECT_FALSE(scene().labels.empty());
    w.grab().save(QString::fromStdString(outputPath("guide-labels.png")));
    w.action("display:labels")->setChecked(false);
    EXPECT_TRUE(app::settings::isDisplayed("guides", false)) << "kept in the settings";

    w.session().setLiveRebuild(false);
    ASSERT_TRUE(w.session().moveGuideJoints(jointOf(w, "arm", 2), translationMatrix(Vec3(2.0, 1.0, 0.0)), "Move").ok());
    ASSERT_TRUE(w.session().isRigStale());
    EXPECT_TRUE(scene().curves.empty()) << "the out-of-date rig is not drawn where the guide no longer is";
    w.session().setLiveRebuild(true);
    EXPECT_FALSE(scene().curves.empty());
}

TEST(NewUser, EditMenuSelectsAllAndHierarchiesAndDeletes)
{
    Editor e;
    app::MainWindow& w = e.window;
    const model::GuideDocument& doc = w.session().document();
    std::size_t joints = 0;
    for (const auto& instance : doc.instances())
        joints += instance.joints.size();
    w.action("selectAll")->trigger();
    EXPECT_EQ(w.session().selection().joints.size(), joints);

    const model::InstanceId arm = doc.instanceNamed("arm")->id;
    w.session().select(app::Selection::ofInstance(arm));
    w.action("selectHierarchy")->trigger();
    std::size_t below = 0;
    for (model::InstanceId id : doc.subtree(arm))
        below += doc.instance(id)->joints.size();
    EXPECT_GT(doc.subtree(arm).size(), 1u) << "the fingers hang below the arm";
    EXPECT_EQ(w.session().selection().joints.size(), below);

    const std::size_t instances = doc.instances().size();
    w.session().select(app::Selection::ofInstance(arm));
    w.action("delete")->trigger();
    EXPECT_EQ(doc.instanceNamed("arm"), nullptr);
    EXPECT_LT(doc.instances().size(), instances);
    w.action("undo")->trigger();
    EXPECT_EQ(w.session().document().instances().size(), instances);

    w.action("closeGuide")->trigger();
    EXPECT_TRUE(w.session().document().instances().empty());
    EXPECT_TRUE(w.session().filePath().isEmpty());
}

TEST(NewUser, HelpAndWindowMenusWithoutBlockingPrompts)
{
    Editor e;
    app::MainWindow& w = e.window;
    w.session().select(app::Selection::ofInstance(w.session().instanceNamed("arm")));
    w.action("helpTemplate")->trigger();
    auto* help = w.findChild<QDialog*>("helpDialog");
    ASSERT_NE(help, nullptr);
    EXPECT_TRUE(help->isVisible());
    EXPECT_FALSE(help->isModal());
    const QString text = help->findChild<QTextBrowser*>("helpText")->toPlainText();
    EXPECT_TRUE(text.contains("arm.limb")) << text.toStdString();
    EXPECT_TRUE(text.contains("ik_space"));
    help->grab().save(QString::fromStdString(outputPath("help-template.png")));
    w.action("helpReadme")->trigger();
    EXPECT_TRUE(help->findChild<QTextBrowser*>("helpText")->toPlainText().contains("Rigsmith"));
    w.action("helpAbout")->trigger();
    EXPECT_TRUE(help->windowTitle().contains("About"));
    help->close();

    auto* options = w.findChild<QDockWidget*>("optionsDock");
    options->close();
    EXPECT_FALSE(options->isVisible());
    QAction* restore = w.action("window:optionsDock");
    ASSERT_NE(restore, nullptr);
    restore->trigger();
    EXPECT_TRUE(options->isVisible()) << "the Window menu brings a closed dock back";
}

TEST(NewUser, NavigationPreferenceOrbitsWithTheMiddleButtonOrTheTouchpad)
{
    Editor e;
    app::MainWindow& w = e.window;
    viewport::ViewportWidget* view = w.viewportWidget();
    const QPoint from = view->rect().center(), to = from + QPoint(60, 0);
    auto middleDrag = [&] {
        QTest::mousePress(view, Qt::MiddleButton, {}, from);
        QMouseEvent move(QEvent::MouseMove, QPointF(to), view->mapToGlobal(QPointF(to)), Qt::NoButton, Qt::MiddleButton, {});
        QApplication::sendEvent(view, &move);
        QTest::mouseRelease(view, Qt::MiddleButton, {}, to);
    };
    w.action("navigation:maya")->trigger();
    double yaw = view->camera().yaw;
    middleDrag();
    EXPECT_EQ(view->camera().yaw, yaw) << "Maya: middle drag pans";

    w.action("navigation:blender")->trigger();
    EXPECT_EQ(app::settings::navigation(), "blender") << "kept in the settings";
    middleDrag();
    EXPECT_NE(view->camera().yaw, yaw) << "Blender: middle drag orbits";

    w.action("navigation:touchpad")->trigger();
    yaw = view->camera().yaw;
    const double distance = view->camera().distance;
    QWheelEvent scroll(QPointF(from), view->mapToGlobal(QPointF(from)), QPoint(40, 0), QPoint(320, 0), Qt::NoButton,
                       Qt::NoModifier, Qt::ScrollUpdate, false);
    QApplication::sendEvent(view, &scroll);
    EXPECT_NE(view->camera().yaw, yaw) << "a two-finger scroll orbits";
    EXPECT_EQ(view->camera().distance, distance);
    w.action("navigation:maya")->trigger();
}

TEST(NewUser, StatusBarDoesNotKeepABuildStageAfterTheBuild)
{
    Editor e;
    app::MainWindow& w = e.window;
    w.buildRig();
    QTest::qWait(150); // a stage is painted once a build has run 100 ms
    emit w.session().buildProgressed(0.3, "configure");
    EXPECT_TRUE(w.statusBar()->currentMessage().startsWith("Building: configure"));
    emit w.session().buildProgressed(1.0, "done");
    EXPECT_FALSE(w.statusBar()->currentMessage().startsWith("Building")) << w.statusBar()->currentMessage().toStdString();
}

TEST(NewUser, EditMenuSelectsAControllerGroupWithItsSubgroups)
{
    Editor e;
    app::MainWindow& w = e.window;
    auto* menu = w.findChild<QMenu*>("controllerGroupMenu");
    ASSERT_NE(menu, nullptr);
    w.buildRig();
    QMetaObject::invokeMethod(menu, "aboutToShow"); // what opening the menu does
    auto* armGroup = menu->findChild<QAction*>("controllerGroup:arm.L");
    ASSERT_NE(armGroup, nullptr) << "every instance copy has its group";
    armGroup->trigger();
    EXPECT_EQ(w.session().mode(), app::EditorMode::Rig);
    const model::Rig& rig = *w.session().rig();
    std::set<std::string> selected;
    for (auto n : w.session().selection().nodes)
        selected.insert(rig.nodes[n].path);
    EXPECT_TRUE(selected.count("arm.L::ctrls.ik"));
    EXPECT_TRUE(selected.count("index.L::ctrls.fk.0")) << "the hand's and fingers' groups nest in the arm's";
    EXPECT_FALSE(selected.count("arm.R::ctrls.ik"));
    EXPECT_FALSE(selected.count("spine::ctrls.cog"));
}
