// Issue 20 in the editor, the Skin Chunks dock's scopes and controls: export
// of the selected joints' vertices, an appended import that keeps the weights
// a subset chunk does not cover, Cancel in the import's progress dialog
// (nothing changes), and the inspector's From and Limit.
#include "EditorTestSupport.h"

#include "SkinChunkPanel.h"
#include "io/SkinChunks.h"

#include <QAction>
#include <QCheckBox>
#include <QPlainTextEdit>
#include <QProgressDialog>
#include <QRegularExpression>
#include <QPushButton>
#include <QSpinBox>
#include <QTreeWidget>

#include <numeric>

using namespace rs;
using namespace rs::test;

namespace {

struct Sleeve {
    Editor e;
    session::Session& s = e.window.session();
    widgets::SkinChunkPanel* panel = nullptr;
    model::MeshWeights bound;

    explicit Sleeve(const std::string& file)
    {
        if (!e.window.addModel(writeSleeve(e.window, file, 12)))
            return;
        e.window.bindSkin();
        QTest::qWaitFor([&] { return !e.window.isBinding(); }, 20000);
        if (s.document().bindings.size() == 1)
            bound = s.document().bindings[0].weights;
        e.window.action("skinChunks")->trigger();
        panel = e.window.chunkPanel();
    }
    bool ready() const { return panel && bound.vertexCount() == 440; }
    // Every vertex's weights on one influence: something an import visibly changes.
    model::MeshWeights spoil()
    {
        std::vector<std::uint32_t> all(440);
        std::iota(all.begin(), all.end(), 0u);
        s.selectVertices(0, all, false);
        EXPECT_TRUE(s.applyWeightOperation(session::Session::WeightOperation::Limit, 1).ok());
        s.clearVertexSelection();
        return s.document().bindings[0].weights;
    }
    void import()
    {
        e.window.importSkinChunks(panel->importFiles(), false);
        ASSERT_TRUE(QTest::qWaitFor([&] { return !e.window.isImportingChunks(); }, 20000));
    }
};

QString logText(app::MainWindow& w)
{
    QString out;
    for (int i = 0; i < w.log()->count(); ++i)
        out += w.log()->item(i)->text() + "\n";
    return out;
}

std::vector<model::Influence> influencesOf(const model::MeshWeights& w, std::uint32_t v)
{
    return {w.begin(v), w.end(v)};
}

} // namespace

TEST(SkinChunkDock, ExportsTheVerticesTheSelectedJointsWeightWithAllTheirWeights)
{
    Sleeve f("sleeve-joints.obj");
    ASSERT_TRUE(f.ready());
    const model::RigNode& elbow = f.s.rig()->nodes[*f.s.rig()->findPath("arm.L::skin.limb.1")];
    ASSERT_NE(elbow.guide, model::kNoId) << "the skin joint is built from a guide joint";
    f.panel->setExportScope(widgets::SkinChunkPanel::ExportScope::SelectedJoints);
    const QString file = QString::fromStdString(outputPath("sleeve-elbow.rschunks"));
    std::filesystem::remove(file.toStdString());

    f.s.select({});
    EXPECT_FALSE(f.e.window.exportSkinChunks(file)) << "no joint selected";
    EXPECT_TRUE(logSays(f.e.window, "no skin joint is selected"));
    EXPECT_FALSE(std::filesystem::exists(file.toStdString()));

    f.s.select(session::Selection::ofInstance(elbow.key.instance, elbow.guide));
    f.s.selectGuideJoints({elbow.guide}, false);
    ASSERT_TRUE(f.e.window.exportSkinChunks(file));
    auto chunks = io::loadSkinChunkFile(file.toStdString());
    ASSERT_TRUE(chunks.ok());
    ASSERT_EQ(chunks->size(), 1u);
    const skin::SkinChunk& c = (*chunks)[0];
    EXPECT_GT(c.vertexCount(), 0u);
    EXPECT_LT(c.vertexCount(), 440u) << "the elbow does not weight the whole sleeve";
    // The skin joints built from the elbow's guide joint (the elbow, its twist joints...).
    std::vector<bool> fromElbow(c.joints.size(), false);
    for (std::size_t j = 0; j < c.joints.size(); ++j)
        if (const auto node = f.s.rig()->find(c.joints[j].key))
            fromElbow[j] = f.s.rig()->nodes[*node].guide == elbow.guide;
    ASSERT_TRUE(std::count(fromElbow.begin(), fromElbow.end(), true) > 0);
    for (std::size_t i = 0; i < c.vertexCount(); ++i)
        ASSERT_TRUE(std::any_of(c.weights.begin(i), c.weights.end(i),
                                [&](const model::Influence& w) { return fromElbow[w.joint] && w.weight > 0.0f; }))
            << "exported vertex " << c.vertexIds[i];

    // The whole instance (no guide joint selected): its skin joints weight every vertex of the sleeve.
    f.s.select(session::Selection::ofInstance(elbow.key.instance));
    ASSERT_TRUE(f.e.window.exportSkinChunks(file)) << logText(f.e.window).toStdString();
    chunks = io::loadSkinChunkFile(file.toStdString());
    ASSERT_TRUE(chunks.ok());
    EXPECT_EQ((*chunks)[0].vertexCount(), 440u);
}

