// The end-to-end scenario with the real widgets, as a rigger works:
// a biped from the sample, a digit at the hand hook through the outliner menu,
// an option changed, a guide dragged with the gizmo, build, pickwalk, save,
// reopen, and undo everything back to the start.
#include "EditorTestSupport.h"

#include "ChannelBox.h"
#include "OptionsEditor.h"
#include "OutlinerView.h"
#include "ViewportWidget.h"
#include "eval/Pickwalk.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDockWidget>
#include <QProgressBar>
#include <QMenu>
#include <QStatusBar>

using namespace rs;
using namespace rs::test;

namespace {

void saveDock(app::MainWindow& w, const char* dock, const std::string& file)
{
    w.findChild<QDockWidget*>(dock)->grab().save(QString::fromStdString(outputPath(file)));
}

} // namespace

TEST(Scenario, FromSampleToSavedRigAndBackToTheStart)
{
    app::MainWindow w;
    w.setProperty("skipUnsavedPrompt", true);
    w.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
    app::EditorSession& session = w.session();

    // 1. File > New > biped.
    w.findChild<QAction*>("new:biped")->trigger();
    ASSERT_EQ(session.document().instances().size(), 11u);
    EXPECT_TRUE(session.filePath().isEmpty()) << "a copy, never the sample itself";
    const model::GuideDocument original = session.document();

    // 2. Outliner: arm > Add template > hand > digit.finger.
    const model::InstanceId arm = session.instanceNamed("arm");
    std::unique_ptr<QMenu> menu(w.outliner()->createContextMenu(arm, &w));
    QMenu* hand = menu->findChild<QMenu*>("addTemplate")->findChild<QMenu*>("hook:hand");
    ASSERT_NE(hand, nullptr);
    QAction* addDigit = hand->findChild<QAction*>("add:digit.finger");
    ASSERT_NE(addDigit, nullptr);
    addDigit->trigger();
    const model::InstanceId digit = session.selection().instance;
    const model::TemplateInstance* added = session.document().instance(digit);
    ASSERT_NE(added, nullptr);
    EXPECT_EQ(added->templateId, "digit.finger");
    EXPECT_EQ(added->parentJoint, session.document().instance(arm)->joints[3].id) << "hung at the hand hook";

    // 3. Options dock: turn the digit's base off.
    QApplication::processEvents(); // the options page is rebuilt on the next turn of the event loop
    ASSERT_EQ(w.optionsEditor()->instance(), digit);
    auto* base = qobject_cast<QCheckBox*>(w.optionsEditor()->editorFor("base"));
    ASSERT_NE(base, nullptr);
    base->click();
    EXPECT_EQ(session.document().instance(digit)->options.at("base"), Value(false));
    saveDock(w, "optionsDock", "scenario-options-dock.png");
    saveDock(w, "outlinerDock", "scenario-outliner-dock.png");

    // 4. Viewport: front view, click the digit's tip guide, drag it up with the gizmo.
    viewport::ViewportWidget* view = w.viewportWidget();
    QTest::keyClick(view, Qt::Key_1);
    const model::JointId tip = session.document().instance(digit)->joints.back().id;
    view->frameSelection();
    const Vec3 tipBefore = translationOf(session.document().jointWorldMatrix(tip));
    QTest::mouseClick(view, Qt::LeftButton, {}, view->toWidgetPixels(tipBefore));
    ASSERT_EQ(session.selection().joint, tip);
    QTest::keyClick(view, Qt::Key_W);
    view->setGizmoWorldSpace(true);
    ASSERT_TRUE(dragGizmoHandle(view, 1));
    EXPECT_GT(translationOf(session.document().jointWorldMatrix(tip)).y - tipBefore.y, 0.005);
    EXPECT_EQ(session.history().size(), 3u) << "add, option, drag: one step each";

    // 5. Build: Rig mode with the new finger's controls; a progress bar in the status bar while it runs.
    auto* progress = w.findChild<QProgressBar*>("buildProgress");
    ASSERT_NE(progress, nullptr);
    std::vector<int> shown;
    const auto watch = QObject::connect(&session, &app::EditorSession::buildProgressed, progress, [&](double fraction) {
        if (fraction < 1.0 && progress->isVisible()) shown.push_back(progress->value());
    }, Qt::DirectConnection);
    w.action("build")->trigger();
    QObject::disconnect(watch);
    EXPECT_GT(shown.size(), 5u) << "the bar was shown and moved on";
    EXPECT_TRUE(std::is_sorted(shown.begin(), shown.end()));
    EXPECT_FALSE(progress->isVisible()) << "hidden when the build is done";
    const model::Rig* rig = session.rig();
    ASSERT_NE(rig, nullptr);
    EXPECT_FALSE(hasErrors(rig->diagnostics)) << formatAll(rig->diagnostics);
    EXPECT_EQ(session.mode(), app::EditorMode::Rig);
    EXPECT_TRUE(w.statusBar()->currentMessage().contains(" ms, 0 errors")) << w.statusBar()->currentMessage().toStdString();
    const std::string digitName = session.document().instance(digit)->name;
    const auto fk = rig->findPath(digitName + ".L::ctrls.fk.1");
    ASSERT_TRUE(fk.has_value()) << digitName;

    // 6. Pickwalk up the new finger's chain with the arrow keys.
    session.selectControllers({*fk}, false);
    QTest::keyClick(view, Qt::Key_Up);
    EXPECT_EQ(rig->nodes[session.selection().node].path, digitName + ".L::ctrls.fk.0");
    QApplication::processEvents();
    saveDock(w, "channelBoxDock", "scenario-channel-box-dock.png");
    saveDock(w, "logDock", "scenario-log-dock.png");
    w.grab().save(QString::fromStdString(outputPath("scenario-rig-mode.png")));

    // 7. Save, and reopen in another window: the same document.
    const QString path = QString::fromStdString(outputPath("scenario.yml"));
    QFile::remove(path);
    ASSERT_TRUE(w.saveFile(path));
    EXPECT_FALSE(w.windowTitle().contains('*'));
    {
        app::MainWindow other;
        other.setProperty("skipUnsavedPrompt", true);
        ASSERT_TRUE(other.openFile(path));
        EXPECT_TRUE(other.session().document() == session.document());
    }

    // 8. Undo everything: the document is the sample again.
    while (w.action("undo")->isEnabled())
        w.action("undo")->trigger();
    EXPECT_TRUE(session.document() == original);
    EXPECT_TRUE(w.windowTitle().contains('*')) << "differs from the saved file";
}
