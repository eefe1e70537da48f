// Overrides in the editor, driven through the real widgets: the channel box's
// Set as Default / Reset / Lock / Keyable / Limit on the selected channels of
// the selected controllers (one undo step each), Rig > Restore on Build, and
// the Overrides dock (by instance, filter, orphans, delete, re-target, delete
// all orphans, a click selects the node).
#include "EditorTestSupport.h"

#include "ChannelBox.h"
#include "LimitDialog.h"
#include "OverridesPanel.h"

#include <QAction>
#include <QApplication>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QPushButton>
#include <QTreeWidget>

using namespace rs;
using namespace rs::test;

namespace {

struct Built {
    Editor e;
    app::MainWindow& w = e.window;
    model::RigNodeIndex left = 0, right = 0;
    Built()
    {
        w.action("build")->trigger();
        EXPECT_EQ(w.session().mode(), app::EditorMode::Rig);
        left = *w.session().rig()->findPath("arm.L::ctrls.fk.0");
        right = *w.session().rig()->findPath("arm.R::ctrls.fk.0");
    }
    NodeKey key(model::RigNodeIndex node) const { return w.session().rig()->nodes[node].key; }
    int channel(model::RigNodeIndex node, const std::string& name) const
    {
        return *w.session().program()->channels().find(node, name);
    }
    const eval::Channel& compiled(model::RigNodeIndex node, const std::string& name) const
    {
        return w.session().program()->channels()[channel(node, name)];
    }
    // The channel box shows `left` (the current controller), both selected.
    void selectBoth()
    {
        w.session().selectControllers({right, left}, false);
        QApplication::processEvents();
    }
    QLabel* label(const std::string& name) const { return w.channelBox()->labelFor(channel(left, name)); }
    void click(const std::string& name, Qt::KeyboardModifiers modifiers = {})
    {
        QLabel* l = label(name);
        ASSERT_NE(l, nullptr) << name;
        QTest::mouseClick(l, Qt::LeftButton, modifiers, l->rect().center());
    }
};

} // namespace

TEST(ChannelBoxOverrides, LockKeyableAndLimitTheSelectedChannelsOfEverySelectedController)
{
    Built t;
    t.selectBoth();
    t.click("rx");
    t.click("ry", Qt::ControlModifier);
    EXPECT_EQ(t.w.channelBox()->selectedChannels(), (QStringList{"rx", "ry"}));
    EXPECT_TRUE(t.label("ry")->property("selected").toBool());

    const std::size_t steps = t.w.session().history().size();
    t.w.channelBox()->channelAction("channelLock")->trigger();
    EXPECT_EQ(t.w.session().history().size(), steps + 1);
    EXPECT_EQ(t.w.session().history().undoText(), "Lock 4 channels");
    for (auto node : {t.left, t.right})
        for (const char* c : {"rx", "ry"}) {
            EXPECT_TRUE(t.compiled(node, c).locked) << c;
            EXPECT_TRUE(t.w.session().document().overrides.at(t.key(node)).locks.at(c).locked);
        }
    EXPECT_FALSE(t.compiled(t.left, "rz").locked);
    QApplication::processEvents();
    // Shown: the name marked locked, its editor disabled; the selection kept.
    EXPECT_TRUE(t.label("rx")->property("locked").toBool());
    EXPECT_FALSE(t.label("rz")->property("locked").toBool());
    EXPECT_FALSE(t.w.channelBox()->editorFor(t.channel(t.left, "rx"))->isEnabled());
    EXPECT_EQ(t.w.channelBox()->selectedChannels(), (QStringList{"rx", "ry"}));

    t.w.channelBox()->channelAction("channelNonKeyable")->trigger();
    EXPECT_FALSE(t.compiled(t.right, "ry").keyable);
    EXPECT_TRUE(t.compiled(t.right, "ry").locked) << "the lock stays";
    QApplication::processEvents();
    EXPECT_FALSE(t.label("rx")->property("keyable").toBool());
    t.w.channelBox()->channelAction("channelUnlock")->trigger();
    t.w.channelBox()->channelAction("channelKeyable")->trigger();
    EXPECT_FALSE(t.compiled(t.right, "rx").locked);
    EXPECT_TRUE(t.compiled(t.right, "rx").keyable);

    // Limit...: the dialog; a bad range cannot be confirmed; OK limits all four.
    t.w.channelBox()->channelAction("channelLimit")->trigger();
    auto* dialog = t.w.channelBox()->findChild<widgets::LimitDialog*>("limitDialog");
    ASSERT_NE(dialog, nullptr);
    dialog->setRange(10.0, -10.0);
    auto* ok = dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    EXPECT_FALSE(ok->isEnabled());
    dialog->findChild<QDoubleSpinBox*>("limitMin")->setValue(-30.0);
    dialog->findChild<QDoubleSpinBox*>("limitMax")->setValue(45.0);
    ASSERT_TRUE(ok->isEnabled());
    QTest::mouseClick(ok, Qt::LeftButton);
    EXPECT_EQ(t.w.session().document().overrides.at(t.key(t.right)).limits.at("ry"), (model::ChannelLimit{-30.0, 45.0}));
    EXPECT_TRUE(t.compiled(t.left, "rx").limited);
    EXPECT_EQ(t.compiled(t.left, "rx").max, 45.0);
    t.w.channelBox()->channelAction("channelRemoveLimit")->trigger();
    EXPECT_FALSE(t.compiled(t.left, "rx").limited);
    EXPECT_EQ(t.w.session().history().size(), steps + 6);
    // Undo walks back one action at a time, the first one last.
    for (int i = 0; i < 6; ++i)
        t.w.action("undo")->trigger();
    EXPECT_FALSE(t.w.session().document().overrides.count(t.key(t.left)));
    EXPECT_FALSE(t.compiled(t.right, "rx").locked);
}

