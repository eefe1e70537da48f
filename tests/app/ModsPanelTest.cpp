// The Mods dock, driven through its widgets: Add (a kind's sample for the
// chosen owner) then Apply adds a mod and the live rig follows; a mistake in
// the text is shown with its line and column and changes nothing; editing a
// mod's text and Apply changes it; Delete removes it; each is one undo step.
#include "EditorTestSupport.h"

#include "ModsPanel.h"

#include <QAction>
#include <QDockWidget>
#include <QApplication>
#include <QLabel>
#include <QMenu>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QToolButton>
#include <QTreeWidget>

using namespace rs;
using namespace rs::test;

namespace {

struct Built {
    Editor e;
    app::MainWindow& w = e.window;
    widgets::ModsPanel* panel = w.modsPanel();
    Built() { w.action("build")->trigger(); }
    const model::RigNode& node(const std::string& id) const { return w.session().rig()->nodes[*w.session().rig()->findPath(id)]; }
    void click(const char* button) { QTest::mouseClick(panel->findChild<QPushButton*>(button), Qt::LeftButton); }
    void addKind(const char* kind)
    {
        auto* add = panel->findChild<QToolButton*>("modAdd");
        ASSERT_TRUE(add && add->menu());
        QAction* action = add->menu()->findChild<QAction*>(QString("modAdd:") + kind);
        ASSERT_TRUE(action) << kind;
        action->trigger();
    }
    void type(const QString& text) { panel->editor()->setPlainText(text); }
};

} // namespace

TEST(ModsPanel, AddEditAndDeleteAModThroughTheDockAndTheRigFollows)
{
    Built t;
    ASSERT_TRUE(t.panel);
    EXPECT_TRUE(t.w.session().document().mods.empty());
    ASSERT_TRUE(t.panel->chooseOwner("arm"));
    t.addKind("hide");
    EXPECT_EQ(t.panel->editor()->toPlainText(), "hide: [ctrls.pv]\n"); // the sample, for the chosen instance
    t.type("hide: [ctrls.pole]");
    t.click("modApply");
    ASSERT_EQ(t.w.session().document().mods.size(), 1u);
    EXPECT_EQ(t.w.session().document().mods[0].owner.id, 4u);
    EXPECT_TRUE(t.node("arm.L::ctrls.pole").hidden);
    EXPECT_TRUE(t.node("arm.R::ctrls.pole").hidden);
    EXPECT_EQ(t.panel->currentMod(), std::optional<std::size_t>(0)); // the new mod stays selected
    ASSERT_EQ(t.panel->tree()->topLevelItemCount(), 2); // Global, arm
    EXPECT_EQ(t.panel->tree()->topLevelItem(1)->text(0), "arm");
    EXPECT_EQ(t.panel->tree()->topLevelItem(1)->child(0)->text(0), "hide  ctrls.pole");

    // A mistake: shown at its line and column; the mod and the rig stay.
    t.type("hide: [ctrls.pole\nspace: 3");
    t.click("modApply");
    EXPECT_TRUE(t.panel->errorLabel()->text().startsWith("line ")) << t.panel->errorLabel()->text().toStdString();
    EXPECT_TRUE(t.node("arm.L::ctrls.pole").hidden);
    EXPECT_EQ(t.w.session().history().undoText(), "Add hide mod");

    t.type("hide: [ctrls.pin]");
    t.click("modApply");
    EXPECT_TRUE(t.panel->errorLabel()->text().isEmpty());
    EXPECT_FALSE(t.node("arm.L::ctrls.pole").hidden);
    EXPECT_TRUE(t.node("arm.L::ctrls.pin").hidden);
    EXPECT_EQ(t.w.session().history().undoText(), "Edit hide mod");
    EXPECT_EQ(t.panel->editor()->toPlainText(), "hide: [ctrls.pin]\n");

    t.click("modDelete");
    EXPECT_TRUE(t.w.session().document().mods.empty());
    EXPECT_FALSE(t.node("arm.L::ctrls.pin").hidden);
    t.w.action("undo")->trigger();
    ASSERT_EQ(t.w.session().document().mods.size(), 1u);
    EXPECT_TRUE(t.node("arm.L::ctrls.pin").hidden);
    EXPECT_EQ(t.panel->tree()->topLevelItem(1)->childCount(), 1);
}

TEST(ModsPanel, AGlobalModNamesItsInstanceAndAMissingNodeIsLoggedNotRefused)
{
    Built t;
    ASSERT_TRUE(t.panel->chooseOwner("Global"));
    t.addKind("vdag");
    EXPECT_TRUE(t.panel->editor()->toPlainText().contains("arm.L::ctrls.ik"));
    t.type("vdag: {node: 'hand.L::ctrls.hand', parent: 'spine::ctrls.nope'}");
    t.click("modApply");
    ASSERT_EQ(t.w.session().document().mods.size(), 1u); // kept
    EXPECT_TRUE(t.w.session().document().mods[0].isGlobal());
    bool logged = false;
    for (const Diagnostic& d : t.w.session().rig()->diagnostics)
        logged = logged || d.message.find("global vdag mod: parent 'spine::ctrls.nope'") != std::string::npos;
    EXPECT_TRUE(logged);
}

TEST(ModsPanel, ScreenshotOfTheDockWithTheTestGuidesMods)
{
    Editor e;
    app::MainWindow& w = e.window;
    ASSERT_TRUE(w.openFile(QString(RIGSMITH_TEST_DATA) + "/Mods/biped/guide.yml"));
    w.action("build")->trigger();
    auto* dock = w.findChild<QDockWidget*>("modsDock");
    ASSERT_NE(dock, nullptr);
    dock->show();
    dock->raise();
    w.resizeDocks({dock}, {380}, Qt::Vertical);
    widgets::ModsPanel* panel = w.modsPanel();
    EXPECT_EQ(panel->tree()->topLevelItemCount(), 3); // Global, arm, hand
    panel->selectMod(0);
    EXPECT_TRUE(panel->editor()->toPlainText().startsWith("space:\n  node: ctrls.ik\n"));
    QApplication::processEvents();
    const QImage shot = w.grab().toImage();
    EXPECT_FALSE(shot.isNull());
    EXPECT_TRUE(shot.save(QString::fromStdString(outputPath("mods-panel.png"))));
}
