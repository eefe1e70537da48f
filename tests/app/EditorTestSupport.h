#pragma once
// Shared by the GUI tests: the editor window opened on the biped sample, and
// where tests write their outputs (screenshots, saved guides).
#include "MainWindow.h"
#include "LogPanel.h"
#include "ViewportWidget.h"

#include <QListWidgetItem>

#include <QTest>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
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

// An OBJ tube of `rings` rings of `sides` around the left arm, shoulder to
// wrist (builds the rig first); `mirrored`: with its mirror image across
// x = 0, as one mesh ("sleeves").
inline QString writeSleeve(app::MainWindow& w, const std::string& name, int rings, int sides = 10, bool mirrored = false)
{
    if (!w.session().rig())
        w.buildRig();
    const model::Rig& rig = *w.session().rig();
    const Vec3 a = translationOf(rig.nodes[*rig.findPath("arm.L::skin.limb.0")].worldMatrix);
    const Vec3 b = translationOf(rig.nodes[*rig.findPath("arm.L::skin.limb.2")].worldMatrix);
    const Vec3 axis = glm::normalize(b - a);
    const Vec3 side = glm::normalize(glm::cross(axis, Vec3(0, 1, 0)));
    const Vec3 up = glm::cross(axis, side);
    const std::string path = outputPath(name);
    std::ofstream out(path);
    const int halves = mirrored ? 2 : 1;
    for (int half = 0; half < halves; ++half)
        for (int r = 0; r < rings; ++r)
            for (int s = 0; s < sides; ++s) {
                const double t = 6.283185307179586 * s / sides;
                Vec3 p = a + (b - a) * (double(r) / (rings - 1)) + 0.05 * (std::cos(t) * side + std::sin(t) * up);
                if (half == 1)
                    p.x = -p.x;
                out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
            }
    out << (mirrored ? "o sleeves\n" : "o sleeve\n");
    for (int half = 0; half < halves; ++half)
        for (int r = 0; r + 1 < rings; ++r)
            for (int s = 0; s < sides; ++s) {
                const int base = half * rings * sides + 1;
                const int i = base + r * sides + s, j = base + r * sides + (s + 1) % sides;
                out << "f " << i << ' ' << j << ' ' << j + sides << ' ' << i + sides << '\n';
            }
    return QString::fromStdString(path);
}

inline bool logSays(app::MainWindow& w, const QString& text)
{
    for (int i = 0; i < w.log()->count(); ++i)
        if (w.log()->item(i)->text().contains(text))
            return true;
    return false;
}


} // namespace rs::test
