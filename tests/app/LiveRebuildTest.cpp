// Live rebuild in the real editor: a guide joint gizmo drag, an Options dock
// spinner and a shape CV drag rebuild the rig and redraw it while the mouse
// button is still down, before the edit is committed.
#include "EditorTestSupport.h"

#include "OptionsEditor.h"
#include "ViewportWidget.h"

#include <QAbstractSpinBox>
#include <QDoubleSpinBox>
#include <QApplication>
#include <QStyle>
#include <QStyleOptionSpinBox>

#include <cstdio>

using namespace rs;
using namespace rs::test;

namespace {

// Presses a gizmo handle and moves along it, leaving the button down.
bool pressAndDragGizmo(viewport::ViewportWidget* view, int axis, QPoint& further)
{
    const auto gizmo = view->gizmo();
    if (!gizmo)
        return false;
    const QPoint handle = view->toWidgetPixels(gizmo->origin() + gizmo->axis(axis) * gizmo->size * 0.6);
    further = view->toWidgetPixels(gizmo->origin() + gizmo->axis(axis) * gizmo->size * 1.6);
    QTest::mousePress(view, Qt::LeftButton, {}, handle);
    QTest::mouseMove(view, (handle + further) / 2);
    QTest::mouseMove(view, further);
    QApplication::processEvents();
    return true;
}

Vec3 nodeWorld(app::MainWindow& w, const NodeKey& key)
{
    const model::Rig& rig = *w.session().rig();
    return translationOf(rig.nodes[*rig.find(key)].worldMatrix);
}

} // namespace

TEST(LiveRebuild, AGuideJointDragMovesTheBuiltRigBeforeTheMouseIsReleased)
{
    Editor editor;
    app::MainWindow& w = editor.window;
    viewport::ViewportWidget* view = w.viewportWidget();
    w.buildRig();
    w.session().setMode(app::EditorMode::Guide); // the guide, with the built rig drawn over it
    QApplication::processEvents();
    const model::TemplateInstance& arm = *w.session().document().instanceNamed("arm");
    const NodeKey ikElbow{arm.id, "L", "ik.1"};
    const Vec3 before = nodeWorld(w, ikElbow);
    QTest::keyClick(view, Qt::Key_1); // front view
    QTest::mouseClick(view, Qt::LeftButton, {}, view->toWidgetPixels(translationOf(w.session().document().jointWorldMatrix(arm.joints[2].id))));
    ASSERT_EQ(w.session().selection().joint, arm.joints[2].id);
    QTest::keyClick(view, Qt::Key_W);
    view->setGizmoWorldSpace(true);
    // What a full upload sends: a display toggle redraws everything.
    std::uint64_t beforeFull = view->sceneVerticesUploaded();
    w.action("display:axes")->trigger();
    QTest::qWaitFor([&] { return view->sceneVerticesUploaded() > beforeFull; }, 3000);
    beforeFull = view->sceneVerticesUploaded();
    w.action("display:axes")->trigger();
    QTest::qWaitFor([&] { return view->sceneVerticesUploaded() > beforeFull; }, 3000);
    const std::uint64_t full = view->sceneVerticesUploaded() - beforeFull;
    ASSERT_GT(full, 1000u);
    const std::uint64_t sent = view->sceneVerticesUploaded();
    QPoint at;
    ASSERT_TRUE(pressAndDragGizmo(view, 1, at));
    QTest::qWaitFor([&] { return view->sceneVerticesUploaded() > sent; }, 3000); // the next frame
    std::printf("scene vertices: a full upload %llu, the drag's frames %llu\n", (unsigned long long)full,
                (unsigned long long)(view->sceneVerticesUploaded() - sent));
    EXPECT_LT(view->sceneVerticesUploaded() - sent, full) << "the drag's frames send the arm and what hangs from it, not the scene";
    EXPECT_FALSE(w.session().isRigStale());
    EXPECT_GT(nodeWorld(w, ikElbow).y - before.y, 0.02) << "the built elbow follows the dragged guide joint, button still down";
    EXPECT_EQ(w.session().history().size(), 0u) << "nothing committed yet";
    EXPECT_GT(view->sceneVerticesUploaded(), sent) << "and the viewport drew it";
    QTest::mouseRelease(view, Qt::LeftButton, {}, at);
    EXPECT_EQ(w.session().history().size(), 1u);
}

