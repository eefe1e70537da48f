// Autosave and crash recovery (issue 7).
#include "EditorTestSupport.h"

#include <QAction>
#include <QAbstractButton>
#include <QApplication>
#include <QFile>
#include <QMessageBox>
#include <QTimer>

#include <fstream>

using namespace rs;

TEST(Autosave, AnAutosaveLeftByACrashIsOfferedAndRecoveredUnsaved)
{
    const std::string path = test::outputPath("autosaved.yml");
    std::filesystem::copy_file(RIGSMITH_SOURCE_DIR "/resources/samples/biped.yml", path,
                               std::filesystem::copy_options::overwrite_existing);
    const QString file = QString::fromStdString(path);
    QFile::remove(app::EditorSession::autosavePathFor(file));
    std::size_t edited = 0;
    {
        // A session edits and autosaves, then "crashes": its window never closes cleanly.
        auto* crashed = new app::MainWindow;
        ASSERT_NE(crashed->findChild<QTimer*>("autosaveTimer"), nullptr);
        EXPECT_EQ(crashed->findChild<QTimer*>("autosaveTimer")->interval(), 60000);
        ASSERT_TRUE(crashed->openFile(file));
        app::EditorSession& s = crashed->session();
        Diagnostics d;
        EXPECT_FALSE(s.autosave(d)) << "nothing unsaved, nothing written";
        ASSERT_TRUE(s.addTemplate("digit.finger", s.document().instanceNamed("arm")->joints[3].id).ok());
        edited = s.document().instances().size();
        ASSERT_TRUE(s.autosave(d)) << formatAll(d);
        EXPECT_TRUE(QFile::exists(s.autosavePath()));
        // leaked on purpose: a crash runs no destructor and no close event
    }
    ASSERT_TRUE(app::EditorSession::hasRecovery(file));

    test::Editor declined; // opens the biped sample, not this file
    QString offered;
    declined.window.setRecoveryPrompt([&](const QString& f, const QString&) { offered = f; return false; });
    ASSERT_TRUE(declined.window.openFile(file));
    EXPECT_EQ(offered, file);
    EXPECT_EQ(declined.window.session().document().instances().size(), edited - 1) << "the file as saved";
    EXPECT_TRUE(app::EditorSession::hasRecovery(file)) << "a declined autosave is not deleted";

    test::Editor editor;
    editor.window.setRecoveryPrompt([](const QString&, const QString&) { return true; });
    ASSERT_TRUE(editor.window.openFile(file));
    app::EditorSession& s = editor.window.session();
    EXPECT_EQ(s.document().instances().size(), edited) << "the autosaved edit is back";
    EXPECT_EQ(s.filePath(), file);
    EXPECT_FALSE(s.history().isClean()) << "recovered changes are unsaved";
    EXPECT_TRUE(editor.window.windowTitle().contains('*')) << editor.window.windowTitle().toStdString();
    editor.window.action("save")->trigger();
    EXPECT_TRUE(s.history().isClean());
    EXPECT_FALSE(QFile::exists(app::EditorSession::autosavePathFor(file))) << "saving removes the autosave";
    EXPECT_FALSE(app::EditorSession::hasRecovery(file));
}

TEST(Files, NewAsksBeforeDroppingUnsavedChanges)
{
    test::Editor editor;
    auto& w = editor.window;
    w.setProperty("skipUnsavedPrompt", false);
    app::EditorSession& s = w.session();
    ASSERT_TRUE(s.renameInstance(s.instanceNamed("neck"), "neck_main").ok());
    // Cancel the question box: the edited guide stays open.
    QTimer::singleShot(200, [] {
        if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget()))
            box->button(QMessageBox::Cancel)->click();
    });
    w.action("new:empty")->trigger();
    EXPECT_NE(s.instanceNamed("neck_main"), model::kNoId) << "cancelled: nothing lost";
    // Discard: the new guide replaces it.
    QTimer::singleShot(200, [] {
        if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget()))
            box->button(QMessageBox::Discard)->click();
    });
    w.action("new:empty")->trigger();
    EXPECT_TRUE(s.document().instances().empty());
    w.setProperty("skipUnsavedPrompt", true);
}

