// rigsmith: the editor.
//   rigsmith [GUIDE]                     open a guide (default: none)
//   rigsmith --screenshot OUT.png [GUIDE]  load, build, render the window, save it, exit
//   rigsmith --startup-time [GUIDE]      print how long it took until the window with
//                                        the guide loaded showed its first frame, exit
//   rigsmith --edit-latency GUIDE        replay 100 guide drags, print the median and
//                                        worst time from an edit to a repainted frame, exit
//   rigsmith --edit-latency --drag CONTROLLER GUIDE   the same in Rig mode: 100 drags
//                                        rotating the controller (a rig path, "arm.L::ctrls.fk.0")
// Screenshot and latency setup (applied after the guide is built):
//   --rig                                 Rig mode
//   --set CONTROLLER.CHANNEL=VALUE        set a channel ("arm.L::ctrls.switch.ik_blend=0")
//                                         before the poses (repeatable, Rig mode)
//   --pose CONTROLLER=RX,RY,RZ            set a controller's rotation (degrees); it stays
//                                         selected (repeatable, Rig mode)
//   --frame X0,Y0,Z0,X1,Y1,Z1             frame this box (metres) instead of everything
//   --action NAME                         trigger an action by object name, e.g.
//                                         weights:selected, skinning:dualQuaternion (repeatable)
//   --chunks FILE                         the Skin Chunks dock previewing an import of FILE, each
//                                         vertex coloured by the step it would take (1:1, transferred,
//                                         inpainted; View > Display > Skin Chunk Steps)
//   --stroke X0,Y0,Z0,X1,Y1,Z1            with --action paintWeights: drag a paint stroke with the
//                                         mouse from one world point's pixel to the other's (what
//                                         lies under them is painted), the brush left at the end
#include "EditLatency.h"
#include "MainWindow.h"
#include "SkinChunkPanel.h"

#include "ViewportWidget.h"

#include <QAction>
#include <QMouseEvent>
#include <QApplication>
#include <QPalette>
#include <QStyleFactory>
#include <QTimer>

#include <QElapsedTimer>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace {

void applyDarkTheme(QApplication& app)
{
    app.setStyle(QStyleFactory::create("Fusion"));
    QPalette p;
    p.setColor(QPalette::Window, QColor(45, 47, 51));
    p.setColor(QPalette::WindowText, QColor(220, 220, 220));
    p.setColor(QPalette::Base, QColor(32, 34, 37));
    p.setColor(QPalette::AlternateBase, QColor(40, 42, 46));
    p.setColor(QPalette::Text, QColor(220, 220, 220));
    p.setColor(QPalette::Button, QColor(52, 54, 58));
    p.setColor(QPalette::ButtonText, QColor(220, 220, 220));
    p.setColor(QPalette::Highlight, QColor(64, 120, 200));
    p.setColor(QPalette::HighlightedText, Qt::white);
    p.setColor(QPalette::ToolTipBase, QColor(32, 34, 37));
    p.setColor(QPalette::ToolTipText, QColor(220, 220, 220));
    p.setColor(QPalette::Disabled, QPalette::Text, QColor(120, 120, 120));
    p.setColor(QPalette::Disabled, QPalette::ButtonText, QColor(120, 120, 120));
    app.setPalette(p);
}

// Milliseconds since the process started (Linux: from /proc), so the dynamic
// loading of Qt before main() counts too; -1 when unknown.
double msSinceProcessStart()
{
    std::ifstream statFile("/proc/self/stat"), uptimeFile("/proc/uptime");
    std::string stat((std::istreambuf_iterator<char>(statFile)), std::istreambuf_iterator<char>());
    double uptime = 0.0;
    const auto close = stat.rfind(')');
    if (close == std::string::npos || !(uptimeFile >> uptime))
        return -1.0;
    std::istringstream fields(stat.substr(close + 2));
    std::string field;
    for (int i = 3; i < 22 && fields >> field; ++i) {} // field 22 is starttime, in clock ticks after boot
    double startTicks = 0.0;
    if (!(fields >> startTicks))
        return -1.0;
    return (uptime - startTicks / double(sysconf(_SC_CLK_TCK))) * 1000.0;
}

