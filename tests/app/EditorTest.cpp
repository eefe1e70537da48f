// GUI tests that drive the real editor widgets under Xvfb (QTest + GoogleTest).
#include "EditorTestSupport.h"

#include "LogPanel.h"
#include "OutlinerView.h"
#include "ViewportWidget.h"
#include "edit/GuideEdits.h"
#include "io/GuideFile.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QSettings>
#include <QMenu>
#include <QTest>
#include <QToolBar>
#include <QToolButton>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace rs;
using namespace rs::test;

namespace {

void clickInstance(app::MainWindow& w, const QString& name)
{
    widgets::OutlinerView* outliner = w.outliner();
    const QModelIndexList found = outliner->model()->match(outliner->model()->index(0, 0), Qt::DisplayRole, name, 1,
                                                           Qt::MatchRecursive | Qt::MatchExactly);
    ASSERT_EQ(found.size(), 1) << name.toStdString();
    outliner->scrollTo(found.front());
    QTest::mouseClick(outliner->viewport(), Qt::LeftButton, {}, outliner->visualRect(found.front()).center());
}

} // namespace

TEST(Editor, AddsATemplateAtAHookBuildsExportsAndUndoesBackToTheStart)
{
    Editor e;
    app::MainWindow& w = e.window;
    const std::string original = io::writeGuideText(w.session().document());
    const auto* arm = w.session().document().instanceNamed("arm");
    const model::JointId hand = arm->joints[3].id; // limb3, the wrist

    clickInstance(w, "arm");
    ASSERT_EQ(w.session().selection().instance, arm->id) << "clicking the outliner selects the instance";

    // Right-click menu: Add template > default (the arm's hand) > core > joints.
    std::unique_ptr<QMenu> menu(w.outliner()->createContextMenu(w.outliner()->selectedInstance(), &w));
    auto* add = menu->findChild<QMenu*>("addTemplate");
    ASSERT_NE(add, nullptr);
    QStringList hooks;
    for (QMenu* m : add->findChildren<QMenu*>(QString(), Qt::FindDirectChildrenOnly))
        hooks << m->title();
    EXPECT_EQ(hooks.join(", ").toStdString(), "default, shoulder, elbow, hand")
        << "one entry per ui.hooks node of arm.limb";
    auto* atDefault = add->findChild<QMenu*>("hook:default");
    ASSERT_NE(atDefault, nullptr);
    QAction* addJoints = atDefault->findChild<QAction*>("add:core.joints");
    ASSERT_NE(addJoints, nullptr);
    addJoints->trigger();

    const auto& doc = w.session().document();
    ASSERT_EQ(doc.instances().size(), 12u);
    const model::TemplateInstance& added = doc.instances().back();
    EXPECT_EQ(added.parentJoint, hand);
    EXPECT_EQ(w.session().selection().instance, added.id);

    // Build through the toolbar button a user would press.
    QToolBar* bar = w.findChild<QToolBar*>("mainToolBar");
    auto* buildButton = qobject_cast<QToolButton*>(bar->widgetForAction(w.action("build")));
    ASSERT_NE(buildButton, nullptr);
    QTest::mouseClick(buildButton, Qt::LeftButton);
    const model::Rig* rig = w.session().rig();
    ASSERT_NE(rig, nullptr);
    EXPECT_FALSE(hasErrors(rig->diagnostics)) << formatAll(rig->diagnostics);
    const auto root = rig->findPath(added.name + ".L::roots.0"); // built once per branch of the arm
    ASSERT_TRUE(root);
    EXPECT_EQ(rig->nodes[rig->nodes[*root].parent].path, "arm.L::blend.2") << "hung under the hand's hook";
    EXPECT_FALSE(w.viewportWidget()->scene().curves.empty()) << "controller curves shown after build";
    QTest::qWait(100);
    w.grab().save(QString::fromStdString(outputPath("editor-after-build.png")));

    const std::string glb = outputPath("editor-export.glb");
    std::filesystem::remove(glb);
    ASSERT_TRUE(w.exportTo(QString::fromStdString(glb)));
    EXPECT_GT(std::filesystem::file_size(glb), 1000u);

    int undos = 0;
    while (w.action("undo")->isEnabled() && undos < 100) {
        w.action("undo")->trigger();
        ++undos;
    }
    EXPECT_EQ(undos, 1);
    EXPECT_EQ(io::writeGuideText(w.session().document()), original);
    EXPECT_EQ(w.outliner()->model()->rowCount(), 1) << "one top-level instance (world) again";
}

