// Guide authoring in the viewport with the real widgets: picking and box
// selection, the W/E/R gizmo on guide joints, views and framing, the
// see-through character model.
#include "EditorTestSupport.h"

#include "LogPanel.h"
#include "edit/GuideEdits.h"
#include "ViewportWidget.h"

#include <QAction>
#include <QApplication>
#include <QSignalSpy>

#include <fstream>
#include <iterator>
#include <glm/gtc/matrix_transform.hpp>

using namespace rs;
using namespace rs::test;

namespace {

Vec3 worldOf(app::MainWindow& w, model::JointId joint)
{
    return translationOf(w.session().document().jointWorldMatrix(joint));
}

} // namespace

TEST(GuideAuthoring, ClickingAGuideJointAndDraggingTheGizmoIsOneUndoStep)
{
    Editor editor;
    app::MainWindow& w = editor.window;
    viewport::ViewportWidget* view = w.viewportWidget();
    const model::GuideDocument original = w.session().document();
    const auto& arm = w.session().document().instanceNamed("arm")->joints;
    const model::JointId elbow = arm[2].id, hand = arm[3].id;
    const Vec3 elbowBefore = worldOf(w, elbow), handBefore = worldOf(w, hand);

    QTest::keyClick(view, Qt::Key_1); // front view: the arm's joints spread out on screen
    EXPECT_TRUE(view->camera().orthographic);
    EXPECT_TRUE(w.action("viewFront")->isChecked());
    QTest::mouseClick(view, Qt::LeftButton, {}, view->toWidgetPixels(elbowBefore));
    ASSERT_EQ(w.session().selection().joint, elbow);
    EXPECT_EQ(w.session().selection().instance, w.session().document().instanceNamed("arm")->id);
    QTest::keyClick(view, Qt::Key_W);
    ASSERT_TRUE(view->gizmo().has_value());
    EXPECT_LT(glm::length(view->gizmo()->origin() - elbowBefore), 1e-9);
    view->setGizmoWorldSpace(true);
    ASSERT_TRUE(dragGizmoHandle(view, 1)); // up along world Y

    const Vec3 moved = worldOf(w, elbow) - elbowBefore;
    EXPECT_GT(moved.y, 0.05);
    EXPECT_LT(std::abs(moved.x) + std::abs(moved.z), 1e-6) << "only along the dragged handle";
    EXPECT_LT(glm::length(worldOf(w, hand) - handBefore - moved), 1e-9) << "the hand follows its parent";
    EXPECT_EQ(w.session().history().size(), 1u) << "the whole drag is one step";
    EXPECT_EQ(w.session().history().undoText(), "Move guide joint of arm");
    EXPECT_TRUE(w.session().isRigStale() || !w.session().rig());
    w.grab().save(QString::fromStdString(outputPath("guide-gizmo-front.png")));

    w.action("undo")->trigger();
    EXPECT_TRUE(w.session().document() == original);

    // Snapping: the joint lands on the 5 cm grid.
    w.action("snapGrid")->trigger();
    ASSERT_TRUE(dragGizmoHandle(view, 0));
    const Vec3 snapped = worldOf(w, elbow);
    EXPECT_NEAR(snapped.x / 0.05, std::round(snapped.x / 0.05), 1e-6);
    EXPECT_NEAR(snapped.y / 0.05, std::round(snapped.y / 0.05), 1e-6);
    w.action("undo")->trigger();
    EXPECT_TRUE(w.session().document() == original);
}

TEST(GuideAuthoring, BoxSelectingFramesAndMovesSeveralJointsTogether)
{
    Editor editor;
    app::MainWindow& w = editor.window;
    viewport::ViewportWidget* view = w.viewportWidget();
    const model::GuideDocument original = w.session().document();
    QTest::keyClick(view, Qt::Key_1);
    const auto* leg = w.session().document().instanceNamed("leg");
    // A box around the knee and the ankle (front view: they line up below the hip).
    const QPoint knee = view->toWidgetPixels(worldOf(w, leg->joints[2].id));
    const QPoint ankle = view->toWidgetPixels(worldOf(w, leg->joints[3].id));
    const QPoint a(std::min(knee.x(), ankle.x()) - 6, knee.y() - 6), b(std::max(knee.x(), ankle.x()) + 6, ankle.y() + 6);
    QTest::mousePress(view, Qt::LeftButton, {}, a);
    QTest::mouseMove(view, (a + b) / 2);
    QTest::mouseMove(view, b);
    QTest::mouseRelease(view, Qt::LeftButton, {}, b);
    const auto& selected = w.session().selection().joints;
    ASSERT_GE(selected.size(), 2u);
    for (model::JointId j : selected)
        EXPECT_EQ(w.session().document().ownerOf(j)->id, leg->id);

    QTest::keyClick(view, Qt::Key_F);
    const Vec3 middle = (worldOf(w, leg->joints[2].id) + worldOf(w, leg->joints[3].id)) * 0.5;
    EXPECT_LT(glm::length(view->camera().target - middle), 0.2) << "framed on the selection";
    QTest::keyClick(view, Qt::Key_W);
    view->setGizmoWorldSpace(true);
    const Vec3 kneeBefore = worldOf(w, leg->joints[2].id);
    ASSERT_TRUE(dragGizmoHandle(view, 0));
    const Vec3 kneeMoved = worldOf(w, leg->joints[2].id) - kneeBefore;
    EXPECT_GT(glm::length(kneeMoved), 0.01) << "every selected joint moved";
    EXPECT_EQ(w.session().history().size(), 1u);
    w.action("undo")->trigger();
    EXPECT_TRUE(w.session().document() == original);

    // Orbiting (Alt+drag) leaves the orthographic view.
    const QPoint c(view->width() / 2, view->height() / 2);
    QTest::mousePress(view, Qt::LeftButton, Qt::AltModifier, c);
    QTest::mouseMove(view, c + QPoint(30, 0));
    QTest::mouseMove(view, c + QPoint(60, 0));
    QTest::mouseRelease(view, Qt::LeftButton, Qt::AltModifier, c + QPoint(60, 0));
    EXPECT_FALSE(view->camera().orthographic);
    EXPECT_TRUE(w.action("viewPerspective")->isChecked());
}

