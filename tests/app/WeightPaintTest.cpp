// Issue 19 item 5 in the editor: Skin > Paint Weights. Strokes dragged with
// the mouse over a bound mesh in the viewport, the Paint dock's joint list,
// locks, tools and operations, each one undo step.
#include "EditorTestSupport.h"

#include "LogPanel.h"
#include "WeightPaintPanel.h"

#include <QAbstractButton>
#include <QAction>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QListWidgetItem>
#include <QSpinBox>
#include <QTreeWidget>

#include <fstream>

using namespace rs;
using namespace rs::test;

namespace {

// An OBJ of two tubes around the arms, shoulder to wrist: the left one and its
// mirror image across x = 0, as one mesh.
QString writeSleeves(app::MainWindow& w, const std::string& name) { return test::writeSleeve(w, name, 16, 12, true); }

int boneOf(app::MainWindow& w, const std::string& path)
{
    const model::Rig& rig = *w.session().rig();
    const auto node = rig.findPath(path);
    const auto& bones = w.session().skinBones();
    for (std::size_t b = 0; b < bones.size(); ++b)
        if (node && bones[b].node == *node)
            return int(b);
    return -1;
}

const model::MeshWeights& weights(app::MainWindow& w) { return *w.session().characterMeshes().at(0).weights; }

double weightOf(const model::MeshWeights& weights, std::size_t vertex, int bone)
{
    for (const model::Influence* i = weights.begin(vertex); i != weights.end(vertex); ++i)
        if (int(i->joint) == bone)
            return i->weight;
    return 0.0;
}

double largestSumError(const model::MeshWeights& weights)
{
    double worst = 0.0;
    for (std::size_t v = 0; v < weights.vertexCount(); ++v) {
        double sum = 0.0;
        for (const model::Influence* i = weights.begin(v); i != weights.end(v); ++i)
            sum += i->weight;
        worst = std::max(worst, std::abs(sum - 1.0));
    }
    return worst;
}

// The editor in Rig mode with both sleeves bound, in paint mode, the camera
// looking at the left sleeve from the front.
struct PaintEditor : Editor {
    app::MainWindow& w = window;
    viewport::ViewportWidget* view = window.viewportWidget();
    widgets::WeightPaintPanel* panel = window.paintPanel();
    Vec3 shoulder, wrist;

    explicit PaintEditor(const std::string& file)
    {
        EXPECT_TRUE(w.addModel(writeSleeves(w, file)));
        w.bindSkin();
        EXPECT_TRUE(QTest::qWaitFor([&] { return !w.isBinding(); }, 20000));
        EXPECT_EQ(w.session().document().bindings.size(), 1u);
        w.action("modeRig")->trigger();
        const model::Rig& rig = *w.session().rig();
        shoulder = translationOf(rig.nodes[*rig.findPath("arm.L::skin.limb.0")].worldMatrix);
        wrist = translationOf(rig.nodes[*rig.findPath("arm.L::skin.limb.2")].worldMatrix);
        w.action("paintWeights")->trigger();
        view->setView(viewport::CameraView::Front);
        view->camera().target = (shoulder + wrist) * 0.5;
        view->camera().distance = 1.2;
        view->update();
        QTest::qWait(50);
    }
    // Where a point along the left arm, shoulder 0 to wrist 1, is on screen.
    QPoint onArm(double t) const { return view->toWidgetPixels(glm::mix(shoulder, wrist, t)); }
    void chooseJoint(int bone)
    {
        QTreeWidget* list = panel->jointList();
        QTreeWidgetItem* item = list->topLevelItem(bone);
        ASSERT_TRUE(item);
        list->scrollToItem(item);
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, list->visualItemRect(item).center());
    }
    void stroke(double from, double to, Qt::KeyboardModifiers modifiers = {})
    {
        const QPoint a = onArm(from), b = onArm(to);
        QTest::mousePress(view, Qt::LeftButton, modifiers, a);
        for (int i = 1; i <= 8; ++i)
            QTest::mouseMove(view, a + (b - a) * i / 8);
        QTest::mouseRelease(view, Qt::LeftButton, modifiers, b);
    }
};

} // namespace

