// The template library and undo history docks driven through their real widgets (issue 7).
#include "EditorTestSupport.h"
#include "HistoryView.h"
#include "TemplateLibrary.h"
#include "WeightPaintPanel.h"

#include <QDockWidget>
#include <QTreeWidget>

using namespace rs;

TEST(Docks, LibraryAddsAtTheSelectedJointAndHistoryJumpsBackAndForth)
{
    test::Editor editor;
    auto& w = editor.window;
    const model::GuideDocument original = w.session().document();
    widgets::TemplateLibrary* library = w.templateLibrary();
    QTreeWidgetItem* finger = library->itemOf("digit.finger");
    ASSERT_NE(finger, nullptr);
    EXPECT_EQ(finger->parent()->text(0), "digit") << "grouped by category";
    EXPECT_FALSE(finger->icon(0).isNull());
    EXPECT_TRUE(finger->toolTip(0).contains("digit.finger"));

    const model::InstanceId arm = w.session().instanceNamed("arm");
    const model::JointId hand = original.instance(arm)->joints[3].id;
    w.session().select(app::Selection::ofInstance(arm, hand));
    const std::size_t before = original.instances().size();
    library->scrollToItem(finger);
    const QPoint at = library->visualItemRect(finger).center();
    QTest::mouseClick(library->viewport(), Qt::LeftButton, {}, at);
    QTest::mouseDClick(library->viewport(), Qt::LeftButton, {}, at);
    ASSERT_EQ(w.session().document().instances().size(), before + 1);
    const model::TemplateInstance& added = w.session().document().instances().back();
    EXPECT_EQ(added.templateId, "digit.finger");
    EXPECT_EQ(added.parentJoint, hand);

    widgets::HistoryView* history = w.historyView();
    ASSERT_EQ(history->count(), 2);
    EXPECT_EQ(history->item(0)->text(), "Opened");
    EXPECT_TRUE(history->item(1)->text().startsWith("Add digit.finger"));
    QTest::mouseClick(history->viewport(), Qt::LeftButton, {}, history->visualItemRect(history->item(0)).center());
    EXPECT_TRUE(w.session().document() == original) << "back to the document as opened";
    EXPECT_EQ(history->count(), 2) << "the undone edit stays listed for redo";
    QTest::mouseClick(history->viewport(), Qt::LeftButton, {}, history->visualItemRect(history->item(1)).center());
    EXPECT_EQ(w.session().document().instances().size(), before + 1);
    w.findChild<QDockWidget*>("libraryDock")->grab().save(QString::fromStdString(test::outputPath("library-dock.png")));
    w.findChild<QDockWidget*>("historyDock")->raise();
    QApplication::processEvents();
    w.findChild<QDockWidget*>("historyDock")->grab().save(QString::fromStdString(test::outputPath("history-dock.png")));
}

TEST(Docks, HistoryListKeepsItsRowsAcrossEditsUndoAndANewBranch)
{
    test::Editor editor;
    auto& w = editor.window;
    widgets::HistoryView* history = w.historyView();
    ASSERT_EQ(history->count(), 1);
    const model::InstanceId arm = w.session().instanceNamed("arm");
    ASSERT_TRUE(w.session().renameInstance(arm, "limb").ok());
    ASSERT_TRUE(w.session().renameInstance(arm, "limbA").ok());
    ASSERT_EQ(history->count(), 3);
    const int mark = Qt::UserRole + 7; // a row rebuilt would lose it (an address could be reused)
    history->item(1)->setData(mark, true);
    EXPECT_FALSE(history->item(1)->data(Qt::ForegroundRole).isValid()) << "a done step keeps the view's colour";

    w.session().history().undo();
    ASSERT_EQ(history->count(), 3) << "the undone step stays listed for redo";
    EXPECT_EQ(history->currentRow(), 1);
    EXPECT_TRUE(history->item(2)->data(Qt::ForegroundRole).isValid()) << "the undone step is greyed";
    EXPECT_TRUE(history->item(1)->data(mark).toBool()) << "rows that still hold are not rebuilt";

    ASSERT_TRUE(w.session().renameInstance(arm, "limbB").ok()); // a new branch drops the redo step
    ASSERT_EQ(history->count(), 3);
    EXPECT_TRUE(history->item(1)->data(mark).toBool());
    EXPECT_EQ(history->item(2)->text().toStdString(), w.session().history().textAt(1));
    EXPECT_FALSE(history->item(2)->data(Qt::ForegroundRole).isValid()) << "the new step is not greyed";
    EXPECT_EQ(history->currentRow(), 2);

    w.session().history().jumpTo(0);
    for (int row = 1; row < history->count(); ++row)
        EXPECT_TRUE(history->item(row)->data(Qt::ForegroundRole).isValid()) << row;
    w.session().history().jumpTo(2);
    for (int row = 1; row < history->count(); ++row)
        EXPECT_FALSE(history->item(row)->data(Qt::ForegroundRole).isValid()) << row;
}

TEST(Docks, PaintJointListIsNotRebuiltByALiveRebuildThatKeepsTheSkinJoints)
{
    test::Editor editor;
    auto& w = editor.window;
    w.buildRig();
    QTreeWidget* joints = w.paintPanel()->jointList();
    ASSERT_GT(joints->topLevelItemCount(), 0);
    const int mark = Qt::UserRole + 7; // a row rebuilt would lose it (an address could be reused)
    joints->topLevelItem(0)->setData(0, mark, true);
    const model::InstanceId arm = w.session().instanceNamed("arm");
    const model::JointId elbow = w.session().document().instance(arm)->joints[2].id;
    Mat4 world = w.session().document().jointWorldMatrix(elbow);
    w.session().beginGuideDrag(elbow);
    world[3][1] += 0.01;
    w.session().dragGuideTo(world);
    ASSERT_TRUE(w.session().endGuideDrag("move elbow").ok());
    EXPECT_TRUE(joints->topLevelItem(0)->data(0, mark).toBool()) << "same skin joints: the rows stand";

    ASSERT_TRUE(w.session().removeInstances({arm}).ok()); // fewer skin joints: listed again
    EXPECT_EQ(joints->topLevelItemCount(), int(w.session().skinBones().size()));
}
