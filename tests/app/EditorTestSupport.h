#pragma once
// Shared by the GUI tests: the editor window opened on the biped sample, and
// where tests write their outputs (screenshots, saved guides).
#include "MainWindow.h"

#include <QTest>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace rs::test {

inline const QString kSample = QString(RIGSMITH_SOURCE_DIR) + "/resources/samples/biped.yml";

inline std::string outputPath(const std::string& name)
{
    const auto dir = std::filesystem::temp_directory_path() / "rigsmith-editor-tests";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

struct Editor {
    app::MainWindow window;
    Editor()
    {
        window.setProperty("skipUnsavedPrompt", true);
        window.show();
        EXPECT_TRUE(QTest::qWaitForWindowExposed(&window));
        EXPECT_TRUE(window.openFile(kSample));
    }
};

} // namespace rs::test