TEST(SkinChunkDock, AnAppendedImportKeepsTheWeightsASubsetChunkDoesNotCover)
{
    Sleeve f("sleeve-append.obj");
    ASSERT_TRUE(f.ready());
    f.s.selectVertices(0, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9}, false);
    f.panel->setExportScope(widgets::SkinChunkPanel::ExportScope::SelectedVertices);
    const QString file = QString::fromStdString(outputPath("sleeve-ten.rschunks"));
    ASSERT_TRUE(f.e.window.exportSkinChunks(file));
    const model::MeshWeights spoiled = f.spoil();
    f.panel->setImportFiles({file});

    f.panel->findChild<QCheckBox*>("appendImport")->setChecked(true);
    EXPECT_TRUE(f.panel->appendImport());
    f.import();
    EXPECT_EQ(f.s.history().undoText(), "Import skin weights");
    const model::MeshWeights& w = f.s.document().bindings[0].weights;
    for (std::uint32_t v = 0; v < 440; ++v)
        ASSERT_EQ(influencesOf(w, v), influencesOf(v < 10 ? f.bound : spoiled, v)) << "vertex " << v;
    EXPECT_TRUE(logSays(f.e.window, "appended: 10 vertices written, 430 kept their weights"));

    // Off (replace): the other vertices are written too, by the fallback from the ten.
    f.e.window.action("undo")->trigger();
    ASSERT_TRUE(f.s.document().bindings[0].weights == spoiled);
    f.panel->setAppendImport(false);
    f.import();
    const model::MeshWeights& r = f.s.document().bindings[0].weights;
    std::size_t changed = 0;
    for (std::uint32_t v = 10; v < 440; ++v)
        changed += influencesOf(r, v) != influencesOf(spoiled, v);
    EXPECT_GT(changed, 0u);
}

TEST(SkinChunkDock, CancelInTheImportProgressDialogChangesNothing)
{
    Sleeve f("sleeve-cancel.obj");
    ASSERT_TRUE(f.ready());
    const QString file = QString::fromStdString(outputPath("sleeve-cancel.rschunks"));
    ASSERT_TRUE(f.e.window.exportSkinChunks(file));
    const model::MeshWeights spoiled = f.spoil();
    const std::size_t steps = f.s.history().size();
    f.panel->setImportFiles({file});
    f.panel->showReports({}, false);

    f.e.window.importSkinChunks(f.panel->importFiles(), false);
    ASSERT_TRUE(f.e.window.isImportingChunks());
    auto* dialog = f.e.window.findChild<QProgressDialog*>("chunkImportProgress");
    ASSERT_NE(dialog, nullptr);
    EXPECT_EQ(dialog->windowModality(), Qt::WindowModal);
    auto* cancel = dialog->findChild<QPushButton*>();
    ASSERT_NE(cancel, nullptr);
    EXPECT_EQ(cancel->text(), "Cancel");
    cancel->click(); // before the worker's end is handled: whether it ran to the end or stopped, nothing is applied
    ASSERT_TRUE(QTest::qWaitFor([&] { return !f.e.window.isImportingChunks(); }, 20000));
    EXPECT_TRUE(f.s.document().bindings[0].weights == spoiled) << "a cancelled import changes nothing";
    EXPECT_EQ(f.s.history().size(), steps);
    EXPECT_TRUE(logSays(f.e.window, "Import cancelled; nothing changed"));
    EXPECT_EQ(f.panel->reportList()->topLevelItemCount(), 0) << "no report of an import that did not happen";
    QTest::qWait(50); // the dialog is deleted later
    EXPECT_EQ(f.e.window.findChild<QProgressDialog*>("chunkImportProgress"), nullptr);

    // The next import runs to the end.
    f.import();
    EXPECT_TRUE(f.s.document().bindings[0].weights == f.bound);
}

TEST(SkinChunkDock, TheInspectorsFromAndLimitShowOtherRowsOfTheSameFile)
{
    Sleeve f("sleeve-inspect.obj");
    ASSERT_TRUE(f.ready());
    const QString file = QString::fromStdString(outputPath("sleeve-inspect.rschunks"));
    ASSERT_TRUE(f.e.window.exportSkinChunks(file));
    f.e.window.inspectSkinChunks(file);
    auto text = [&] { return f.panel->inspector()->toPlainText(); };
    auto vertexRows = [&] { return text().count(QRegularExpression("^    \\d+ id \\d+ ", QRegularExpression::MultilineOption)); };
    EXPECT_TRUE(text().contains("vertices: 440 (0 to 9)")) << text().toStdString();
    EXPECT_EQ(vertexRows(), 10);

    auto* from = f.panel->findChild<QSpinBox*>("inspectFrom");
    auto* limit = f.panel->findChild<QSpinBox*>("inspectLimit");
    ASSERT_TRUE(from && limit);
    from->setValue(435);
    EXPECT_TRUE(text().contains("vertices: 440 (435 to 439)")) << text().toStdString();
    EXPECT_TRUE(text().contains("\n    435 id 435 "));
    EXPECT_EQ(vertexRows(), 5) << "only the rows there are";
    limit->setValue(2);
    EXPECT_TRUE(text().contains("vertices: 440 (435 to 436)")) << text().toStdString();
    EXPECT_EQ(vertexRows(), 2);
    limit->setValue(0);
    EXPECT_TRUE(text().contains("vertices: 440\n")) << text().toStdString();
    EXPECT_EQ(vertexRows(), 0);
    from->setValue(1000);
    limit->setValue(5);
    EXPECT_TRUE(text().contains("vertices: 440\n")) << "past the end: no rows";
    EXPECT_EQ(vertexRows(), 0);
}
