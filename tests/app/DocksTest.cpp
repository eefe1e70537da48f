// The template library and undo history docks driven through their real widgets (issue 7).
#include "EditorTestSupport.h"
#include "HistoryView.h"
#include "TemplateLibrary.h"

#include <QDockWidget>

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
