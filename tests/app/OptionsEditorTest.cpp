// The options dock driven through its real widgets (issue 7).
#include "EditorTestSupport.h"
#include "OptionsEditor.h"

#include <QAction>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QDockWidget>
#include <QLineEdit>
#include <QMenu>
#include "OutlinerView.h"
#include <QSpinBox>
#include <QToolButton>

using namespace rs;

namespace {

// Selects the instance named `name` and lets the options dock show it.
model::InstanceId showOptionsOf(app::MainWindow& w, const QString& name)
{
    const auto id = w.session().instanceNamed(name);
    w.session().select(app::Selection::ofInstance(id));
    QApplication::processEvents();
    return id;
}

} // namespace

TEST(OptionsEditor, EditsOptionsAndGuideParametersAsUndoableSteps)
{
    test::Editor editor;
    auto& w = editor.window;
    const model::GuideDocument original = w.session().document();
    const auto spine = showOptionsOf(w, "spine");
    widgets::OptionsEditor* options = w.optionsEditor();
    ASSERT_EQ(options->instance(), spine);

    // A boolean option: one click, one undo step, shown bold with its reset button.
    auto* stretch = qobject_cast<QCheckBox*>(options->editorFor("stretch"));
    ASSERT_NE(stretch, nullptr);
    EXPECT_TRUE(stretch->isChecked());
    EXPECT_FALSE(options->findChild<QToolButton*>("reset:stretch")->isEnabled());
    stretch->click();
    QApplication::processEvents();
    EXPECT_EQ(w.session().document().instance(spine)->options.at("stretch"), Value(false));
    auto* reset = options->findChild<QToolButton*>("reset:stretch");
    ASSERT_NE(reset, nullptr);
    EXPECT_TRUE(reset->isEnabled()) << "a changed option can be reset";
    EXPECT_EQ(w.session().history().undoText(), "Set option stretch");

    // A guide parameter regenerates the guide joints.
    auto* number = qobject_cast<QSpinBox*>(options->editorFor("number"));
    ASSERT_NE(number, nullptr);
    EXPECT_EQ(number->minimum(), 3);
    EXPECT_EQ(number->maximum(), 12);
    EXPECT_FALSE(number->toolTip().isEmpty()) << "help as the tooltip";
    number->setValue(7);
    QApplication::processEvents();
    EXPECT_EQ(w.session().document().instance(spine)->joints.size(), 7u);
    EXPECT_EQ(w.session().history().undoText(), "Set guide option number");
    w.action("build")->trigger();
    ASSERT_NE(w.session().rig(), nullptr);
    EXPECT_FALSE(hasErrors(w.session().rig()->diagnostics)) << formatAll(w.session().rig()->diagnostics);
    w.findChild<QDockWidget*>("optionsDock")->grab().save(QString::fromStdString(test::outputPath("options-dock.png")));

    // Reset, then undo everything back to the start.
    options->findChild<QToolButton*>("reset:stretch")->click();
    QApplication::processEvents();
    EXPECT_EQ(w.session().document().instance(spine)->options.count("stretch"), 0u);
    while (w.action("undo")->isEnabled())
        w.action("undo")->trigger();
    EXPECT_TRUE(w.session().document() == original);
}

TEST(OptionsEditor, OutlinerMirrorsAndResetsOptionsAsUndoableSteps)
{
    test::Editor editor;
    auto& w = editor.window;
    const model::GuideDocument original = w.session().document();
    const auto neck = w.session().instanceNamed("neck");
    std::unique_ptr<QMenu> menu(w.outliner()->createContextMenu(neck, &w));
    auto* mirror = menu->findChild<QAction*>("mirror");
    ASSERT_NE(mirror, nullptr);
    EXPECT_FALSE(mirror->isChecked());
    EXPECT_FALSE(menu->findChild<QAction*>("resetOptions")->isEnabled()) << "nothing to reset yet";
    mirror->trigger();
    EXPECT_EQ(w.session().document().instance(neck)->options.at("branches"), Value(std::string("[L, R]")));

    menu.reset(w.outliner()->createContextMenu(neck, &w));
    EXPECT_TRUE(menu->findChild<QAction*>("mirror")->isChecked());
    menu->findChild<QAction*>("resetOptions")->trigger();
    EXPECT_TRUE(w.session().document().instance(neck)->options.empty());
    EXPECT_EQ(w.session().history().undoText(), "Reset options of neck");
    while (w.action("undo")->isEnabled())
        w.action("undo")->trigger();
    EXPECT_TRUE(w.session().document() == original);
}

TEST(OptionsEditor, NameOverridesRenameTheBuiltControls)
{
    test::Editor editor;
    auto& w = editor.window;
    const model::GuideDocument original = w.session().document();
    const auto arm = showOptionsOf(w, "arm");
    auto* ik = qobject_cast<QLineEdit*>(w.optionsEditor()->editorFor("name:ik"));
    ASSERT_NE(ik, nullptr);
    EXPECT_EQ(ik->placeholderText(), "ik") << "the template's name shows as the placeholder";
    ik->setFocus();
    QTest::keyClicks(ik, "hand");
    QTest::keyClick(ik, Qt::Key_Return);
    QApplication::processEvents();
    EXPECT_EQ(w.session().document().instance(arm)->names.at("ik"), "hand");
    EXPECT_EQ(w.session().history().undoText(), "Name ik of arm");
    w.action("build")->trigger();
    ASSERT_NE(w.session().rig(), nullptr);
    const auto control = w.session().rig()->findPath("arm.L::ctrls.ik");
    ASSERT_TRUE(control.has_value());
    EXPECT_EQ(w.session().rig()->nodes[*control].name, "c_arm_hand_L");

    EXPECT_TRUE(w.session().setNameOverride(arm, "ik", "bad name!").failed()) << "refused, nothing changes";
    EXPECT_EQ(w.session().history().size(), 1u);
    w.action("undo")->trigger();
    EXPECT_TRUE(w.session().document() == original);
}

// A guide's number is read as it is written: the robot's `ik_blend: 0` is an
// integer in a float option, which the dock edits as the number it is (it
// crashed the editor when the robot's arm was selected).
TEST(OptionsEditor, AFloatOptionWrittenAsAnIntegerEditsAsANumber)
{
    test::Editor editor;
    auto& w = editor.window;
    ASSERT_TRUE(w.openFile(QString(RIGSMITH_SOURCE_DIR) + "/resources/samples/robot.yml"));
    const auto arm = showOptionsOf(w, "arm");
    ASSERT_EQ(w.session().document().instance(arm)->options.at("ik_blend"), Value(0LL)) << "the sample writes it so";
    QWidget* holder = w.optionsEditor()->editorFor("ik_blend");
    ASSERT_NE(holder, nullptr);
    auto* box = holder->findChild<QDoubleSpinBox*>();
    ASSERT_NE(box, nullptr);
    EXPECT_EQ(box->value(), 0.0);
    EXPECT_TRUE(w.optionsEditor()->findChild<QToolButton*>("reset:ik_blend")->isEnabled()) << "changed from 1";
    box->setValue(0.25);
    QApplication::processEvents();
    EXPECT_EQ(w.session().document().instance(arm)->options.at("ik_blend"), Value(0.25));
}