TEST(GuideAuthoring, AModelIsShownSeeThroughUntilBoundAndABadOneIsReported)
{
    Editor editor;
    app::MainWindow& w = editor.window;
    // A character to place guides on: the biped's own proxy mesh exported as glTF.
    w.buildRig();
    io::ExportRequest request;
    request.path = outputPath("reference.glb");
    request.proxyVertices = 6000;
    ASSERT_TRUE(w.exportRig(request));
    w.session().setMode(app::EditorMode::Guide);
    ASSERT_TRUE(w.addModel(QString::fromStdString(request.path)));
    auto* view = w.viewportWidget();
    ASSERT_EQ(view->scene().meshes.size(), 1u);
    EXPECT_FALSE(view->scene().meshes[0].skinned) << "see-through until bound";
    const std::size_t modelVertices = view->scene().meshes[0].data().vertexCount();
    EXPECT_GT(modelVertices, 3000u);
    QTest::keyClick(view, Qt::Key_1);
    view->frameAll();
    QApplication::processEvents();
    w.grab().save(QString::fromStdString(outputPath("reference-model.png")));

    // Persistent GPU buffers: a repaint that only moves the camera sends no
    // scene vertices, and a guide edit sends the guide but not the model again.
    auto repaint = [&] {
        QSignalSpy swapped(view, &viewport::ViewportWidget::frameSwapped);
        view->update();
        return swapped.wait(2000);
    };
    ASSERT_TRUE(repaint());
    std::uint64_t before = view->verticesUploaded();
    std::uint64_t meshBefore = view->meshVerticesUploaded();
    ASSERT_TRUE(repaint());
    EXPECT_LT(view->verticesUploaded() - before, 500u) << "only the gizmo";
    const model::JointId neck = w.session().document().instanceNamed("neck")->joints[1].id;
    Transform moved = w.session().document().joint(neck)->local;
    moved.translate.x += 0.01;
    before = view->verticesUploaded();
    ASSERT_TRUE(edit::setJointTransform(w.session().history(), neck, moved).ok());
    ASSERT_TRUE(repaint());
    EXPECT_GT(view->verticesUploaded() - before, 10u) << "the moved guide is sent";
    EXPECT_EQ(view->meshVerticesUploaded(), meshBefore) << "the model is not sent again";
    w.action("undo")->trigger();

    const std::string broken = outputPath("broken.obj");
    std::ofstream(broken) << "this is not a model\n";
    const int messages = w.log()->count();
    EXPECT_FALSE(w.addModel(QString::fromStdString(broken)));
    EXPECT_GT(w.log()->count(), messages);
    EXPECT_TRUE(w.log()->item(w.log()->count() - 1)->text().contains("broken.obj"));
    EXPECT_EQ(view->scene().meshes.size(), 1u) << "the shown model stays";
    EXPECT_EQ(w.session().document().models, std::vector<std::string>{request.path}) << "and the guide keeps the good one";

    // The guide remembers its model (relative to the guide file): reopened, it shows again.
    EXPECT_EQ(w.session().history().undoText(), "Add model reference.glb");
    const QString saved = QString::fromStdString(outputPath("with-reference.yml"));
    Diagnostics diagnostics;
    ASSERT_TRUE(w.session().save(saved, diagnostics)) << formatAll(diagnostics);
    std::ifstream in(saved.toStdString());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("\nmodels:\n  - reference.glb\n"), std::string::npos) << text;
    {
        Editor second;
        ASSERT_TRUE(second.window.openFile(saved));
        ASSERT_EQ(second.window.viewportWidget()->scene().meshes.size(), 1u);
        EXPECT_EQ(second.window.viewportWidget()->scene().meshes[0].data().vertexCount(), modelVertices);
    }

    w.action("undo")->trigger();
    EXPECT_TRUE(view->scene().meshes.empty());
    EXPECT_TRUE(w.session().document().models.empty());
    w.action("redo")->trigger();
    EXPECT_EQ(view->scene().meshes.size(), 1u) << "redoing the add shows it again";
}

