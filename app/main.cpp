// rigsmith: the editor.
//   rigsmith [GUIDE]                     open a guide (default: none)
//   rigsmith --screenshot OUT.png [GUIDE]  load, build, render the window, save it, exit
#include "MainWindow.h"

#include "ViewportWidget.h"

#include <QApplication>
#include <QPalette>
#include <QStyleFactory>
#include <QTimer>

#include <cstdio>

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

} // namespace

int main(int argc, char** argv)
{
    rs::viewport::requestOpenGl33Core();
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

    rs::app::MainWindow window;
    if (!screenshot.isEmpty())
        window.setRecoveryPrompt([](const QString&, const QString&) { return false; }); // never asks
    if (!args.isEmpty() && !window.openFile(args.front()) && !screenshot.isEmpty())
        return 1;
    window.show();
    if (screenshot.isEmpty()) {
        if (args.isEmpty())
            window.offerUntitledRecovery();
        return app.exec();
    }

    window.buildRig();
    window.viewportWidget()->frameAll();
    int status = 1;
    QTimer::singleShot(500, &window, [&] {
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