TEST(Editor, F5ReloadsTemplatesWithoutARestart)
{
    const std::filesystem::path folder = outputPath("reload-templates");
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    setenv("RIGSMITH_TEMPLATE_PATH", folder.c_str(), 1);
    Editor e;
    app::MainWindow& w = e.window;
    EXPECT_EQ(w.session().templates().find("extra.tail"), nullptr);
    w.action("build")->trigger();
    const std::size_t nodesBefore = w.session().rig()->nodes.size();

    // The rigger writes a new template and breaks another one, then presses F5.
    std::filesystem::create_directories(folder / "extra" / "tail");
    std::ofstream(folder / "extra" / "tail" / "template.yml") << "name: tail\nbase: core.joints\nstructure:\n  chain: /*\n";
    std::filesystem::create_directories(folder / "extra" / "broken");
    std::ofstream(folder / "extra" / "broken" / "template.yml") << "name: [oops\n";
    w.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
    QTest::keyClick(w.outliner(), Qt::Key_F5);

    ASSERT_NE(w.session().templates().find("extra.tail"), nullptr) << "the new template is available";
    EXPECT_NE(w.session().templates().find("core.joints"), nullptr) << "a broken manifest drops only itself";
    EXPECT_EQ(w.session().rig()->nodes.size(), nodesBefore) << "the rig was rebuilt with the reloaded templates";
    EXPECT_FALSE(w.session().isRigStale());
    std::string log;
    auto* panel = w.findChild<widgets::LogPanel*>("buildLog");
    for (int i = 0; i < panel->count(); ++i)
        log += panel->item(i)->text().toStdString() + "\n";
    EXPECT_NE(log.find("broken/template.yml:2:1: error: malformed YAML"), std::string::npos) << log;
    EXPECT_NE(log.find("Reloaded"), std::string::npos) << log;

    clickInstance(w, "arm");
    std::unique_ptr<QMenu> menu(w.outliner()->createContextMenu(w.outliner()->selectedInstance(), &w));
    EXPECT_NE(menu->findChild<QAction*>("add:extra.tail"), nullptr) << "the outliner offers it at once";
    unsetenv("RIGSMITH_TEMPLATE_PATH");
}

TEST(Editor, AFileThatFailsToLoadLeavesTheOpenGuideUntouched)
{
    Editor e;
    const std::string before = io::writeGuideText(e.window.session().document());
    const std::string broken = outputPath("broken.yml");
    std::ofstream(broken) << "rigsmith_guide: 1\ninstances:\n  - id: 1\n    template: [\n";
    EXPECT_FALSE(e.window.openFile(QString::fromStdString(broken)));
    EXPECT_EQ(io::writeGuideText(e.window.session().document()), before);
    const QString lastLine = e.window.log()->item(e.window.log()->count() - 1)->text();
    EXPECT_TRUE(lastLine.startsWith(QString::fromStdString(broken) + ":5:")) << lastLine.toStdString();
}

TEST(Editor, ClickingAGuideJointInTheViewportSelectsItsInstance)
{
    Editor e;
    app::MainWindow& w = e.window;
    w.viewportWidget()->frameAll();
    QTest::qWait(50);
    const auto& doc = w.session().document();
    const auto* neck = doc.instanceNamed("neck");
    const QPoint at = w.viewportWidget()->toWidgetPixels(translationOf(doc.jointWorldMatrix(neck->joints[2].id)));
    QTest::mouseClick(w.viewportWidget(), Qt::LeftButton, {}, at);
    EXPECT_EQ(w.session().selection().instance, neck->id);
    EXPECT_EQ(w.session().selection().joint, neck->joints[2].id);
    EXPECT_EQ(w.outliner()->selectedInstance(), neck->id) << "selection synchronised with the outliner";
}

int main(int argc, char** argv)
{
    viewport::requestOpenGl33Core();
    // Saved layouts and recent files per test process (ctest runs tests in parallel), not the user's.
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope,
                       QDir::tempPath() + "/rigsmith-editor-settings-" + QString::number(QCoreApplication::applicationPid()));
    QApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}

