// Rig mode, driven through the real widgets: Build switches to it, a click on a
// controller's curve selects it, the channel box edits it, the W gizmo drags
// it, the arrow keys pickwalk, pose tools run from the menu and the channel box's
// context menu (FK/IK match), and undo takes
// every pose change back.
#include "EditorTestSupport.h"

#include "ChannelBox.h"
#include "ViewportWidget.h"

#include <QAction>
#include <QApplication>
#include <QDoubleSpinBox>

#include <algorithm>

using namespace rs;
using namespace rs::test;

namespace {

model::RigNodeIndex nodeId(app::MainWindow& w, const std::string& id)
{
    auto found = w.session().rig()->findPath(id);
    EXPECT_TRUE(found.has_value()) << id;
    return found.value_or(0);
}

// Clicks points of the controller's curves until the click selects it.
bool clickController(app::MainWindow& w, model::RigNodeIndex node)
{
    viewport::ViewportWidget* view = w.viewportWidget();
    for (const auto& curve : view->scene().curves) {
        if (curve.node != node)
            continue;
        for (std::size_t i = 0; i < curve.points.size(); i += 3) {
            QTest::mouseClick(view, Qt::LeftButton, {}, view->toWidgetPixels(curve.points[i]));
            if (w.session().selection().node == node)
                return true;
        }
    }
    return false;
}

Vec3 posedPosition(app::MainWindow& w, const std::string& id)
{
    return translationOf(w.session().evaluation()->worldMatrix(nodeId(w, id)));
}

} // namespace

