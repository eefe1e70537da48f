// The outliner with the real widgets: hook pseudo-items, multi-selection,
// Duplicate from the context menu, drag and drop to re-hang, Delete.
#include "EditorTestSupport.h"

#include "OutlinerView.h"
#include "LogPanel.h"

#include <QAction>
#include <QDockWidget>
#include <QDropEvent>
#include <QMenu>
#include <QMimeData>
#include <QStandardItemModel>

using namespace rs;
using namespace rs::test;

namespace {

QModelIndex itemNamed(widgets::OutlinerView* outliner, const QString& text)
{
    const auto found = outliner->model()->match(outliner->model()->index(0, 0), Qt::DisplayRole, text, 1,
                                                Qt::MatchRecursive | Qt::MatchExactly);
    return found.isEmpty() ? QModelIndex() : found.front();
}

void click(widgets::OutlinerView* outliner, const QModelIndex& index, Qt::KeyboardModifiers modifiers = {})
{
    outliner->scrollTo(index);
    QTest::mouseClick(outliner->viewport(), Qt::LeftButton, modifiers, outliner->visualRect(index).center());
}

// What a drag from the outliner onto `target` delivers (QDrag::exec is modal, so
// the test sends the drop a completed drag would).
void dropOn(widgets::OutlinerView* outliner, const QModelIndex& target)
{
    QMimeData* mime = outliner->model()->mimeData(outliner->selectionModel()->selectedRows());
    const QPoint at = outliner->visualRect(target).center();
    QDragEnterEvent enter(at, Qt::MoveAction, mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(outliner->viewport(), &enter);
    QDragMoveEvent move(at, Qt::MoveAction, mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(outliner->viewport(), &move);
    QDropEvent drop(QPointF(at), Qt::MoveAction, mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(outliner->viewport(), &drop);
    delete mime;
}

Vec3 worldOf(app::MainWindow& w, model::JointId joint)
{
    return translationOf(w.session().document().jointWorldMatrix(joint));
}

} // namespace

TEST(Outliner, HooksAreItemsAndInstancesHangUnderTheirHook)
{
    Editor editor;
    widgets::OutlinerView* outliner = editor.window.outliner();
    const QModelIndex arm = itemNamed(outliner, "arm");
    ASSERT_TRUE(arm.isValid());
    QStringList hooks;
    for (int r = 0; r < outliner->model()->rowCount(arm); ++r)
        hooks << outliner->model()->index(r, 0, arm).data().toString();
    EXPECT_TRUE(hooks.contains("shoulder") && hooks.contains("elbow") && hooks.contains("hand")) << hooks.join(", ").toStdString();
    const QModelIndex thumb = itemNamed(outliner, "thumb");
    ASSERT_TRUE(thumb.isValid());
    EXPECT_EQ(thumb.parent().data().toString(), "default") << "the fingers hang under the hand master's hook";
    EXPECT_EQ(thumb.parent().parent().data().toString(), "hand");
    EXPECT_EQ(thumb.parent().parent().parent().data().toString(), "hand") << "the hand master hangs under the arm's hand hook";

    // Clicking a hook selects its joint (the gizmo goes there).
    click(outliner, itemNamed(outliner, "elbow"));
    const auto* armInstance = editor.window.session().document().instanceNamed("arm");
    EXPECT_EQ(editor.window.session().selection().instance, armInstance->id);
    EXPECT_EQ(editor.window.session().selection().joint, armInstance->joints[2].id);
    editor.window.findChild<QDockWidget*>("outlinerDock")->grab().save(QString::fromStdString(outputPath("outliner-dock.png")));
}

TEST(Outliner, SeveralInstancesAreDuplicatedReHungAndDeletedTogether)
{
    Editor editor;
    app::MainWindow& w = editor.window;
    widgets::OutlinerView* outliner = w.outliner();
    const model::GuideDocument original = w.session().document();

    click(outliner, itemNamed(outliner, "index"));
    click(outliner, itemNamed(outliner, "ring"), Qt::ControlModifier);
    ASSERT_EQ(outliner->topSelectedInstances().size(), 2u);
    std::unique_ptr<QMenu> menu(outliner->createContextMenu(w.session().instanceNamed("ring"), &w));
    QAction* duplicate = menu->findChild<QAction*>("duplicate");
    ASSERT_NE(duplicate, nullptr);
    duplicate->trigger();
    const auto& doc = w.session().document();
    ASSERT_NE(doc.instanceNamed("index1"), nullptr);
    ASSERT_NE(doc.instanceNamed("ring1"), nullptr);
    EXPECT_EQ(w.session().history().size(), 1u) << "one step for both";

    // Drag the leg onto the neck (its default hook, the head): re-hung there, still where it was.
    const model::InstanceId leg = w.session().instanceNamed("leg");
    const model::JointId foot = doc.instance(leg)->joints[3].id;
    const Vec3 footBefore = worldOf(w, foot);
    click(outliner, itemNamed(outliner, "leg"));
    const QModelIndex neck = itemNamed(outliner, "neck");
    ASSERT_TRUE(neck.isValid());
    EXPECT_EQ(outliner->model()->rowCount(neck), 0) << "an unused default hook is not listed";
    dropOn(outliner, neck);
    EXPECT_EQ(doc.instance(leg)->parent, doc.instanceNamed("neck")->id);
    EXPECT_LT(glm::length(worldOf(w, foot) - footBefore), 1e-9);
    EXPECT_EQ(itemNamed(outliner, "leg").parent().data().toString(), "default") << "the used default hook is listed";
    EXPECT_EQ(itemNamed(outliner, "leg").parent().parent().data().toString(), "neck") << "the tree follows the document";

    // Delete both copies with the Delete key.
    click(outliner, itemNamed(outliner, "index1"));
    click(outliner, itemNamed(outliner, "ring1"), Qt::ControlModifier);
    QTest::keyClick(outliner, Qt::Key_Delete);
    EXPECT_EQ(doc.instanceNamed("index1"), nullptr);
    EXPECT_EQ(doc.instanceNamed("ring1"), nullptr);
    EXPECT_EQ(w.session().history().undoText(), "Remove 2 templates") << "one undo step";
    w.session().history().undo();
    EXPECT_NE(doc.instanceNamed("index1"), nullptr);
    EXPECT_NE(doc.instanceNamed("ring1"), nullptr);

    while (w.session().history().canUndo())
        w.session().history().undo();
    EXPECT_TRUE(w.session().document() == original);
}
