// Issue 20: the character's vertices coloured by the step that placed their
// weights (View > Display > Skin Chunk Steps, and the Skin Chunks dock), in
// the viewport outside weight painting: a sleeve remeshed with a flared cuff
// is re-fitted on open (its middle transferred, the cuff inpainted), the
// other arm's sleeve is loaded 1:1; a grab of the viewport shows the three
// colours where those vertices are.
#include "EditorTestSupport.h"

#include "SkinChunkPanel.h"
#include "ViewportWidget.h"

#include <QAction>
#include <QCheckBox>
#include <QImage>
#include <QLabel>

#include <fstream>

using namespace rs;
using namespace rs::test;

namespace {

struct Arm {
    Vec3 shoulder, wrist;
};

Arm armOf(app::MainWindow& w, bool right)
{
    if (!w.session().rig())
        w.buildRig();
    const model::Rig& rig = *w.session().rig();
    Arm arm{translationOf(rig.nodes[*rig.findPath("arm.L::skin.limb.0")].worldMatrix),
            translationOf(rig.nodes[*rig.findPath("arm.L::skin.limb.2")].worldMatrix)};
    if (right) {
        arm.shoulder.x = -arm.shoulder.x;
        arm.wrist.x = -arm.wrist.x;
    }
    return arm;
}

// A tube along the arm, its radius flaring from 5 cm to `cuff` over the last third.
QString writeTube(const Arm& arm, const std::string& file, const std::string& name, int rings, double cuff)
{
    const Vec3 axis = glm::normalize(arm.wrist - arm.shoulder);
    const Vec3 side = glm::normalize(glm::cross(axis, Vec3(0, 1, 0)));
    const Vec3 up = glm::cross(axis, side);
    const std::string path = outputPath(file);
    std::ofstream out(path);
    constexpr int kSides = 16;
    for (int r = 0; r < rings; ++r) {
        const double t = double(r) / (rings - 1);
        const double radius = t < 2.0 / 3.0 ? 0.05 : 0.05 + (cuff - 0.05) * (t - 2.0 / 3.0) * 3.0;
        for (int s = 0; s < kSides; ++s) {
            const double a = 6.283185307179586 * s / kSides;
            const Vec3 p = arm.shoulder + (arm.wrist - arm.shoulder) * t + radius * (std::cos(a) * side + std::sin(a) * up);
            out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
        }
    }
    out << "o " << name << '\n';
    for (int r = 0; r + 1 < rings; ++r)
        for (int s = 0; s < kSides; ++s) {
            const int i = r * kSides + s + 1, j = r * kSides + (s + 1) % kSides + 1;
            out << "f " << i << ' ' << j << ' ' << j + kSides << ' ' << i + kSides << '\n';
        }
    return QString::fromStdString(path);
}

enum class Hue { Green, Orange, Magenta, Other };

Hue hueOf(QRgb p)
{
    const double r = qRed(p), g = qGreen(p), b = qBlue(p);
    if (g > 40 && g > 1.8 * r && g > 1.8 * b)
        return Hue::Green;
    if (r > 60 && g > 0.25 * r && g < 0.85 * r && b < 0.25 * r)
        return Hue::Orange;
    if (r > 60 && b > 60 && g < 0.35 * std::min(r, b))
        return Hue::Magenta;
    return Hue::Other;
}

// How many pixels of `hue` lie within 6 pixels of where `world` is drawn.
int pixelsNear(const QImage& image, const viewport::ViewportWidget* view, const Vec3& world, Hue hue)
{
    const QPoint at = view->toWidgetPixels(world);
    int n = 0;
    for (int y = at.y() - 6; y <= at.y() + 6; ++y)
        for (int x = at.x() - 6; x <= at.x() + 6; ++x)
            if (image.valid(x, y) && hueOf(image.pixel(x, y)) == hue)
                ++n;
    return n;
}

} // namespace

TEST(RouteColours, TheViewportColoursEachVertexByTheStepThatPlacedItsWeights)
{
    Editor e;
    const Arm left = armOf(e.window, false), right = armOf(e.window, true);
    ASSERT_TRUE(e.window.addModel(writeTube(left, "route-sleeve.obj", "sleeve", 12, 0.05)));
    ASSERT_TRUE(e.window.addModel(writeTube(right, "route-other.obj", "other", 12, 0.05)));
    e.window.bindSkin();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !e.window.isBinding(); }, 20000));
    ASSERT_EQ(e.window.session().document().bindings.size(), 2u);
    e.window.setReloadPrompt([](const QString&) { return false; });
    const QString guide = QString::fromStdString(outputPath("route-colours.yml"));
    ASSERT_TRUE(e.window.saveFile(guide));
    writeTube(left, "route-sleeve.obj", "sleeve", 15, 0.16); // remeshed, its cuff flared far off the old one
    ASSERT_TRUE(e.window.openFile(guide));
    ASSERT_TRUE(QTest::qWaitFor([&] { return !e.window.isRefitting(); }, 30000));
    ASSERT_EQ(e.window.session().history().undoText(), "Re-fit weights of mesh 'sleeve'");
    e.window.action("modeRig")->trigger(); // bound meshes are drawn opaque and skinned

    widgets::SkinChunkPanel* panel = e.window.chunkPanel();
    EXPECT_TRUE(panel->routeLegend()->text().contains("inpainted"));
    QAction* steps = e.window.action("display:routes");
    ASSERT_NE(steps, nullptr);
    EXPECT_FALSE(steps->isChecked());
    panel->routeColours()->setChecked(true); // the dock's switch is the View menu's
    EXPECT_TRUE(steps->isChecked());
    EXPECT_TRUE(e.window.isShowingRoutes());

    // Only the meshes: a controller drawn over a sampled point (the elbow's pin,
    // the right side's hue-turned colours) is no vertex colour.
    e.window.action("display:controllers")->setChecked(false);
    e.window.action("display:skinJoints")->setChecked(false);
    viewport::ViewportWidget* view = e.window.viewportWidget();
    view->frameAll();
    QApplication::processEvents();
    const QImage shown = view->grab().toImage();
    shown.save(QString::fromStdString(outputPath("route-colours.png")));
    // The camera looks at the character's front: a tube's nearest point faces it.
    const Vec3 toCamera = glm::normalize(view->camera().position() - (left.shoulder + left.wrist) * 0.5);
    auto front = [&](const Arm& arm, double t, double radius) {
        return arm.shoulder + (arm.wrist - arm.shoulder) * t + radius * toCamera;
    };
    EXPECT_GT(pixelsNear(shown, view, front(right, 0.5, 0.05), Hue::Green), 20) << "the unchanged sleeve: loaded 1:1";
    EXPECT_GT(pixelsNear(shown, view, front(left, 0.35, 0.05), Hue::Orange), 20) << "the re-fitted sleeve where it did not move: transferred";
    EXPECT_GT(pixelsNear(shown, view, front(left, 0.97, 0.15), Hue::Magenta), 20) << "the flared cuff: inpainted";
    EXPECT_EQ(pixelsNear(shown, view, front(right, 0.5, 0.05), Hue::Magenta), 0);

    steps->trigger(); // off: the materials again
    EXPECT_FALSE(panel->routeColours()->isChecked());
    QApplication::processEvents();
    const QImage plain = view->grab().toImage();
    EXPECT_EQ(pixelsNear(plain, view, front(left, 0.97, 0.15), Hue::Magenta), 0) << "no colours with the switch off";
    EXPECT_EQ(pixelsNear(plain, view, front(right, 0.5, 0.05), Hue::Green), 0);
}
