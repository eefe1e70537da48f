// CV mode through the real widgets: F8's action, clicks and a box on the CVs
// the viewport draws, a gizmo drag, the rebuilt rig and undo.
#include "EditorTestSupport.h"

#include "edit/ShapeCvEdit.h"

#include <QAction>

using namespace rs;
using namespace rs::test;

namespace {

Vec3 cvWorld(const app::EditorSession& session, const std::string& id, int curve, int cv)
{
    const model::Rig& rig = *session.rig();
    return edit::cvWorldPosition(rig, {*rig.findPath(id), curve, cv});
}

QPoint pixelOf(viewport::ViewportWidget* view, const Vec3& world) { return view->toWidgetPixels(world); }

// CVs of curve 0 of `node` that no drawn CV elsewhere hides on screen, with
// how many CVs share their place (a cube's corner is several CVs).
std::vector<int> clickableCvs(viewport::ViewportWidget* view, model::RigNodeIndex node)
{
    std::vector<int> out;
    const auto& cvs = view->scene().cvs;
    for (const auto& cv : cvs) {
        if (cv.cv.node != node || cv.cv.curve != 0)
            continue;
        bool alone = true;
        for (const auto& other : cvs)
            if (glm::length(other.position - cv.position) > 1e-6 &&
                (pixelOf(view, other.position) - pixelOf(view, cv.position)).manhattanLength() < 24)
                alone = false;
        if (alone)
            out.push_back(cv.cv.cv);
    }
    return out;
}

} // namespace

