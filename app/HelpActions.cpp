// MainWindow's Help menu: About, the README and the selected template's help
// page (TemplateHelp.h), shown in one non-modal help window; the Options
// dock's help button opens the same page.
#include "MainWindow.h"

#include "ActionKit.h"
#include "TemplateHelp.h"
#include "base/Paths.h"

#include <QDialog>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QTextBrowser>
#include <QTextDocument>
#include <QUrl>
#include <QVBoxLayout>

namespace rs::app {

namespace {

QString text(const std::string& s) { return QString::fromStdString(s); }

} // namespace

void MainWindow::showTemplateHelp(const std::string& templateId)
{
    const auto* manifest = m_session.templates().find(templateId);
    if (!manifest) {
        showHelpText(tr("Template help"), tr("Template %1 is not loaded.").arg(text(templateId)));
        return;
    }
    QFile file(text(dataDirectory()) + "/templates/README.md");
    const QString readme = file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
    const TemplateHelpPage page = templateHelpPage(*manifest, m_session.templates(), readme);
    showHelpText(tr("Template %1").arg(text(manifest->id)), page.markdown, page.picture);
}

void MainWindow::showHelpText(const QString& title, const QString& markdown, const QImage& picture)
{
    auto* dialog = findChild<QDialog*>("helpDialog");
    if (!dialog) { // non-modal: it never blocks the editor (or a test)
        dialog = new QDialog(this);
        dialog->setObjectName("helpDialog");
        dialog->resize(760, 640);
        auto* layout = new QVBoxLayout(dialog);
        auto* browser = new QTextBrowser(dialog);
        browser->setObjectName("helpText");
        browser->setOpenExternalLinks(true);
        layout->addWidget(browser);
    }
    dialog->setWindowTitle(title);
    auto* browser = dialog->findChild<QTextBrowser*>("helpText");
    browser->setMarkdown(markdown); // clears the document's resources: the picture goes in after
    if (!picture.isNull()) {
        browser->document()->addResource(QTextDocument::ImageResource, QUrl(kTemplatePictureUrl), picture);
        browser->document()->markContentsDirty(0, browser->document()->characterCount());
    }
    dialog->show();
    dialog->raise();
}

void MainWindow::createHelpActions()
{
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->setObjectName("helpMenu");
    QAction* templateHelpAction = makeAction(this, "helpTemplate", tr("&Template Help"), QKeySequence::HelpContents);
    templateHelpAction->setToolTip(tr("The selected template's description and options (F1)"));
    connect(templateHelpAction, &QAction::triggered, this, [this] {
        const auto* instance = m_session.document().instance(m_session.selection().instance);
        if (!instance) {
            showHelpText(tr("Template help"), tr("Select a template instance (in the outliner or the viewport) to read "
                                                 "its template's help."));
            return;
        }
        showTemplateHelp(instance->templateId);
    });
    QAction* readme = makeAction(this, "helpReadme", tr("&README"), {});
    connect(readme, &QAction::triggered, this, [this] {
        QFile file(text(dataDirectory()) + "/README.md");
        showHelpText(tr("Rigsmith README"), file.open(QIODevice::ReadOnly)
                                                ? QString::fromUtf8(file.readAll())
                                                : tr("The README was not found at %1.").arg(file.fileName()));
    });
    QAction* about = makeAction(this, "helpAbout", tr("&About Rigsmith"), {});
    connect(about, &QAction::triggered, this, [this] {
        showHelpText(tr("About Rigsmith"),
                     tr("# Rigsmith\n\nA rig editor: place template guides (arms, legs, spines...), build the rig, "
                        "pose it as an animator would and export it to glTF or FBX.\n\n"
                        "Built with Qt %1. Data folder: `%2`.\n").arg(qVersion(), text(dataDirectory())));
    });
    help->addActions({templateHelpAction, readme});
    help->addSeparator();
    help->addAction(about);
}

} // namespace rs::app