TEST(LiveRebuild, AnOptionsSpinnerChangesTheBuiltRigWhileItsArrowIsHeld)
{
    Editor editor;
    app::MainWindow& w = editor.window;
    w.buildRig();
    const auto arm = w.session().instanceNamed("arm");
    w.session().select(app::Selection::ofInstance(arm));
    QApplication::processEvents();
    QWidget* editorOf = w.optionsEditor()->editorFor("ik_blend");
    ASSERT_NE(editorOf, nullptr);
    auto* spinner = editorOf->findChild<QDoubleSpinBox*>(); // beside it a slider, applied on release
    ASSERT_NE(spinner, nullptr);
    ASSERT_TRUE(spinner->isVisible());
    const NodeKey switchKey{arm, "L", "ctrls.switch"};
    auto blend = [&] {
        const model::Rig& rig = *w.session().rig();
        return rig.nodes[*rig.find(switchKey)].attribute("ik_blend")->value;
    };
    EXPECT_DOUBLE_EQ(blend(), 1.0);
    QStyleOptionSpinBox option;
    option.initFrom(spinner);
    option.rect = spinner->rect();
    option.subControls = QStyle::SC_SpinBoxUp | QStyle::SC_SpinBoxDown | QStyle::SC_SpinBoxFrame | QStyle::SC_SpinBoxEditField;
    option.buttonSymbols = spinner->buttonSymbols();
    option.stepEnabled = QAbstractSpinBox::StepUpEnabled | QAbstractSpinBox::StepDownEnabled;
    const QPoint down = spinner->style()->subControlRect(QStyle::CC_SpinBox, &option, QStyle::SC_SpinBoxDown, spinner).center();
    QTest::mousePress(spinner, Qt::LeftButton, {}, down);
    QApplication::processEvents();
    EXPECT_LT(blend(), 1.0) << "the rig is rebuilt with the new default while the arrow is held";
    EXPECT_FALSE(w.session().isRigStale());
    QTest::mouseRelease(spinner, Qt::LeftButton, {}, down);
}

TEST(LiveRebuild, AShapeCvDragMovesTheBuiltControllersCurveBeforeTheMouseIsReleased)
{
    Editor editor;
    app::MainWindow& w = editor.window;
    viewport::ViewportWidget* view = w.viewportWidget();
    w.buildRig();
    w.session().setMode(app::EditorMode::Guide);
    const auto arm = w.session().instanceNamed("arm");
    const model::RigNodeIndex ik = *w.session().rig()->find({arm, "L", "ctrls.ik"});
    w.session().selectControllers({ik}, false);
    QApplication::processEvents();
    view->frameSelection();
    w.action("cvMode")->trigger();
    ASSERT_TRUE(w.session().isCvMode());
    w.session().selectCvs({{ik, 0, 0}}, false);
    QApplication::processEvents();
    view->setGizmoWorldSpace(true);
    QTest::keyClick(view, Qt::Key_W);
    auto cv = [&] {
        const model::Rig& rig = *w.session().rig();
        const model::RigNode& node = rig.nodes[*rig.find({arm, "L", "ctrls.ik"})];
        return Vec3(node.worldMatrix * glm::dvec4(node.curves[0].cvs[0], 1.0));
    };
    const Vec3 before = cv();
    QPoint at;
    ASSERT_TRUE(pressAndDragGizmo(view, 1, at));
    EXPECT_GT(cv().y - before.y, 0.01) << "the built controller's CV follows, button still down";
    EXPECT_FALSE(w.session().isRigStale());
    EXPECT_EQ(w.session().history().size(), 0u) << "nothing committed yet";
    QTest::mouseRelease(view, Qt::LeftButton, {}, at);
    EXPECT_EQ(w.session().history().size(), 1u);
}