// --startup-time: reports when the viewport has drawn its first frame.
int reportStartup(QApplication& app, rs::app::MainWindow& window, const QElapsedTimer& sinceMain)
{
    QObject::connect(window.viewportWidget(), &rs::viewport::ViewportWidget::frameSwapped, &window, [&] {
        const nlohmann::json report{{"ms_since_main", std::round(sinceMain.nsecsElapsed() / 1e5) / 10.0},
                                    {"ms_since_process_start", std::round(msSinceProcessStart())},
                                    {"templates", window.session().document().instances().size()}};
        std::printf("%s\n", report.dump().c_str());
        std::fflush(stdout);
        window.setProperty("skipUnsavedPrompt", true);
        app.quit();
    }, Qt::SingleShotConnection);
    return app.exec();
}

// The values of every `option VALUE` pair in `args`, removed from it.
QStringList takeAll(QStringList& args, const QString& option)
{
    QStringList values;
    for (int at = args.indexOf(option); at >= 0 && at + 1 < args.size(); at = args.indexOf(option)) {
        values << args.at(at + 1);
        args.remove(at, 2);
    }
    return values;
}

// --rig, --set, --pose, --action: what a screenshot or a measurement shows.
bool applySetup(rs::app::MainWindow& window, bool rigMode, const QStringList& sets, const QStringList& poses,
                const QStringList& actions)
{
    auto& session = window.session();
    if (rigMode || !poses.isEmpty() || !sets.isEmpty())
        session.setMode(rs::app::EditorMode::Rig);
    for (const QString& set : sets) {
        const QString target = set.section('=', 0, 0);
        const auto* rig = session.rig();
        const auto node = rig ? rig->findPath(target.section('.', 0, -2).toStdString()) : std::nullopt;
        const auto channel = node && session.program()
                                 ? session.program()->channels().find(*node, target.section('.', -1).toStdString())
                                 : std::nullopt;
        const rs::Status status = channel ? session.setChannel(*channel, set.section('=', 1).toDouble(), false)
                                          : rs::Status::refused("no such controller or channel");
        if (status.failed()) {
            std::fprintf(stderr, "rigsmith: --set %s: %s\n", qPrintable(set), rs::formatAll(status.diagnostics()).c_str());
            return false;
        }
    }
    for (const QString& pose : poses) {
        const QStringList parts = pose.split('=');
        const QStringList angles = parts.value(1).split(',');
        const auto* rig = session.rig();
        const auto node = rig ? rig->findPath(parts.value(0).toStdString()) : std::nullopt;
        if (!node || angles.size() != 3) {
            std::fprintf(stderr, "rigsmith: --pose %s: no such controller, or not RX,RY,RZ\n", qPrintable(pose));
            return false;
        }
        session.selectControllers({*node}, false);
        for (int axis = 0; axis < 3; ++axis) {
            const auto channel = session.program()->channels().find(*node, std::string("r") + char('x' + axis));
            const rs::Status set = channel ? session.setChannel(*channel, angles[axis].toDouble(), false)
                                           : rs::Status::refused("no rotate channel");
            if (set.failed())
                std::fprintf(stderr, "rigsmith: --pose %s: %s\n", qPrintable(pose), rs::formatAll(set.diagnostics()).c_str());
        }
    }
    for (const QString& name : actions) {
        QAction* a = window.findChild<QAction*>(name);
        if (!a) {
            std::fprintf(stderr, "rigsmith: --action %s: no such action\n", qPrintable(name));
            return false;
        }
        a->trigger();
    }
    return true;
}

