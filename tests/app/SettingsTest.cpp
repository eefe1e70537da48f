// What the editor keeps between runs (issue 7): the dock layout and recent files.
#include "EditorTestSupport.h"
#include "Settings.h"

#include <QDockWidget>
#include <QMenu>
#include <QSettings>

using namespace rs;

TEST(Settings, LayoutAndRecentFilesAreKeptBetweenRuns)
{
    QSettings("Rigsmith", "rigsmith").clear();
    {
        test::Editor editor; // opens the biped sample
        EXPECT_EQ(app::settings::recentFiles().value(0), QFileInfo(test::kSample).absoluteFilePath());
        editor.window.findChild<QDockWidget*>("libraryDock")->hide();
        editor.window.close(); // saves the layout
    }
    {
        test::Editor editor;
        EXPECT_FALSE(editor.window.findChild<QDockWidget*>("libraryDock")->isVisible()) << "the layout came back";
        auto* recent = editor.window.findChild<QMenu*>("recentMenu");
        ASSERT_NE(recent, nullptr);
        emit recent->aboutToShow();
        ASSERT_FALSE(recent->actions().isEmpty());
        EXPECT_EQ(recent->actions().first()->text(), QFileInfo(test::kSample).absoluteFilePath());
        editor.window.findChild<QDockWidget*>("libraryDock")->show();
        editor.window.close();
    }
    QSettings("Rigsmith", "rigsmith").clear();
}