TEST(RigMode, ClickChannelBoxGizmoPickwalkAndUndoBackToTheRestPose)
{
    Editor e;
    app::MainWindow& w = e.window;
    w.action("build")->trigger();
    ASSERT_EQ(w.session().mode(), app::EditorMode::Rig);
    EXPECT_TRUE(w.action("modeRig")->isChecked());
    EXPECT_TRUE(w.viewportWidget()->isRigMode());
    const std::size_t undoStart = w.session().history().index();
    const Vec3 restHand = posedPosition(w, "arm.L::skin.limb.2");

    // The arm is in IK by default, where its FK controls are hidden: switch it
    // half-way to FK through its switch control's channel, so both FK and IK show.
    const auto elbow = nodeId(w, "arm.L::ctrls.fk.1");
    EXPECT_FALSE(w.session().evaluation()->isVisible(elbow));
    const auto settings = nodeId(w, "arm.L::ctrls.switch");
    const int blend = *w.session().program()->channels().find(settings, "ik_blend");
    ASSERT_TRUE(w.session().setChannel(blend, 0.5, true).ok());
    // Click the left arm's FK elbow control: selected, its channels in the channel box.
    ASSERT_TRUE(clickController(w, elbow));
    const int rz = *w.session().program()->channels().find(elbow, "rz");
    auto* spin = qobject_cast<QDoubleSpinBox*>(w.channelBox()->editorFor(rz));
    ASSERT_NE(spin, nullptr);
    spin->setValue(45.0); // as if typed and confirmed
    EXPECT_EQ(w.session().history().undoText(), "Set c_arm2_L.rz");
    EXPECT_GT(glm::length(posedPosition(w, "arm.L::skin.limb.2") - restHand), 0.05); // the hand followed
    QApplication::processEvents(); // rows added to a visible box show on the next event loop turn
    w.grab().save(QString::fromStdString(outputPath("rig-mode-channel-box.png")));

    // W gizmo: drag the X handle; one undo step named after the control.
    QTest::keyClick(w.viewportWidget(), Qt::Key_W);
    const auto ik = nodeId(w, "arm.L::ctrls.ik");
    ASSERT_TRUE(clickController(w, ik));
    const auto gizmo = w.viewportWidget()->gizmo();
    ASSERT_TRUE(gizmo.has_value());
    const Vec3 before = posedPosition(w, "arm.L::ctrls.ik");
    ASSERT_TRUE(test::dragGizmoHandle(w.viewportWidget(), 0));
    const Vec3 moved = posedPosition(w, "arm.L::ctrls.ik") - before;
    EXPECT_GT(glm::dot(moved, gizmo->axis(0)), gizmo->size * 0.5); // moved along its X handle
    EXPECT_LT(glm::length(moved - gizmo->axis(0) * glm::dot(moved, gizmo->axis(0))), 1e-6);
    EXPECT_EQ(w.session().history().undoText(), "Move c_arm_ik_L");

    // Pickwalk with the arrow keys, and M to the twin.
    QTest::keyClick(w.viewportWidget(), Qt::Key_M);
    EXPECT_EQ(w.session().rig()->nodes[w.session().selection().node].path, "arm.R::ctrls.ik");
    ASSERT_TRUE(clickController(w, elbow));
    QTest::keyClick(w.viewportWidget(), Qt::Key_Up);
    EXPECT_EQ(w.session().rig()->nodes[w.session().selection().node].path, "arm.L::ctrls.fk.0");
    QTest::keyClick(w.viewportWidget(), Qt::Key_Down);
    EXPECT_EQ(w.session().selection().node, elbow);

    // Mirror the left arm onto the right from the Pose menu, in FK (the IK
    // control moved above is not among what is mirrored).
    ASSERT_TRUE(w.session().setChannel(blend, 0.0, false).ok());
    w.session().selectControllers({elbow, settings}, false);
    w.action("mirrorPose")->trigger();
    EXPECT_EQ(w.session().history().undoText(), "Mirror pose");
    const Vec3 left = posedPosition(w, "arm.L::skin.limb.2"), right = posedPosition(w, "arm.R::skin.limb.2");
    EXPECT_NEAR(right.x, -left.x, 1e-6);
    EXPECT_NEAR(right.y, left.y, 1e-6);

    // Rebuilding keeps the pose and the selection; undo takes everything back.
    w.action("build")->trigger();
    EXPECT_EQ(w.session().selection().nodes, (std::vector<model::RigNodeIndex>{elbow, settings}));
    EXPECT_NEAR(posedPosition(w, "arm.R::skin.limb.2").y, left.y, 1e-6);

    // Right-click in the channel box: match IK to the FK arm, one undo step, the hand stays.
    const auto menu = w.channelBox()->actions();
    EXPECT_NE(std::find(menu.begin(), menu.end(), w.action("fkToIk")), menu.end());
    EXPECT_NE(std::find(menu.begin(), menu.end(), w.action("ikToFk")), menu.end());
    EXPECT_EQ(w.channelBox()->contextMenuPolicy(), Qt::ActionsContextMenu);
    const Vec3 hand = posedPosition(w, "arm.L::skin.limb.2");
    w.session().selectControllers({elbow}, false);
    w.action("fkToIk")->trigger();
    EXPECT_EQ(w.session().history().undoText(), "Match IK to FK");
    EXPECT_LT(glm::length(posedPosition(w, "arm.L::skin.limb.2") - hand), 1e-5);
    EXPECT_TRUE(w.session().evaluation()->isVisible(ik)) << "in IK now: the IK control shows";
    while (w.session().history().index() > undoStart)
        w.action("undo")->trigger();
    EXPECT_TRUE(model::testPose(w.session().document().overrides).empty());
    EXPECT_LT(glm::length(posedPosition(w, "arm.L::skin.limb.2") - restHand), 1e-9);
    EXPECT_FALSE(w.session().isRigStale()); // posing never ages the rig
}

TEST(RigMode, BoxSelectPicksEveryControllerInTheRectangle)
{
    Editor e;
    app::MainWindow& w = e.window;
    w.action("build")->trigger();
    viewport::ViewportWidget* view = w.viewportWidget();
    QTest::mousePress(view, Qt::LeftButton, {}, QPoint(2, 2));
    QTest::mouseMove(view, QPoint(view->width() / 2, view->height() / 2));
    QTest::mouseMove(view, QPoint(view->width() - 2, view->height() - 2));
    QTest::mouseRelease(view, Qt::LeftButton, {}, QPoint(view->width() - 2, view->height() - 2));
    // Every controller the pose shows (the limbs are in IK: their FK controls are hidden).
    std::size_t shown = 0;
    for (model::RigNodeIndex i = 0; i < w.session().rig()->nodes.size(); ++i)
        shown += w.session().rig()->nodes[i].kind == model::RigNodeKind::Controller && w.session().evaluation()->isVisible(i);
    EXPECT_LT(shown, w.session().rig()->count(model::RigNodeKind::Controller));
    EXPECT_EQ(w.session().selection().nodes.size(), shown);
    w.action("resetSelected")->trigger(); // nothing posed: a refused (empty) step is not recorded
    EXPECT_FALSE(w.session().history().canUndo());
}