TEST(WeightPaint, ADragOverTheMeshIsOneUndoStepAddingTheJointsWeight)
{
    PaintEditor e("sleeves-paint.obj");
    app::MainWindow& w = e.w;
    ASSERT_TRUE(w.findChild<QDockWidget*>("paintDock")->isVisible());
    ASSERT_TRUE(e.view->isPaintMode());
    EXPECT_EQ(w.displayOptions().weights, viewport::WeightDisplay::SelectedJoint) << "painting shows the weights";
    const int wristBone = boneOf(w, "arm.L::skin.limb.2");
    ASSERT_GE(wristBone, 0);
    e.chooseJoint(wristBone);
    EXPECT_EQ(w.paintBone(), wristBone);
    EXPECT_EQ(e.view->scene().weightBone, wristBone) << "the heat map shows the painted joint";

    const auto hit = e.view->meshHitAt(e.onArm(0.3));
    ASSERT_TRUE(hit) << "the front of the sleeve is under the upper arm";
    const std::size_t hitVertex = hit->vertex;
    const model::MeshWeights before = weights(w);
    const std::size_t steps = w.session().history().index();
    e.stroke(0.25, 0.4);
    EXPECT_EQ(w.session().history().index(), steps + 1) << "one stroke, one undo step";
    EXPECT_EQ(w.session().history().undoText(), "Add weights of " + w.session().rig()->nodes[w.session().skinBones()[wristBone].node].name);
    const model::MeshWeights& after = weights(w);
    EXPECT_GT(weightOf(after, hitVertex, wristBone), weightOf(before, hitVertex, wristBone) + 0.05);
    EXPECT_LT(largestSumError(after), 1e-4);
    // The right sleeve, far from the brush, is untouched.
    const std::size_t half = after.vertexCount() / 2;
    for (std::size_t v = half; v < after.vertexCount(); ++v)
        ASSERT_EQ(std::vector<model::Influence>(after.begin(v), after.end(v)),
                  std::vector<model::Influence>(before.begin(v), before.end(v))) << v;

    // Ctrl+drag subtracts, as its own step.
    const double painted = weightOf(after, hitVertex, wristBone);
    e.stroke(0.25, 0.4, Qt::ControlModifier);
    EXPECT_EQ(w.session().history().index(), steps + 2);
    EXPECT_EQ(w.session().history().undoText().rfind("Subtract weights of ", 0), 0u) << w.session().history().undoText();
    EXPECT_LT(weightOf(weights(w), hitVertex, wristBone), painted - 0.05);
    EXPECT_LT(largestSumError(weights(w)), 1e-4);

    w.session().history().undo();
    w.session().history().undo();
    EXPECT_EQ(weights(w), before);
}

TEST(WeightPaint, ALockedJointRefusesTheBrush)
{
    PaintEditor e("sleeves-lock.obj");
    app::MainWindow& w = e.w;
    const int wristBone = boneOf(w, "arm.L::skin.limb.2");
    e.chooseJoint(wristBone);
    QTreeWidgetItem* row = e.panel->jointList()->topLevelItem(wristBone);
    row->setCheckState(1, Qt::Checked); // the lock box, as a click does
    EXPECT_EQ(w.session().lockedJoints().count(w.session().skinBones()[wristBone].key), 1u);
    const model::MeshWeights before = weights(w);
    const std::size_t steps = w.session().history().index();
    e.stroke(0.25, 0.4);
    EXPECT_EQ(w.session().history().index(), steps) << "nothing painted, no step";
    EXPECT_EQ(weights(w), before);
    EXPECT_TRUE(logSays(w, "is locked"));

    row->setCheckState(1, Qt::Unchecked);
    e.stroke(0.25, 0.4);
    EXPECT_EQ(w.session().history().index(), steps + 1) << "unlocked, it paints";
}

