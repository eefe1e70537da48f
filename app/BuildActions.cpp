// MainWindow's build and export: Build (Ctrl+B) with its progress bar and
// status line, and File > Export, straight to a path or through the export
// dialog (its path following the guide, its progress and report).
#include "MainWindow.h"

#include "ExportDialog.h"
#include "LogPanel.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QProgressBar>
#include <QStatusBar>

namespace rs::app {

bool MainWindow::exportTo(const QString& path)
{
    io::ExportRequest request;
    request.path = path.toStdString();
    return exportRig(request);
}

bool MainWindow::exportRig(const io::ExportRequest& request)
{
    if (!m_session.rig() || m_session.isRigStale())
        buildRig();
    auto* dialog = m_exportDialog && m_exportDialog->isVisible() ? m_exportDialog : nullptr;
    const Diagnostics diagnostics = m_session.exportRig(request, [dialog](double fraction) {
        if (dialog) {
            dialog->setProgress(fraction);
            QCoreApplication::processEvents(QEventLoop::ExcludeUserInputEvents);
        }
        return true;
    });
    if (dialog)
        dialog->showReport(diagnostics);
    const QString path = QString::fromStdString(request.path);
    report(hasErrors(diagnostics) ? tr("Export failed") : tr("Exported %1").arg(path), diagnostics);
    if (hasErrors(diagnostics) && !dialog)
        showWriteFailure(tr("Could not export %1.").arg(path), diagnostics);
    return !hasErrors(diagnostics);
}

widgets::ExportDialog* MainWindow::exportDialog()
{
    if (!m_exportDialog) {
        m_exportDialog = new widgets::ExportDialog(this);
        connect(m_exportDialog, &widgets::ExportDialog::exportRequested, this,
                [this](const io::ExportRequest& request) { exportRig(request); });
    }
    // The path follows the guide: <guide folder>/<guide name>.glb, made again
    // for each guide opened or saved under another name (a path typed for
    // this guide is kept).
    const QString guide = m_session.filePath() + "|" + QString::fromStdString(m_session.document().name);
    if (guide != m_exportDialogGuide) {
        const QFileInfo file(m_session.filePath());
        const QString folder = m_session.filePath().isEmpty() ? QDir::currentPath() : file.absolutePath();
        const QString name = m_session.document().name.empty() ? file.completeBaseName()
                                                                : QString::fromStdString(m_session.document().name);
        m_exportDialog->setPath(QDir(folder).filePath((name.isEmpty() ? tr("rig") : name) + ".glb"));
        m_exportDialogGuide = guide;
    }
    return m_exportDialog;
}

void MainWindow::showBuildProgress(double fraction, const QString& stage)
{
    // The build is synchronous: paint the bar and message now (no event loop
    // runs until it ends), once a build has run 100 ms and then at most every
    // 100 ms, so a build of a few milliseconds never pays for a repaint (a
    // window repaint costs more than a biped's build on software GL).
    const bool done = fraction >= 1.0;
    m_buildProgress->setVisible(!done);
    m_buildProgress->setValue(int(fraction * 1000.0));
    if (done && statusBar()->currentMessage().startsWith(tr("Building: ").trimmed()))
        statusBar()->clearMessage(); // a build that ended never leaves its last stage behind
    if (done || !m_buildPainted.isValid() || m_buildPainted.elapsed() < 100)
        return;
    statusBar()->showMessage(tr("Building: %1...").arg(stage));
    statusBar()->repaint();
    m_buildPainted.start();
}

void MainWindow::buildRig()
{
    m_buildPainted.start(); // the first paint waits 100 ms
    const double ms = m_session.build();
    m_buildProgress->hide();
    const auto* rig = m_session.rig();
    m_log->addMessage(tr("Built %1 nodes in %2 ms").arg(rig->nodes.size()).arg(ms, 0, 'f', 2),
                      hasErrors(rig->diagnostics) ? Severity::Error : Severity::Note);
    std::size_t errors = 0, warnings = 0;
    for (const Diagnostic& d : rig->diagnostics)
        (d.severity == Severity::Error ? errors : warnings) += d.severity != Severity::Note ? 1 : 0;
    statusBar()->showMessage(tr("Build: %1 ms, %2 errors, %3 warnings (details in the build log)")
                                 .arg(ms, 0, 'f', 2).arg(errors).arg(warnings), 8000);
    m_session.setMode(EditorMode::Rig); // a build is for checking the rig as an animator will use it
}

} // namespace rs::app