namespace {

// A copy of the biped sample at `name` in the test folder, without an autosave.
QString bipedCopy(const std::string& name)
{
    const std::string path = test::outputPath(name);
    std::filesystem::copy_file(RIGSMITH_SOURCE_DIR "/resources/samples/biped.yml", path,
                               std::filesystem::copy_options::overwrite_existing);
    QFile::remove(app::EditorSession::autosavePathFor(QString::fromStdString(path)));
    return QString::fromStdString(path);
}

QByteArray bytesOf(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace

// Issue 18 item 1: after undoing back to the saved state the autosave holds
// nothing newer; it is never offered (it would load the undone edits back).
TEST(Autosave, AnAutosaveUndoneBackToTheSavedStateIsNeverOffered)
{
    const QString file = bipedCopy("undone.yml");
    const QByteArray saved = bytesOf(file);
    auto* crashed = new app::MainWindow; // leaked on purpose: a crash runs no close event
    crashed->setRecoveryPrompt([](const QString&, const QString&) { ADD_FAILURE() << "no autosave yet"; return false; });
    ASSERT_TRUE(crashed->openFile(file));
    app::EditorSession& s = crashed->session();
    const std::size_t instances = s.document().instances().size();
    std::vector<model::InstanceId> all;
    for (const auto& instance : s.document().instances())
        all.push_back(instance.id);
    ASSERT_TRUE(s.removeInstances(all).ok()); // the rigger deletes everything...
    ASSERT_TRUE(s.document().instances().empty());
    Diagnostics d;
    ASSERT_TRUE(s.autosave(d)) << formatAll(d);
    while (!s.history().isClean()) // ...and undoes it all
        s.history().undo();
    ASSERT_EQ(s.document().instances().size(), instances);
    EXPECT_FALSE(QFile::exists(app::EditorSession::autosavePathFor(file))) << "undone to clean: the autosave is removed";
    EXPECT_FALSE(app::EditorSession::hasRecovery(file)) << "a crash now offers nothing";

    test::Editor next; // its prompt fails the test when asked
    ASSERT_TRUE(next.window.openFile(file));
    EXPECT_EQ(next.window.session().document().instances().size(), instances);
    EXPECT_EQ(bytesOf(file), saved);

    // An autosave that holds the very guide of the file (written by an older
    // Rigsmith, or killed mid-undo) is not offered either, and is removed on open.
    QFile stale(app::EditorSession::autosavePathFor(file));
    ASSERT_TRUE(stale.open(QIODevice::WriteOnly));
    stale.write(saved);
    stale.close();
    EXPECT_EQ(app::EditorSession::recoveryState(file), app::EditorSession::Recovery::NothingNewer);
    test::Editor again;
    ASSERT_TRUE(again.window.openFile(file));
    EXPECT_FALSE(QFile::exists(app::EditorSession::autosavePathFor(file)));
}

// An autosave made from the file as it was before another window (or the CLI)
// saved it would load older work over newer: it is kept but not offered.
TEST(Autosave, AnAutosaveOfAnOlderVersionOfTheFileIsNotOfferedOverIt)
{
    const QString file = bipedCopy("other-version.yml");
    auto* crashed = new app::MainWindow; // leaked: it crashes later
    crashed->setRecoveryPrompt([](const QString&, const QString&) { return false; });
    ASSERT_TRUE(crashed->openFile(file));
    app::EditorSession& s = crashed->session();
    ASSERT_TRUE(s.renameInstance(s.instanceNamed("neck"), "neck_old").ok());

    {
        test::Editor other; // a second window saves its own edit of the same file
        ASSERT_TRUE(other.window.openFile(file));
        app::EditorSession& o = other.window.session();
        ASSERT_TRUE(o.renameInstance(o.instanceNamed("neck"), "neck_new").ok());
        ASSERT_TRUE(other.window.saveFile(file));
    }
    const QByteArray newer = bytesOf(file);
    Diagnostics d;
    ASSERT_TRUE(s.autosave(d)) << formatAll(d); // written after that save, so newer by time
    EXPECT_EQ(app::EditorSession::recoveryState(file), app::EditorSession::Recovery::OtherVersion);

    test::Editor next;
    ASSERT_TRUE(next.window.openFile(file));
    EXPECT_NE(next.window.session().instanceNamed("neck_new"), model::kNoId) << "the file as saved last";
    EXPECT_EQ(bytesOf(file), newer);
    EXPECT_TRUE(QFile::exists(app::EditorSession::autosavePathFor(file))) << "kept: nothing is lost";
    QFile::remove(app::EditorSession::autosavePathFor(file));
}