TEST(GuideAuthoring, TheGizmoEditsASelectedControllersShapeInGuideMode)
{
    Editor editor;
    app::MainWindow& w = editor.window;
    const model::GuideDocument original = w.session().document();
    w.buildRig();
    w.session().setMode(app::EditorMode::Guide);
    const model::Rig* rig = w.session().rig();
    const auto ik = rig->findPath("arm.L::ctrls.ik");
    ASSERT_TRUE(ik.has_value());
    w.session().selectControllers({*ik}, false);
    viewport::ViewportWidget* view = w.viewportWidget();
    QTest::keyClick(view, Qt::Key_W);
    view->setGizmoWorldSpace(true);
    ASSERT_TRUE(view->gizmo().has_value());
    EXPECT_LT(maxAbsDifference(view->gizmo()->target, rig->nodes[*ik].worldMatrix), 1e-9) << "on the shape, in the controller's frame";
    const Vec3 rightBefore = translationOf(w.session().rig()->nodes[*w.session().rig()->findPath("arm.R::ctrls.ik")].worldMatrix *
                                           glm::translate(glm::dmat4(1.0), w.session().rig()->nodes[*w.session().rig()->findPath("arm.R::ctrls.ik")].curves.front().points[0]));
    ASSERT_TRUE(dragGizmoHandle(view, 1));

    const auto* arm = w.session().document().instanceNamed("arm");
    const auto& overrides = w.session().document().overrides;
    const auto record = overrides.find(NodeKey{arm->id, {}, "ctrls.ik"}); // the authored side: both copies show it
    ASSERT_TRUE(record != overrides.end() && record->second.shape);
    const Transform& moved = record->second.shape->edit.transform;
    EXPECT_GT(moved.translate.y + moved.translate.z, 0.0) << "moved up in the world";
    EXPECT_EQ(w.session().history().size(), 1u);
    EXPECT_EQ(w.session().history().undoText(), "Edit shape ctrls.ik of arm");
    EXPECT_FALSE(w.session().isRigStale()) << "rebuilt at once";
    EXPECT_EQ(w.session().mode(), app::EditorMode::Guide);
    const auto& right = w.session().rig()->nodes[*w.session().rig()->findPath("arm.R::ctrls.ik")];
    const Vec3 rightAfter = translationOf(right.worldMatrix * glm::translate(glm::dmat4(1.0), right.curves.front().points[0]));
    EXPECT_GT(rightAfter.y - rightBefore.y, 0.01) << "the mirrored side follows";
    w.grab().save(QString::fromStdString(outputPath("shape-edit.png")));
    w.action("undo")->trigger();
    EXPECT_TRUE(w.session().document() == original);
}

TEST(GuideAuthoring, TheGizmoOnAMirroredCopysShapeEditsTheAuthoredSideReflected)
{
    Editor editor;
    app::MainWindow& w = editor.window;
    w.buildRig();
    w.session().setMode(app::EditorMode::Guide);
    auto worldPoint = [&](const std::string& id) {
        const model::RigNode& n = w.session().rig()->nodes[*w.session().rig()->findPath(id)];
        return Vec3(n.worldMatrix * Vec4(n.curves.front().points[0], 1.0));
    };
    const Vec3 left0 = worldPoint("arm.L::ctrls.ik"), right0 = worldPoint("arm.R::ctrls.ik");
    w.session().selectControllers({*w.session().rig()->findPath("arm.R::ctrls.ik")}, false);
    viewport::ViewportWidget* view = w.viewportWidget();
    QTest::keyClick(view, Qt::Key_W);
    view->setGizmoWorldSpace(true);
    ASSERT_TRUE(dragGizmoHandle(view, 0)) << "world X on the right side";
    EXPECT_EQ(w.session().history().undoText(), "Edit shape ctrls.ik of arm");
    const Vec3 left1 = worldPoint("arm.L::ctrls.ik"), right1 = worldPoint("arm.R::ctrls.ik");
    const Vec3 moved = right1 - right0;
    EXPECT_GT(std::abs(moved.x), 0.01);
    EXPECT_LT(std::abs(moved.y) + std::abs(moved.z), 1e-6) << "the dragged shape moved along world X only";
    EXPECT_LT(glm::length((left1 - left0) - Vec3(-moved.x, moved.y, moved.z)), 1e-6) << "the authored side moved mirrored";
}