TEST(ChannelBoxOverrides, SetAsDefaultMarksTheChannelAndResetReturnsToIt)
{
    Built t;
    t.selectBoth();
    ASSERT_TRUE(t.w.session().setChannel(t.channel(t.left, "rz"), 30.0, false).ok());
    ASSERT_TRUE(t.w.session().setChannel(t.channel(t.right, "rz"), -20.0, false).ok());
    QApplication::processEvents();
    t.click("rz");
    // Right-clicking a name that is not selected selects it (the menu acts on it).
    QTest::mousePress(t.label("tx"), Qt::RightButton, {}, t.label("tx")->rect().center());
    EXPECT_EQ(t.w.channelBox()->selectedChannels(), QStringList{"tx"});
    t.click("rz");
    const std::size_t steps = t.w.session().history().size();
    t.w.channelBox()->channelAction("channelSetDefault")->trigger();
    EXPECT_EQ(t.w.session().history().size(), steps + 1);
    EXPECT_EQ(t.w.session().document().overrides.at(t.key(t.left)).defaults.at("rz"), 30.0);
    EXPECT_EQ(t.w.session().document().overrides.at(t.key(t.right)).defaults.at("rz"), -20.0);
    EXPECT_EQ(t.compiled(t.right, "rz").defaultValue, -20.0);
    QApplication::processEvents();
    EXPECT_TRUE(t.label("rz")->property("defaultOverridden").toBool());
    EXPECT_FALSE(t.label("ry")->property("defaultOverridden").toBool());
    EXPECT_NE(t.label("rz")->toolTip().indexOf("30"), -1) << t.label("rz")->toolTip().toStdString();

    auto* spin = qobject_cast<QDoubleSpinBox*>(t.w.channelBox()->editorFor(t.channel(t.left, "rz")));
    ASSERT_NE(spin, nullptr);
    spin->setValue(5.0);
    ASSERT_TRUE(t.w.session().setChannel(t.channel(t.right, "rz"), 7.0, false).ok());
    t.w.channelBox()->channelAction("channelResetDefault")->trigger();
    EXPECT_EQ(t.w.session().history().undoText(), "Reset 2 channels");
    EXPECT_EQ(t.w.session().pose()[t.channel(t.left, "rz")], 30.0);
    EXPECT_EQ(t.w.session().pose()[t.channel(t.right, "rz")], -20.0);
    QApplication::processEvents();
    spin = qobject_cast<QDoubleSpinBox*>(t.w.channelBox()->editorFor(t.channel(t.left, "rz")));
    ASSERT_NE(spin, nullptr);
    EXPECT_EQ(spin->value(), 30.0);
}

TEST(ChannelBoxOverrides, RestoreMenuTurnsAKindOffAndOnAndRebuilds)
{
    Built t;
    QMenu* menu = t.w.findChild<QMenu*>("restoreMenu");
    ASSERT_NE(menu, nullptr);
    EXPECT_EQ(menu->actions().size(), model::kOverrideKindCount);
    for (QAction* a : menu->actions())
        EXPECT_TRUE(a->isChecked()) << a->objectName().toStdString();
    ASSERT_TRUE(t.w.session().editChannels({t.channel(t.left, "tx")}, session::Session::ChannelEdit::Lock).ok());
    ASSERT_TRUE(t.compiled(t.left, "tx").locked);
    t.w.action("restore:locks")->trigger();
    EXPECT_FALSE(t.w.session().restore().restores(model::OverrideKind::Locks));
    EXPECT_FALSE(t.compiled(t.left, "tx").locked) << "rebuilt without the locks";
    EXPECT_TRUE(t.w.session().document().overrides.at(t.key(t.left)).locks.count("tx")) << "the record stays";
    t.w.action("restore:locks")->trigger();
    EXPECT_TRUE(t.compiled(t.left, "tx").locked);
}

