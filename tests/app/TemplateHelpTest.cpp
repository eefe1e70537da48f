// The template help pages (issue 22 item 8): one per template, with what it
// builds (templates/README.md), a picture of its built rig, its hooks and its
// options; opened from the Help menu and the Options dock's "?" button.
#include "EditorTestSupport.h"
#include "OptionsEditor.h"
#include "TemplateHelp.h"

#include <QDialog>
#include <QFile>
#include <QRegularExpression>
#include <QTextBrowser>
#include <QTextDocument>
#include <QToolButton>
#include <QUrl>

#include <set>

using namespace rs;
using namespace rs::test;

namespace {

QString templatesReadme()
{
    QFile file(QString(RIGSMITH_SOURCE_DIR) + "/templates/README.md");
    EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << file.fileName().toStdString();
    return QString::fromUtf8(file.readAll());
}

// Distinct colours in the picture: a blank or one-colour image means nothing was drawn.
std::size_t colourCount(const QImage& image)
{
    std::set<QRgb> colours;
    for (int y = 0; y < image.height(); y += 3)
        for (int x = 0; x < image.width(); x += 3)
            colours.insert(image.pixel(x, y));
    return colours.size();
}

} // namespace

TEST(TemplateHelp, ReadmeSectionStopsAtTheNextHeadingOfItsLevel)
{
    const QString readme = "# Templates\n\n## a.one\nFirst.\n\n### detail\nKept.\n\n## a.two\nSecond.\n\n## Face\n"
                           "### face.jaw\nJaw text.\n### face.eye\nEye.\n";
    EXPECT_EQ(app::readmeSection(readme, "a.one"), "First.\n\n### detail\nKept.");
    EXPECT_EQ(app::readmeSection(readme, "a.two"), "Second.");
    EXPECT_EQ(app::readmeSection(readme, "face.jaw"), "Jaw text.");
    EXPECT_EQ(app::readmeSection(readme, "face.eye"), "Eye.");
    EXPECT_TRUE(app::readmeSection(readme, "a.on").isEmpty()) << "a heading matches the whole id";
}

TEST(TemplateHelp, EveryTemplateHasAPageWithWhatItBuildsAPictureAndItsHooks)
{
    Editor e;
    const auto& registry = e.window.session().templates();
    const QString readme = templatesReadme();
    ASSERT_FALSE(registry.all().empty());
    for (const templates::TemplateManifest* manifest : registry.all()) {
        SCOPED_TRACE(manifest->id);
        const app::TemplateHelpPage page = app::templateHelpPage(*manifest, registry, readme);
        EXPECT_FALSE(app::readmeSection(readme, manifest->id).isEmpty()) << "templates/README.md has no section for it";
        EXPECT_TRUE(page.markdown.contains("## What it builds"));
        EXPECT_TRUE(page.markdown.contains("## Hooks")) << page.markdown.toStdString();
        ASSERT_FALSE(page.picture.isNull()) << page.pictureProblem.toStdString();
        EXPECT_GT(colourCount(page.picture), 3u) << "the picture shows the built rig, not a blank frame";
        EXPECT_TRUE(page.markdown.contains(app::kTemplatePictureUrl));
        for (const auto& opt : manifest->opts)
            EXPECT_TRUE(page.markdown.contains("`" + QString::fromStdString(opt.name) + "`")) << opt.name;
        page.picture.save(QString::fromStdString(outputPath("template-" + manifest->id + ".png")));
    }
}

// The page's option table comes from the manifest; its "What it builds" text is written by hand. Every option
// must be named there (`name` or `name: value`), in the common options, or in the section of a template the
// text refers to by id ("as on `arm.limb`"), so a rigger reading the page learns what each option does.
TEST(TemplateHelp, EveryOptionIsNamedInItsReadmeSectionOrOneItRefersTo)
{
    Editor e;
    const auto& registry = e.window.session().templates();
    const QString readme = templatesReadme();
    const QString common = app::readmeSection(readme, "Common options");
    ASSERT_FALSE(common.isEmpty());
    for (const templates::TemplateManifest* manifest : registry.all()) {
        SCOPED_TRACE(manifest->id);
        const QString own = app::readmeSection(readme, manifest->id);
        QString text = own + "\n" + common;
        for (const templates::TemplateManifest* other : registry.all())
            if (other != manifest && own.contains(QString::fromStdString(other->id)))
                text += "\n" + app::readmeSection(readme, other->id);
        for (const templates::Parameter& opt : manifest->opts) {
            const QRegularExpression named("`" + QRegularExpression::escape(QString::fromStdString(opt.name)) + "[`:]");
            EXPECT_TRUE(text.contains(named)) << "templates/README.md does not say what `" << opt.name << "` does";
        }
    }
}

TEST(TemplateHelp, TheOptionsDockHelpButtonOpensTheSelectedTemplatesPageWithItsPicture)
{
    Editor e;
    app::MainWindow& w = e.window;
    auto* button = w.findChild<widgets::OptionsEditor*>("optionsEditor")->findChild<QToolButton*>("templateHelp");
    ASSERT_NE(button, nullptr);
    EXPECT_FALSE(button->isEnabled()) << "nothing selected: no template to explain";
    w.session().select(app::Selection::ofInstance(w.session().instanceNamed("leg")));
    QApplication::processEvents();
    ASSERT_TRUE(button->isEnabled());
    button->click();
    auto* help = w.findChild<QDialog*>("helpDialog");
    ASSERT_NE(help, nullptr);
    EXPECT_TRUE(help->isVisible());
    auto* browser = help->findChild<QTextBrowser*>("helpText");
    const QString text = browser->toPlainText();
    EXPECT_TRUE(text.contains("leg.limb"));
    EXPECT_TRUE(text.contains("What it builds"));
    EXPECT_TRUE(text.contains("reverse foot", Qt::CaseInsensitive)) << text.toStdString();
    const QVariant picture = browser->document()->resource(QTextDocument::ImageResource, QUrl(app::kTemplatePictureUrl));
    EXPECT_FALSE(picture.value<QImage>().isNull()) << "the page's picture is in the document";
    help->resize(900, 1000);
    help->grab().save(QString::fromStdString(outputPath("help-leg.png")));
}
