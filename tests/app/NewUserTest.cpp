// Issue 18, items 14-17: the editor tried as a new user would. The wheel over
// a panel scrolls it, the channel box gives the keyboard back, a guide that
// fails to open says why in a box, the export path and the saved name follow
// the guide, enum options are combo boxes and ranges show at the field.
#include "EditorTestSupport.h"

#include "ChannelBox.h"
#include "ExportDialog.h"
#include "OptionsEditor.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QStatusBar>
#include <QWheelEvent>

#include <fstream>

using namespace rs;
using namespace rs::test;

namespace {

void showOptionsOf(app::MainWindow& w, const QString& name)
{
    w.session().select(app::Selection::ofInstance(w.session().instanceNamed(name)));
    QApplication::processEvents();
}

void turnWheel(QWidget* widget, int notches)
{
    const QPointF at(widget->width() / 2.0, widget->height() / 2.0);
    QWheelEvent wheel(at, widget->mapToGlobal(at), QPoint(), QPoint(0, 120 * notches), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(widget, &wheel);
}

} // namespace

TEST(NewUser, WheelOverAnUnfocusedOptionFieldLeavesItsValue)
{
    Editor e;
    app::MainWindow& w = e.window;
    w.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
    showOptionsOf(w, "arm");
    auto* twist = qobject_cast<QSpinBox*>(w.optionsEditor()->editorFor("twist_upper"));
    ASSERT_NE(twist, nullptr);
    const int before = twist->value();
    const std::size_t steps = w.session().history().index();
    turnWheel(twist, 1); // scrolling the panel past it
    EXPECT_EQ(twist->value(), before);
    EXPECT_EQ(w.session().history().index(), steps) << "no edit from scrolling";
    EXPECT_EQ(twist->focusPolicy(), Qt::StrongFocus) << "the wheel does not focus it";

    // Another GUI test on the same X display may hold the focus for a moment.
    w.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
    twist->setFocus();
    QTRY_VERIFY(twist->hasFocus());
    turnWheel(twist, 1); // a focused field takes the wheel
    EXPECT_EQ(twist->value(), before + 1);
}

TEST(NewUser, ChannelBoxGivesTheKeyboardBackToTheViewportAfterAnEdit)
{
    Editor e;
    app::MainWindow& w = e.window;
    w.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
    w.action("build")->trigger();
    const model::Rig* rig = w.session().rig();
    const auto elbow = *rig->findPath("arm.L::ctrls.fk.1");
    // The arm is in IK by default, where its FK controls are hidden (and so not pickwalked): switch it to FK.
    const auto blend = w.session().program()->channels().find(*rig->findPath("arm.L::ctrls.switch"), "ik_blend");
    ASSERT_TRUE(blend.has_value());
    ASSERT_TRUE(w.session().setChannel(*blend, 0.0, false).ok());
    w.session().selectControllers({elbow}, false);
    QApplication::processEvents();
    const int rz = *w.session().program()->channels().find(elbow, "rz");
    auto* spin = qobject_cast<QDoubleSpinBox*>(w.channelBox()->editorFor(rz));
    ASSERT_NE(spin, nullptr);
    auto* wheelProbe = spin;
    const double rest = spin->value();
    turnWheel(wheelProbe, 2);
    EXPECT_EQ(spin->value(), rest) << "the wheel over an unfocused channel changes nothing";

    spin->setFocus();
    QTest::keyClick(spin, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(spin, "30");
    QTest::keyClick(spin, Qt::Key_Return);
    EXPECT_EQ(w.session().history().undoText(), "Set c_arm2_L.rz");
    EXPECT_EQ(QApplication::focusWidget(), w.viewportWidget()) << "Enter hands the keyboard back";

    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Up); // pickwalk works again
    EXPECT_NE(w.session().selection().node, elbow);
}

TEST(NewUser, AGuideThatFailsToOpenSaysWhereInABox)
{
    Editor e;
    app::MainWindow& w = e.window;
    QString title, text;
    w.setErrorPrompt([&](const QString& t, const QString& m) { title = t, text = m; });
    const std::string path = outputPath("broken-guide.yml");
    std::ofstream(path) << "version: 2\nname: broken\ninstances:\n  - template: core.joints\n    name: [unclosed\n";
    const std::size_t before = w.session().document().instances().size();
    EXPECT_FALSE(w.openFile(QString::fromStdString(path)));
    EXPECT_EQ(w.session().document().instances().size(), before) << "the open guide is unchanged";
    EXPECT_FALSE(title.isEmpty()) << "a box, not only the log";
    EXPECT_TRUE(text.contains(QString::fromStdString(path) + ":")) << text.toStdString();
    EXPECT_TRUE(text.contains(QRegularExpression(":\\d+:\\d+: error"))) << "file:line:column " << text.toStdString();
    for (QChar c : text)
        EXPECT_TRUE(c.isPrint() || c == '\n') << "stray character U+" << std::hex << int(c.unicode()) << " in " << text.toStdString();
}

TEST(NewUser, ExportPathAndSavedNameFollowTheGuide)
{
    Editor e;
    app::MainWindow& w = e.window;
    const QString samples = QFileInfo(kSample).absolutePath();
    EXPECT_EQ(QString::fromStdString(w.exportDialog()->request().path), samples + "/biped.glb");
    w.exportDialog()->setPath("/tmp/typed-for-biped.glb"); // kept while the guide stays
    EXPECT_EQ(w.exportDialog()->request().path, "/tmp/typed-for-biped.glb");
    ASSERT_TRUE(w.openFile(samples + "/quadruped.yml"));
    EXPECT_EQ(QString::fromStdString(w.exportDialog()->request().path), samples + "/quadruped.glb");

    w.action("new:empty")->trigger();
    ASSERT_TRUE(w.session().addTemplate("core.joints", model::kNoId).ok());
    const QString saved = QString::fromStdString(outputPath("hero.yml"));
    ASSERT_TRUE(w.saveFile(saved));
    EXPECT_EQ(w.session().document().name, "hero") << "not 'untitled'";
    QFile file(saved);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_TRUE(file.readAll().contains("name: hero"));
    EXPECT_EQ(QString::fromStdString(w.exportDialog()->request().path), QFileInfo(saved).absolutePath() + "/hero.glb");
}

TEST(NewUser, EnumOptionsAreComboBoxesAndNumbersShowTheirRange)
{
    Editor e;
    app::MainWindow& w = e.window;
    showOptionsOf(w, "arm");
    auto* space = qobject_cast<QComboBox*>(w.optionsEditor()->editorFor("ik_space"));
    ASSERT_NE(space, nullptr) << "an enum is a combo box, not free text";
    QStringList items;
    for (int i = 0; i < space->count(); ++i)
        items << space->itemText(i);
    EXPECT_EQ(items.join(",").toStdString(), "world,root,cog,chest,head");
    EXPECT_EQ(space->currentText(), "world");
    space->setCurrentIndex(3);
    emit space->activated(3);
    QApplication::processEvents();
    EXPECT_EQ(w.session().document().instanceNamed("arm")->options.at("ik_space"), Value(std::string("chest")));

    auto* twist = qobject_cast<QSpinBox*>(w.optionsEditor()->editorFor("twist_upper"));
    auto* range = w.optionsEditor()->findChild<QLabel*>("range:twist_upper");
    ASSERT_NE(twist, nullptr);
    ASSERT_NE(range, nullptr);
    EXPECT_EQ(range->text(), QString("0 \u2026 8")) << "the range is visible";
    auto* line = twist->findChild<QLineEdit*>();
    line->selectAll();
    QTest::keyClicks(line, "15");
    EXPECT_TRUE(twist->property("rangeError").toBool()) << "out of range shows at the field";
    EXPECT_TRUE(range->text().contains("outside")) << range->text().toStdString();
    line->selectAll();
    QTest::keyClicks(line, "5");
    EXPECT_FALSE(twist->property("rangeError").toBool());
}