// --chunks: the Skin Chunks dock previewing an import of the files (its
// report, the vertices it would transfer selected) and inspecting the first.
bool previewChunks(QApplication& app, rs::app::MainWindow& window, const QStringList& files)
{
    if (QAction* dock = window.findChild<QAction*>("skinChunks"); dock && !dock->isChecked())
        dock->trigger();
    window.chunkPanel()->setImportFiles(files);
    window.importSkinChunks(files, true);
    while (window.isImportingChunks())
        app.processEvents(QEventLoop::AllEvents, 50);
    window.inspectSkinChunks(files.front());
    if (QAction* steps = window.findChild<QAction*>("display:routes"); steps && !steps->isChecked())
        steps->trigger(); // each vertex coloured by the step the preview took
    return true;
}

// --stroke: the left button dragged across the viewport as a rigger would.
void dragStroke(rs::viewport::ViewportWidget* view, const QStringList& numbers)
{
    if (numbers.size() != 6) {
        std::fprintf(stderr, "rigsmith: --stroke needs X0,Y0,Z0,X1,Y1,Z1\n");
        return;
    }
    const QPointF from = view->toWidgetPixels({numbers[0].toDouble(), numbers[1].toDouble(), numbers[2].toDouble()});
    const QPointF to = view->toWidgetPixels({numbers[3].toDouble(), numbers[4].toDouble(), numbers[5].toDouble()});
    auto send = [view](QEvent::Type type, QPointF at, Qt::MouseButton button, Qt::MouseButtons buttons) {
        QMouseEvent event(type, at, view->mapToGlobal(at), button, buttons, Qt::NoModifier);
        QApplication::sendEvent(view, &event);
    };
    send(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    constexpr int kSteps = 24;
    for (int i = 1; i <= kSteps; ++i)
        send(QEvent::MouseMove, from + (to - from) * (double(i) / kSteps), Qt::NoButton, Qt::LeftButton);
    send(QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
    send(QEvent::MouseMove, to, Qt::NoButton, Qt::NoButton); // hovering: the brush circle
}

} // namespace

// Printed without a display (no QApplication is made for it).
const char* kUsage =
    "usage: rigsmith [GUIDE]                     open a guide (default: an empty one)\n"
    "       rigsmith --screenshot OUT.png [GUIDE]   load, build, render the window, save it, exit\n"
    "       rigsmith --startup-time [GUIDE]      print how long until the window showed the guide (JSON), exit\n"
    "       rigsmith --edit-latency GUIDE        replay 100 guide drags, print the median and worst\n"
    "                                            edit-to-frame time (JSON), exit\n"
    "       rigsmith --edit-latency --drag CONTROLLER GUIDE   the same in Rig mode, rotating CONTROLLER\n"
    "                                            (a rig path, \"arm.L::ctrls.fk.0\")\n"
    "screenshot and latency setup (applied after the guide is built):\n"
    "  --rig                          Rig mode\n"
    "  --set CONTROLLER.CHANNEL=VALUE set a channel (\"arm.L::ctrls.switch.ik_blend=0\"), repeatable\n"
    "  --pose CONTROLLER=RX,RY,RZ     set a controller's rotation in degrees, repeatable\n"
    "  --frame X0,Y0,Z0,X1,Y1,Z1      frame this box (metres) instead of everything\n"
    "  --action NAME                  trigger an action by object name (weights:selected...), repeatable\n"
    "  --chunks FILE                  the Skin Chunks dock previewing an import of FILE (repeatable), each vertex\n"
    "                                 coloured by its step (1:1, transferred, inpainted)\n"
    "The headless command line (build, bind, export) is rigsmith-cli.\n";

int main(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i)
        if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
            std::fputs(kUsage, stdout);
            return 0;
        }
    QElapsedTimer sinceMain;
    sinceMain.start();
    rs::viewport::requestOpenGl33Core();
    // A window's requested repaint waits for Qt's idle timer (5 ms by default)
    // unless the platform paces frames itself; the viewport repaints only after
    // an edit or a camera move, so it draws at the next turn of the event loop
    // (an edit reaches the screen up to 5 ms sooner). The variable still wins.
    if (!qEnvironmentVariableIsSet("QT_QPA_UPDATE_IDLE_TIME"))
        qputenv("QT_QPA_UPDATE_IDLE_TIME", "0");
    QApplication app(argc, argv);
    QApplication::setApplicationName("Rigsmith");
    applyDarkTheme(app);

    QStringList args = app.arguments().mid(1);
    QString screenshot;
    if (const int at = args.indexOf("--screenshot"); at >= 0) {
        if (at + 1 >= args.size()) {
            std::fprintf(stderr, "usage: rigsmith --screenshot OUT.png [GUIDE]\n");
            return 2;
        }
        screenshot = args.at(at + 1);
        args.remove(at, 2);
    }

    const bool rigMode = args.removeAll("--rig") > 0;
    const QStringList sets = takeAll(args, "--set");
    const QStringList poses = takeAll(args, "--pose");
    const QStringList actions = takeAll(args, "--action");
    const QStringList drags = takeAll(args, "--drag");
    const QStringList frame = takeAll(args, "--frame");
    const QStringList strokes = takeAll(args, "--stroke");
    const QStringList chunkFiles = takeAll(args, "--chunks");
    const bool startupTime = args.removeAll("--startup-time") > 0;
    const bool editLatency = args.removeAll("--edit-latency") > 0;
    if (editLatency && args.isEmpty()) {
        std::fprintf(stderr, "usage: rigsmith --edit-latency GUIDE\n");
        return 2;
    }
    rs::app::MainWindow window;
    if (!screenshot.isEmpty() || startupTime || editLatency)
        window.setRecoveryPrompt([](const QString&, const QString&) { return false; }); // never asks
    if (!args.isEmpty() && !window.openFile(args.front()) && !screenshot.isEmpty())
        return 1;
    window.show();
    if (startupTime)
        return reportStartup(app, window, sinceMain);
    if (editLatency) {
        if (!window.session().document().instances().size())
            return 1;
        QTimer::singleShot(0, &window, [&] {
            for (const QString& name : actions) // what is drawn while measuring (display:meshes...)
                if (QAction* a = window.findChild<QAction*>(name))
                    a->trigger();
            const int status = drags.isEmpty() ? rs::app::reportEditLatency(window)
                                               : rs::app::reportRigEditLatency(window, drags.front().toStdString());
            window.setProperty("skipUnsavedPrompt", true);
            QApplication::exit(status);
        });
        return app.exec();
    }
    if (screenshot.isEmpty()) {
        if (args.isEmpty())
            window.offerUntitledRecovery();
        return app.exec();
    }

    window.buildRig();
    while (window.isRefitting()) // changed meshes re-fitted on open (a worker thread) before the picture
        app.processEvents(QEventLoop::AllEvents, 50);
    if (!applySetup(window, rigMode, sets, poses, actions))
        return 1;
    if (!chunkFiles.isEmpty() && !previewChunks(app, window, chunkFiles))
        return 1;
    window.viewportWidget()->frameAll();
    if (const QStringList box = frame.value(0).split(','); box.size() == 6) {
        auto* view = window.viewportWidget();
        view->camera().frame({box[0].toDouble(), box[1].toDouble(), box[2].toDouble()},
                             {box[3].toDouble(), box[4].toDouble(), box[5].toDouble()}, double(view->width()) / view->height());
        view->update();
    }
    QTimer::singleShot(250, &window, [&] { // once the viewport has its size
        for (const QString& stroke : strokes)
            dragStroke(window.viewportWidget(), stroke.split(','));
    });
    int status = 1;
    QTimer::singleShot(800, &window, [&] {
        const QImage image = window.grab().toImage();
        status = image.save(screenshot) ? 0 : 1;
        if (status != 0)
            std::fprintf(stderr, "rigsmith: cannot write %s\n", qPrintable(screenshot));
        window.setProperty("skipUnsavedPrompt", true);
        app.quit();
    });
    app.exec();
    return status;
}