TEST(WeightPaint, BoxSelectThenLimitChangesOnlyTheSelectedVertices)
{
    PaintEditor e("sleeves-limit.obj");
    app::MainWindow& w = e.w;
    e.panel->findChild<QAbstractButton*>("paintTool:select")->click();
    EXPECT_EQ(e.view->paintTool(), viewport::PaintTool::SelectVertices);
    // A box around the elbow, where the heat bind blends the upper and lower arm.
    const QPoint elbow = e.view->toWidgetPixels(translationOf(
        w.session().rig()->nodes[*w.session().rig()->findPath("arm.L::skin.limb.1")].worldMatrix));
    const QPoint corner(40, 60);
    QTest::mousePress(e.view, Qt::LeftButton, {}, elbow - corner);
    QTest::mouseMove(e.view, elbow);
    QTest::mouseMove(e.view, elbow + corner);
    QTest::mouseRelease(e.view, Qt::LeftButton, {}, elbow + corner);
    const auto& selected = w.session().selectedVertices();
    ASSERT_EQ(selected.size(), 1u);
    const std::vector<std::uint32_t> picked = selected.begin()->second;
    const model::MeshWeights before = weights(w);
    ASSERT_FALSE(picked.empty());
    EXPECT_LT(picked.size(), before.vertexCount() / 4) << "a box around the elbow, the camera's side only";
    EXPECT_EQ(e.view->scene().meshes.at(0).selectedVertices, picked);
    // Every vertex in the box on the camera's side of the sleeve is picked, none on the far side.
    const session::CharacterMesh& cm = w.session().characterMeshes().at(0);
    const model::Mesh& mesh = cm.data(w.session().models());
    const QRect box = QRect(elbow - corner, elbow + corner).adjusted(2, 2, -2, -2);
    std::size_t front = 0;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const Vec3 p(mesh.positions[v]);
        const Vec3 onAxis = e.shoulder + (e.wrist - e.shoulder) * glm::dot(p - e.shoulder, e.wrist - e.shoulder) /
                                             glm::dot(e.wrist - e.shoulder, e.wrist - e.shoulder);
        const double towardsCamera = p.z - onAxis.z; // the front view looks down -Z
        const bool isPicked = std::binary_search(picked.begin(), picked.end(), std::uint32_t(v));
        if (!box.contains(e.view->toWidgetPixels(p)))
            continue;
        if (towardsCamera > 0.02) {
            ++front;
            EXPECT_TRUE(isPicked) << "front vertex " << v;
        } else if (towardsCamera < -0.02) {
            EXPECT_FALSE(isPicked) << "far-side vertex " << v;
        }
    }
    EXPECT_GT(front, 10u);
    e.view->update();
    QTest::qWait(50);
    e.window.grab().save(QString::fromStdString(outputPath("weight-paint-selection.png"))); // to look at
    auto count = [](const model::MeshWeights& m, std::size_t v) { return m.offsets[v + 1] - m.offsets[v]; };
    ASSERT_TRUE(std::any_of(picked.begin(), picked.end(), [&](std::uint32_t v) { return count(before, v) > 1; }));

    const std::size_t steps = w.session().history().index();
    e.panel->limitCount()->setValue(1);
    e.panel->button("limit")->click();
    EXPECT_EQ(w.session().history().index(), steps + 1);
    EXPECT_EQ(w.session().history().undoText(), "Limit influences");
    const model::MeshWeights& after = weights(w);
    bool unselectedBlended = false;
    for (std::size_t v = 0; v < after.vertexCount(); ++v) {
        if (std::binary_search(picked.begin(), picked.end(), std::uint32_t(v))) {
            EXPECT_EQ(count(after, v), 1u) << v;
        } else {
            ASSERT_EQ(std::vector<model::Influence>(after.begin(v), after.end(v)),
                      std::vector<model::Influence>(before.begin(v), before.end(v))) << v;
            unselectedBlended |= count(after, v) > 1;
        }
    }
    EXPECT_TRUE(unselectedBlended) << "vertices outside the box keep their blends";

    e.panel->button("clearSelection")->click();
    EXPECT_TRUE(w.session().selectedVertices().empty());
}

TEST(WeightPaint, MirrorFromTheDockCopiesAStrokeOntoTheOtherArm)
{
    PaintEditor e("sleeves-mirror.obj");
    app::MainWindow& w = e.w;
    const int left = boneOf(w, "arm.L::skin.limb.2"), right = boneOf(w, "arm.R::skin.limb.2");
    ASSERT_GE(right, 0) << "the biped's arm is mirrored";
    ASSERT_GT(e.shoulder.x, 0.0) << "the left arm is on +X";
    e.chooseJoint(left);
    const auto hit = e.view->meshHitAt(e.onArm(0.3));
    ASSERT_TRUE(hit);
    e.stroke(0.25, 0.4);
    const std::size_t half = weights(w).vertexCount() / 2; // the right sleeve's vertex v + half mirrors v
    const double painted = weightOf(weights(w), hit->vertex, left);
    ASSERT_GT(painted, weightOf(weights(w), hit->vertex + half, right) + 0.05);

    const std::size_t steps = w.session().history().index();
    e.panel->button("mirrorPositive")->click();
    EXPECT_EQ(w.session().history().index(), steps + 1);
    EXPECT_NEAR(weightOf(weights(w), hit->vertex + half, right), painted, 1e-3);
    EXPECT_LT(largestSumError(weights(w)), 1e-4);
}

TEST(WeightPaint, BracketsAndBDragResizeTheBrushWithoutPainting)
{
    PaintEditor e("sleeves-radius.obj");
    const double start = e.panel->brush().radius;
    QTest::keyClick(e.view, Qt::Key_BracketRight);
    EXPECT_NEAR(e.view->brushRadius(), start * 1.25, 1e-9);
    EXPECT_NEAR(e.panel->brush().radius, start * 1.25, 1e-3) << "the dock follows the viewport (in millimetres)";
    QTest::keyClick(e.view, Qt::Key_BracketLeft);
    EXPECT_NEAR(e.panel->brush().radius, start, 1e-3);

    const std::size_t steps = e.w.session().history().index();
    const QPoint at = e.onArm(0.3);
    QTest::keyPress(e.view, Qt::Key_B);
    QTest::mousePress(e.view, Qt::LeftButton, {}, at);
    QTest::mouseMove(e.view, at + QPoint(60, 0));
    QTest::mouseRelease(e.view, Qt::LeftButton, {}, at + QPoint(60, 0));
    QTest::keyRelease(e.view, Qt::Key_B);
    EXPECT_GT(e.panel->brush().radius, start * 1.2);
    EXPECT_EQ(e.w.session().history().index(), steps) << "resizing paints nothing";

    // The dock's radius drives the viewport's brush circle.
    e.panel->findChild<QDoubleSpinBox*>("paintRadius")->setValue(0.02);
    EXPECT_NEAR(e.view->brushRadius(), 0.02, 1e-9);
}
