// Issue 20 in the editor: the Skin Chunks dock (export, inspect, preview and
// import on a worker thread as one undo step) and a guide whose model was
// remeshed re-fitted on open from the chunks saved beside its weights.
#include "EditorTestSupport.h"

#include "SkinChunkPanel.h"
#include "io/WeightsFile.h"

#include <QAction>
#include <QDockWidget>
#include <QPlainTextEdit>
#include <QTreeWidget>

using namespace rs;
using namespace rs::test;

namespace {

void bindSleeve(Editor& e, const std::string& file)
{
    ASSERT_TRUE(e.window.addModel(writeSleeve(e.window, file, 12)));
    e.window.bindSkin();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !e.window.isBinding(); }, 20000));
    ASSERT_EQ(e.window.session().document().bindings.size(), 1u);
}

std::size_t selectedVertexCount(const session::Session& s)
{
    std::size_t n = 0;
    for (const auto& [mesh, vertices] : s.selectedVertices())
        n += vertices.size();
    return n;
}

} // namespace

TEST(SkinChunkDock, ExportsInspectsPreviewsAndImportsAsOneUndoStep)
{
    Editor e;
    bindSleeve(e, "sleeve-chunks.obj");
    const model::MeshWeights bound = e.window.session().document().bindings[0].weights;
    e.window.action("skinChunks")->trigger();
    ASSERT_TRUE(e.window.findChild<QDockWidget*>("skinChunkDock")->isVisible());
    widgets::SkinChunkPanel* panel = e.window.chunkPanel();

    const QString file = QString::fromStdString(outputPath("sleeve.rschunks"));
    ASSERT_TRUE(e.window.exportSkinChunks(file));
    e.window.inspectSkinChunks(file);
    const QString text = panel->inspector()->toPlainText();
    EXPECT_TRUE(text.contains("chunk 0: sleeve")) << text.toStdString();
    EXPECT_TRUE(text.contains("vertices: 440 (0 to 9)"));

    // Spoil the weights, then preview: nothing changes, the 1:1 vertices are selected.
    auto& s = e.window.session();
    ASSERT_TRUE(s.applyWeightOperation(session::Session::WeightOperation::Limit, 1).ok());
    const model::MeshWeights spoiled = s.document().bindings[0].weights;
    const std::size_t steps = s.history().size();
    panel->setImportFiles({file});
    panel->setPreviewSelects(widgets::SkinChunkPanel::PreviewSelects::OneToOne);
    e.window.importSkinChunks(panel->importFiles(), true);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !e.window.isImportingChunks(); }, 20000));
    EXPECT_TRUE(s.document().bindings[0].weights == spoiled) << "a preview applies nothing";
    EXPECT_EQ(s.history().size(), steps);
    EXPECT_EQ(selectedVertexCount(s), 440u);
    ASSERT_EQ(panel->reportList()->topLevelItemCount(), 1);
    EXPECT_EQ(panel->reportList()->topLevelItem(0)->text(1), "one-to-one (preview)");
    EXPECT_EQ(panel->reportList()->topLevelItem(0)->text(4), "440");

    s.clearVertexSelection();
    e.window.importSkinChunks(panel->importFiles(), false);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !e.window.isImportingChunks(); }, 20000));
    EXPECT_EQ(s.history().undoText(), "Import skin weights");
    EXPECT_TRUE(s.document().bindings[0].weights == bound) << "exported and imported 1:1: exactly the bound weights";
    EXPECT_EQ(panel->reportList()->topLevelItem(0)->text(1), "one-to-one");
    EXPECT_TRUE(logSays(e.window, "Imported skin weights onto 1 meshes"));
    e.window.action("undo")->trigger();
    EXPECT_TRUE(s.document().bindings[0].weights == spoiled);
}

TEST(SkinChunkDock, ARemeshedModelIsRefittedOnOpenFromTheSavedChunks)
{
    Editor e;
    bindSleeve(e, "sleeve-reopen.obj");
    e.window.setReloadPrompt([](const QString&) { return false; }); // the change is read on open below
    const QString guide = QString::fromStdString(outputPath("sleeve-reopen.yml"));
    ASSERT_TRUE(e.window.saveFile(guide));
    EXPECT_TRUE(std::filesystem::exists(io::chunksPathFor(guide.toStdString()))) << "the bound meshes are saved beside the weights";
    writeSleeve(e.window, "sleeve-reopen.obj", 14); // remeshed in another program
    ASSERT_TRUE(e.window.openFile(guide));
    auto& s = e.window.session();
    ASSERT_EQ(s.document().bindings.size(), 1u);
    EXPECT_EQ(s.document().bindings[0].vertexCount, 520u);
    EXPECT_TRUE(logSays(e.window, "(440 vertices then, 520 now): its weights were re-fitted from the previous mesh"));
    EXPECT_EQ(s.history().undoText(), "Re-fit weights of mesh 'sleeve'");
    EXPECT_FALSE(s.history().isClean()) << "the re-fitted weights are not saved yet";
    e.window.action("undo")->trigger();
    EXPECT_EQ(s.document().bindings[0].vertexCount, 440u) << "undo brings the previous record back";
}