TEST(Editor, FileNewListsTheSamplesAndStartsAnUntitledCopy)
{
    Editor e;
    app::MainWindow& w = e.window;
    auto* newMenu = w.findChild<QMenu*>("newMenu");
    ASSERT_NE(newMenu, nullptr);
    QStringList entries;
    for (QAction* a : newMenu->actions())
        if (!a->isSeparator())
            entries << a->objectName();
    EXPECT_EQ(entries.join(", ").toStdString(), "new:empty, new:biped, new:cart, new:claw, new:face, new:prop, new:quadruped, new:robot, new:strider, new:vehicle");

    w.action("new:quadruped")->trigger();
    EXPECT_TRUE(w.session().filePath().isEmpty()) << "a copy: saving never overwrites the sample";
    EXPECT_EQ(w.session().document().name, "quadruped");
    EXPECT_NE(w.session().document().instanceNamed("tail"), nullptr);
    w.action("build")->trigger();
    ASSERT_NE(w.session().rig(), nullptr);
    EXPECT_TRUE(w.session().rig()->diagnostics.empty()) << formatAll(w.session().rig()->diagnostics);
    EXPECT_TRUE(w.session().rig()->findPath("hind_leg.R::rfoot.heel"));

    w.action("new:empty")->trigger();
    EXPECT_TRUE(w.session().document().instances().empty());
}

TEST(Editor, OutlinerArrowKeysPickwalkTheTemplateInstances)
{
    Editor e;
    app::MainWindow& w = e.window;
    clickInstance(w, "arm");
    auto selected = [&] { return QString::fromStdString(w.session().document().instance(w.session().selection().instance)->name); };
    ASSERT_EQ(selected(), "arm");
    QTest::keyClick(w.outliner(), Qt::Key_Up);
    EXPECT_EQ(selected(), "spine");
    QTest::keyClick(w.outliner(), Qt::Key_Down);
    EXPECT_EQ(selected(), "neck"); // the spine's first child
    QTest::keyClick(w.outliner(), Qt::Key_Right);
    EXPECT_EQ(selected(), "arm");
    QTest::keyClick(w.outliner(), Qt::Key_Down);
    EXPECT_EQ(selected(), "hand"); // the arm's only child: the hand master
    QTest::keyClick(w.outliner(), Qt::Key_Down);
    EXPECT_EQ(selected(), "thumb"); // the hand's first finger
    QTest::keyClick(w.outliner(), Qt::Key_Left);
    EXPECT_EQ(selected(), "pinky"); // siblings wrap
    EXPECT_EQ(w.outliner()->selectedInstance(), w.session().selection().instance); // the tree follows
}

// The build log's messages about a mirrored copy (the R side of `branches: [L, R]`)
// select the authored instance; one about a node of the copy also selects that node.
TEST(Editor, ClickingADiagnosticAboutAMirroredCopySelectsItsSourceAndTheNode)
{
    Editor e;
    app::MainWindow& w = e.window;
    const model::InstanceId arm = w.session().document().instanceNamed("arm")->id;
    model::PoseValues pose;
    pose[{arm, "R", "ctrls.fk.9"}]["rx"] = 10.0; // no such control: the build reports it, on the R copy
    ASSERT_TRUE(edit::setPose(w.session().history(), pose, "Pose").ok());
    w.findChild<QAction*>("build")->trigger();
    const model::Rig* rig = w.session().rig();
    ASSERT_NE(rig, nullptr);
    widgets::LogPanel* log = w.log();
    auto rowContaining = [&](const QString& text) {
        for (int row = log->count() - 1; row >= 0; --row)
            if (log->item(row)->text().contains(text))
                return log->item(row);
        return static_cast<QListWidgetItem*>(nullptr);
    };
    w.session().select({});
    QListWidgetItem* orphan = rowContaining("arm.R::ctrls.fk.9");
    ASSERT_NE(orphan, nullptr);
    log->scrollToItem(orphan);
    QTest::mouseClick(log->viewport(), Qt::LeftButton, {}, log->visualItemRect(orphan).center());
    EXPECT_EQ(w.session().selection().instance, arm);

    // A message about a node of the mirrored copy (as the export checks make).
    const auto ikRight = rig->findPath("arm.R::ctrls.ik");
    ASSERT_TRUE(ikRight);
    Diagnostic d = makeWarning({}, "a message about the right IK control");
    d.subject = Subject::ofNode(rig->nodes[*ikRight].key);
    log->addDiagnostics({d});
    w.session().select({});
    QListWidgetItem* item = log->item(log->count() - 1);
    log->scrollToItem(item);
    QTest::mouseClick(log->viewport(), Qt::LeftButton, {}, log->visualItemRect(item).center());
    EXPECT_EQ(w.session().selection().instance, arm) << "the authored instance of the R copy";
    EXPECT_EQ(w.session().selection().node, *ikRight) << "the mirrored node itself";
}