TEST(ChannelBoxOverrides, CleanUpOnBuildHidesWhatAnimatorsShouldNotTouchAndUndoUnchecksIt)
{
    Built t;
    QAction* cleanup = t.w.action("rig:cleanup");
    ASSERT_NE(cleanup, nullptr);
    EXPECT_FALSE(cleanup->isChecked()) << "off by default";
    const std::size_t steps = t.w.session().history().size();
    cleanup->trigger();
    EXPECT_TRUE(t.w.session().cleanup());
    EXPECT_EQ(t.w.session().history().size(), steps + 1);
    t.left = *t.w.session().rig()->findPath("arm.L::ctrls.fk.0");
    EXPECT_TRUE(t.compiled(t.left, "tx").locked);
    EXPECT_TRUE(t.compiled(t.left, "tx").hidden);
    EXPECT_FALSE(t.compiled(t.left, "rx").locked);
    t.selectBoth();
    EXPECT_EQ(t.label("tx"), nullptr) << "a hidden channel has no row";
    EXPECT_NE(t.label("rx"), nullptr);
    t.w.action("undo")->trigger();
    QApplication::processEvents();
    EXPECT_FALSE(t.w.session().cleanup());
    EXPECT_FALSE(cleanup->isChecked()) << "the menu follows the undo";
    t.left = *t.w.session().rig()->findPath("arm.L::ctrls.fk.0");
    EXPECT_FALSE(t.compiled(t.left, "tx").locked);
    // An undone restore toggle unchecks its action too.
    t.w.action("restore:names")->trigger();
    EXPECT_FALSE(t.w.action("restore:names")->isChecked());
    t.w.action("undo")->trigger();
    EXPECT_TRUE(t.w.action("restore:names")->isChecked());
}

TEST(OverridesPanel, ListsRecordsByInstanceFiltersAndAClickSelectsTheNode)
{
    Built t;
    model::Override limits;
    limits.limits = {{"rx", {-5.0, 5.0}}};
    model::Override name;
    name.displayName = "shoulder_twist_ctl";
    ASSERT_TRUE(t.w.session().setOverride(t.key(t.left), limits).ok());
    ASSERT_TRUE(t.w.session().setOverride(t.key(t.right), name).ok());
    widgets::OverridesPanel* panel = t.w.overridesPanel();
    QTreeWidgetItem* left = panel->itemOf(t.key(t.left));
    QTreeWidgetItem* right = panel->itemOf(t.key(t.right));
    ASSERT_NE(left, nullptr);
    ASSERT_NE(right, nullptr);
    EXPECT_EQ(left->parent()->text(0), "arm.L");
    EXPECT_EQ(right->parent()->text(0), "arm.R");
    EXPECT_EQ(right->text(0).left(18), "shoulder_twist_ctl");
    ASSERT_EQ(left->childCount(), 1);
    EXPECT_EQ(left->child(0)->text(0), "limits");
    EXPECT_EQ(left->text(1), "applied");

    panel->findChild<QLineEdit*>("overridesFilter")->setText("limits");
    EXPECT_NE(panel->itemOf(t.key(t.left)), nullptr);
    EXPECT_EQ(panel->itemOf(t.key(t.right)), nullptr);
    panel->setFilter({});

    t.w.session().select({});
    QTreeWidget* tree = panel->tree();
    tree->scrollToItem(panel->itemOf(t.key(t.right)));
    QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, tree->visualItemRect(panel->itemOf(t.key(t.right))).center());
    EXPECT_EQ(t.w.session().selection().node, t.right);
}

