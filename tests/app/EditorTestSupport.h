#pragma once
// Shared by the GUI tests: the editor window opened on the biped sample, and
// where tests write their outputs (screenshots, saved guides).
#include "MainWindow.h"
#include "ViewportWidget.h"

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
        // A stray autosave of the sample must fail the test, not wait on a question box.
        window.setRecoveryPrompt([](const QString& file, const QString& autosave) {
            ADD_FAILURE() << "unexpected recovery prompt for " << file.toStdString() << " (" << autosave.toStdString() << ")";
            return false;
        });
        window.show();
        EXPECT_TRUE(QTest::qWaitForWindowExposed(&window));
        EXPECT_TRUE(window.openFile(kSample));
    }
};

// Drags the gizmo's handle `axis` from `from` to `to` handle lengths out along
// it, as a mouse would; false when no gizmo is shown.
inline bool dragGizmoHandle(viewport::ViewportWidget* view, int axis, double from = 0.6, double to = 1.6)
{
    const auto gizmo = view->gizmo();
    if (!gizmo)
        return false;
    const QPoint handle = view->toWidgetPixels(gizmo->origin() + gizmo->axis(axis) * gizmo->size * from);
    const QPoint further = view->toWidgetPixels(gizmo->origin() + gizmo->axis(axis) * gizmo->size * to);
    QTest::mousePress(view, Qt::LeftButton, {}, handle);
    QTest::mouseMove(view, (handle + further) / 2);
    QTest::mouseMove(view, further);
    QTest::mouseRelease(view, Qt::LeftButton, {}, further);
    return true;
}

} // namespace rs::test
