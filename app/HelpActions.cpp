// MainWindow's Help menu: About, the README and the selected template's help
// (its description, link and options), shown in one non-modal help window.
#include "MainWindow.h"

#include "ActionKit.h"
#include "base/Paths.h"

#include <QDialog>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace rs::app {

namespace {

QString text(const std::string& s) { return QString::fromStdString(s); }

QString parameterRows(const std::vector<templates::Parameter>& parameters)
{
    QString rows;
    for (const templates::Parameter& p : parameters) {
        QString values = text(formatValue(p.value));
        if (p.isEnum()) {
            QStringList labels;
            for (const auto& [index, label] : p.enumLabels)
                labels << text(label);
            values += " (" + labels.join(", ") + ")";
        } else if (p.min || p.max) {
            values += QString(" (%1 to %2)").arg(p.min ? QString::number(*p.min) : "-inf", p.max ? QString::number(*p.max) : "inf");
        }
        rows += QString("| `%1` | %2 | %3 |\n").arg(text(p.name), values, text(p.help).replace('|', '/'));
    }
    return rows;
}

QString templateHelp(const templates::TemplateManifest& m)
{
    QString md = QString("# %1\n\n%2\n\n").arg(text(m.id), text(m.desc));
    if (!m.help.empty())
        md += QString("More: <%1>\n\n").arg(text(m.help));
    for (const auto& [title, parameters] : {std::pair{QObject::tr("Guide parameters"), &m.guides},
                                             std::pair{QObject::tr("Options"), &m.opts}})
        if (!parameters->empty())
            md += QString("## %1\n\n| name | default | help |\n|---|---|---|\n%2\n").arg(title, parameterRows(*parameters));
    md += QString("\nManifest: `%1`\n").arg(text(m.file));
    return md;
}

} // namespace

void MainWindow::showHelpText(const QString& title, const QString& markdown)
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
    dialog->findChild<QTextBrowser*>("helpText")->setMarkdown(markdown);
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
        const auto* manifest = instance ? m_session.templates().find(instance->templateId) : nullptr;
        if (!manifest) {
            showHelpText(tr("Template help"), tr("Select a template instance (in the outliner or the viewport) to read "
                                                 "its template's help."));
            return;
        }
        showHelpText(tr("Template %1").arg(text(manifest->id)), templateHelp(*manifest));
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