TEST(CvMode, ClicksAndBoxSelectCvsAndTheGizmoMovesThemAsOneUndoStep)
{
    Editor editor;
    app::MainWindow& w = editor.window;
    const model::GuideDocument original = w.session().document();
    viewport::ViewportWidget* view = w.viewportWidget();
    w.buildRig();
    w.session().setMode(app::EditorMode::Guide);
    const std::string ik = "arm.L::ctrls.ik", twin = "arm.R::ctrls.ik";
    const model::RigNodeIndex node = *w.session().rig()->findPath(ik);

    // Select the IK control, then F8: its CVs and hulls are drawn.
    w.session().selectControllers({node}, false);
    QApplication::processEvents();
    view->frameSelection();
    QApplication::processEvents();
    w.action("cvMode")->trigger();
    ASSERT_TRUE(w.session().isCvMode());
    const std::size_t count = w.session().rig()->nodes[node].curves[0].cvs.size();
    ASSERT_GE(view->scene().cvs.size(), count);
    EXPECT_FALSE(view->scene().hulls.empty());
    EXPECT_FALSE(view->gizmo().has_value()) << "no gizmo until CVs are picked";

    // Click one CV, Shift+click another: the gizmo sits between them.
    const std::vector<int> clickable = clickableCvs(view, node);
    ASSERT_GE(clickable.size(), 2u);
    const int a = clickable[0];
    auto placeOf = [&](int cv) { return cvWorld(w.session(), ik, 0, cv); };
    const int b = *std::find_if(clickable.begin(), clickable.end(), [&](int cv) { return glm::length(placeOf(cv) - placeOf(a)) > 1e-6; });
    int other = 0;
    while (glm::length(placeOf(other) - placeOf(a)) < 1e-6 || glm::length(placeOf(other) - placeOf(b)) < 1e-6) ++other;
    const auto cornerA = viewport::coincidentCvs(view->scene(), {node, 0, a});
    const auto cornerB = viewport::coincidentCvs(view->scene(), {node, 0, b});
    QTest::keyClick(view, Qt::Key_Q); // the select tool: no gizmo handle in the way of the clicks
    QTest::mouseClick(view, Qt::LeftButton, {}, pixelOf(view, placeOf(a)));
    EXPECT_EQ(w.session().selection().cvs, cornerA) << "a click picks the CV with the CVs at its place";
    QTest::mouseClick(view, Qt::LeftButton, Qt::ShiftModifier, pixelOf(view, placeOf(b)));
    ASSERT_EQ(w.session().selection().cvs.size(), cornerA.size() + cornerB.size());
    QTest::mouseClick(view, Qt::LeftButton, Qt::ShiftModifier, pixelOf(view, placeOf(b)));
    EXPECT_EQ(w.session().selection().cvs, cornerA) << "Shift+click again deselects";
    QTest::mouseClick(view, Qt::LeftButton, Qt::ShiftModifier, pixelOf(view, placeOf(b)));
    const std::size_t picked = w.session().selection().cvs.size();
    const Vec3 a0 = cvWorld(w.session(), ik, 0, a), b0 = cvWorld(w.session(), ik, 0, b);
    const Vec3 twin0 = cvWorld(w.session(), twin, 0, a), other0 = cvWorld(w.session(), ik, 0, other);
    view->setGizmoWorldSpace(true);
    QTest::keyClick(view, Qt::Key_W);
    ASSERT_TRUE(view->gizmo().has_value());
    EXPECT_LT(glm::length(view->gizmo()->origin() - (a0 * double(cornerA.size()) + b0 * double(cornerB.size())) / double(picked)), 1e-9);

    // Drag the world-Y handle: both CVs rise together, one undo step, rebuilt at once.
    ASSERT_TRUE(dragGizmoHandle(view, 1));
    EXPECT_EQ(w.session().history().size(), 1u);
    EXPECT_EQ(w.session().history().undoText(), "Move " + std::to_string(picked) + " CVs of ctrls.ik of arm");
    EXPECT_FALSE(w.session().isRigStale());
    const Vec3 a1 = cvWorld(w.session(), ik, 0, a), b1 = cvWorld(w.session(), ik, 0, b);
    EXPECT_GT(a1.y - a0.y, 0.01);
    EXPECT_LT(glm::length((a1 - a0) - (b1 - b0)), 1e-9) << "moved together";
    EXPECT_LT(glm::length((a1 - a0) - Vec3(0.0, a1.y - a0.y, 0.0)), 1e-9) << "along world Y only";
    EXPECT_LT(glm::length(cvWorld(w.session(), ik, 0, other) - other0), 1e-12) << "unselected CVs stay";
    const Vec3 twin1 = cvWorld(w.session(), twin, 0, a);
    EXPECT_LT(glm::length((twin1 - twin0) - (a1 - a0)), 1e-9) << "the mirrored side follows (a Y move reflects onto itself)";
    EXPECT_EQ(w.session().selection().cvs.size(), picked) << "the rebuild keeps the CVs selected";
    w.grab().save(QString::fromStdString(outputPath("cv-mode.png")));

    // A box around the whole control selects every CV of it.
    QRect box;
    for (const auto& cv : view->scene().cvs)
        if (cv.cv.node == node) box |= QRect(pixelOf(view, cv.position), QSize(1, 1));
    box.adjust(-8, -8, 8, 8);
    QTest::keyClick(view, Qt::Key_Q);
    QTest::mousePress(view, Qt::LeftButton, {}, box.topLeft());
    QTest::mouseMove(view, box.center());
    QTest::mouseMove(view, box.bottomRight());
    QTest::mouseRelease(view, Qt::LeftButton, {}, box.bottomRight());
    std::size_t all = 0;
    for (const auto& curve : w.session().rig()->nodes[node].curves) all += curve.cvs.size();
    EXPECT_EQ(w.session().selection().cvs.size(), all);

    // A click on nothing drops the CVs and keeps the controller; F8 again leaves CV mode.
    QTest::mouseClick(view, Qt::LeftButton, {}, QPoint(5, view->height() - 5));
    EXPECT_TRUE(w.session().selection().cvs.empty());
    EXPECT_EQ(w.session().selection().node, node);
    w.action("cvMode")->trigger();
    EXPECT_TRUE(view->scene().cvs.empty());

    w.action("undo")->trigger();
    EXPECT_TRUE(w.session().document() == original);
    EXPECT_LT(glm::length(cvWorld(w.session(), ik, 0, a) - a0), 1e-12) << "undo rebuilds the shape at once";
}
