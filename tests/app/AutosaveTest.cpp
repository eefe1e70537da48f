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