TEST(OverridesPanel, OrphansAreMarkedRetargetedDeletedAndDeletedAllAtOnce)
{
    Built t;
    const NodeKey gone{t.key(t.left).instance, "L", "ctrls.fk.9"};
    const NodeKey gone2{t.key(t.left).instance, "L", "ctrls.fk.8"};
    model::Override record;
    record.limits = {{"rz", {-15.0, 15.0}}};
    record.locks = {{"tx", {true, true}}};
    ASSERT_TRUE(t.w.session().setOverride(gone, record).ok());
    widgets::OverridesPanel* panel = t.w.overridesPanel();
    QTreeWidgetItem* item = panel->itemOf(gone);
    ASSERT_NE(item, nullptr);
    EXPECT_TRUE(item->text(1).startsWith("orphan: ")) << item->text(1).toStdString();
    EXPECT_NE(item->text(1).indexOf("ctrls.fk.9"), -1);
    EXPECT_EQ(item->foreground(0).color(), QColor(230, 140, 40)) << "orphans show in orange";

    // Re-target... onto the left FK shoulder: the record moves, one undo step.
    panel->tree()->setCurrentItem(item);
    const std::size_t steps = t.w.session().history().size();
    QTest::mouseClick(panel->findChild<QPushButton*>("overridesRetarget"), Qt::LeftButton);
    auto* dialog = panel->findChild<QDialog*>("retargetDialog");
    ASSERT_NE(dialog, nullptr);
    auto* list = dialog->findChild<QListWidget*>("retargetList");
    const QString target = "arm.L / " + QString::fromStdString(t.w.session().rig()->nodes[t.left].name);
    dialog->findChild<QLineEdit*>("retargetFilter")->setText(target);
    const auto found = list->findItems(target, Qt::MatchExactly);
    ASSERT_EQ(found.size(), 1);
    list->setCurrentItem(found.front());
    dialog->accept();
    ASSERT_EQ(t.w.session().history().size(), steps + 1);
    ASSERT_TRUE(t.w.session().document().overrides.count(t.key(t.left)));
    EXPECT_FALSE(t.w.session().document().overrides.count(gone));
    EXPECT_EQ(t.w.session().document().overrides.at(t.key(t.left)).limits.at("rz"), (model::ChannelLimit{-15.0, 15.0}));
    EXPECT_TRUE(t.compiled(t.left, "tx").locked);
    ASSERT_NE(panel->itemOf(t.key(t.left)), nullptr);
    EXPECT_EQ(panel->itemOf(t.key(t.left))->text(1), "applied");

    // Delete one kind only: select the "locks" row.
    QTreeWidgetItem* applied = panel->itemOf(t.key(t.left));
    panel->tree()->clearSelection();
    for (int i = 0; i < applied->childCount(); ++i)
        applied->child(i)->setSelected(applied->child(i)->text(0) == "locks");
    QTest::mouseClick(panel->findChild<QPushButton*>("overridesDelete"), Qt::LeftButton);
    ASSERT_TRUE(t.w.session().document().overrides.count(t.key(t.left))) << "only the locks were deleted";
    EXPECT_FALSE(t.w.session().document().overrides.at(t.key(t.left)).locks.count("tx"));
    EXPECT_TRUE(t.w.session().document().overrides.at(t.key(t.left)).limits.count("rz"));

    // Two orphans, deleted at once; the applied record stays.
    ASSERT_TRUE(t.w.session().setOverride(gone, record).ok());
    ASSERT_TRUE(t.w.session().setOverride(gone2, record).ok());
    const std::size_t before = t.w.session().history().size();
    auto* all = panel->findChild<QPushButton*>("overridesDeleteOrphans");
    ASSERT_TRUE(all->isEnabled());
    QTest::mouseClick(all, Qt::LeftButton);
    EXPECT_EQ(t.w.session().history().size(), before + 1);
    EXPECT_EQ(t.w.session().history().undoText(), "Delete all orphans");
    EXPECT_FALSE(t.w.session().document().overrides.count(gone));
    EXPECT_FALSE(t.w.session().document().overrides.count(gone2));
    EXPECT_TRUE(t.w.session().document().overrides.count(t.key(t.left)));
    EXPECT_FALSE(all->isEnabled());
    t.w.action("undo")->trigger();
    EXPECT_NE(panel->itemOf(gone2), nullptr) << "undo brings them back, and the panel follows";
}

TEST(OverridesPanel, ScreenshotWithTheDockOpen)
{
    Built t;
    model::Override record;
    record.limits = {{"rx", {-5.0, 5.0}}};
    record.defaults = {{"rz", 12.0}};
    ASSERT_TRUE(t.w.session().setOverride(t.key(t.left), record).ok());
    record.displayName = "gone_ctl";
    ASSERT_TRUE(t.w.session().setOverride(NodeKey{t.key(t.left).instance, "L", "ctrls.fk.9"}, record).ok());
    t.selectBoth();
    t.click("rx");
    auto* dock = t.w.findChild<QDockWidget*>("overridesDock");
    ASSERT_NE(dock, nullptr);
    dock->show();
    dock->raise();
    t.w.resizeDocks({dock}, {320}, Qt::Vertical);
    QApplication::processEvents();
    const QImage shot = t.w.grab().toImage();
    EXPECT_FALSE(shot.isNull());
    EXPECT_TRUE(shot.save(QString::fromStdString(outputPath("overrides-panel.png"))));
}
