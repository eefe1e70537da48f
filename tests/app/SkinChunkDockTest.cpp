// Issue 20 in the editor: the Skin Chunks dock (export, inspect, preview and
// import on a worker thread as one undo step) and a guide whose model was
// remeshed re-fitted on open from the chunks saved beside its weights.
#include "EditorTestSupport.h"

#include "SkinChunkPanel.h"
#include "SkinInfluenceBox.h"
#include "io/SkinChunks.h"
#include "io/WeightsFile.h"

#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QStatusBar>
#include <QTimer>
#include <QTreeWidget>

#include <atomic>
#include <chrono>
#include <thread>

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

// The chunk file with the elbow's influence renamed (another identity and
// name, as from a rig of another build); the elbow joint's name.
std::string writeRenamedElbow(const QString& from, const QString& to, const session::Session& s)
{
    auto chunks = io::loadSkinChunkFile(from.toStdString());
    EXPECT_TRUE(chunks.ok());
    const auto node = *s.rig()->findPath("arm.L::skin.limb.1");
    for (skin::SkinChunk& c : *chunks)
        for (std::size_t j = 0; j < c.joints.size(); ++j)
            if (c.joints[j].key == s.rig()->nodes[node].key) {
                c.weights.joints[j] = c.joints[j].key = {999, "", "skin.elbow_old"};
                c.joints[j].name = "elbow_old";
            }
    EXPECT_TRUE(io::saveSkinChunkFile(to.toStdString(), *chunks).ok());
    return s.rig()->nodes[node].name;
}

QStringList listed(const QListWidget* list)
{
    QStringList out;
    for (int i = 0; i < list->count(); ++i)
        out.push_back(list->item(i)->text());
    return out;
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
    auto& s = e.window.session();
    // The worker waits (at most 20 s) for the GUI thread's event loop to let it go: the re-fit computes while the window runs.
    std::atomic<bool> released{false};
    std::atomic<int> waits{0};
    skin::TransferOptions watched = s.refitOptions();
    watched.progress = [&](double) {
        ++waits;
        for (int i = 0; i < 20000 && !released; ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        return true;
    };
    s.setRefitOptions(watched);
    ASSERT_TRUE(e.window.openFile(guide));
    EXPECT_TRUE(e.window.isRefitting()) << "the open returns while the re-fit computes";
    EXPECT_EQ(s.document().bindings[0].vertexCount, 440u) << "nothing applied yet";
    const QLabel* progress = e.window.statusBar()->findChild<QLabel*>("refitProgress");
    ASSERT_NE(progress, nullptr);
    EXPECT_TRUE(progress->text().startsWith("Re-fitting the weights of 1 changed mesh")) << progress->text().toStdString();
    // An edit while it computes: that result is stale, discarded and computed again, never applied over the edit.
    ASSERT_TRUE(QTest::qWaitFor([&] { return waits.load() > 0; }, 20000));
    const model::InstanceId renamed = s.document().instances().back().id;
    ASSERT_TRUE(s.renameInstance(renamed, "renamed_meanwhile").ok());
    QTimer::singleShot(50, [&] { released = true; }); // only a running event loop lets the worker go
    ASSERT_TRUE(QTest::qWaitFor([&] { return !e.window.isRefitting(); }, 30000));
    EXPECT_TRUE(released) << "the worker was let go by the GUI thread's timer";
    EXPECT_EQ(e.window.statusBar()->findChild<QLabel*>("refitProgress"), nullptr) << "the progress leaves the status bar";
    ASSERT_EQ(s.document().bindings.size(), 1u);
    EXPECT_EQ(s.document().bindings[0].vertexCount, 520u);
    EXPECT_TRUE(logSays(e.window, "(440 vertices then, 520 now): its weights were re-fitted from the previous mesh"));
    EXPECT_EQ(s.history().undoText(), "Re-fit weights of mesh 'sleeve'");
    EXPECT_EQ(s.document().instance(renamed)->name, "renamed_meanwhile") << "the edit made meanwhile is kept";
    ASSERT_EQ(s.history().size(), 2u) << "the rename, then the re-fit computed again after it";
    EXPECT_FALSE(s.history().isClean()) << "the re-fitted weights are not saved yet";
    const model::MeshBinding threaded = s.document().bindings[0];
    e.window.action("undo")->trigger();
    EXPECT_EQ(s.document().bindings[0].vertexCount, 440u) << "undo brings the previous record back";

    // The same re-fit on this thread (as the CLI runs it) gives the same record.
    s.setRefitRunner(nullptr);
    s.setRefitOptions(skin::defaultRefitOptions());
    ASSERT_EQ(s.refitChangedMeshes().size(), 1u);
    EXPECT_TRUE(s.document().bindings[0] == threaded) << "the worker's result equals the synchronous one";
}

TEST(SkinChunkDock, MissingInfluencesStopWithAListOrMapByANameMapFileOrAreCreatedAsJoints)
{
    Editor e;
    bindSleeve(e, "sleeve-influences.obj");
    auto& s = e.window.session();
    const model::MeshWeights bound = s.document().bindings[0].weights;
    e.window.action("skinChunks")->trigger();
    widgets::SkinChunkPanel* panel = e.window.chunkPanel();
    widgets::SkinInfluenceBox* box = panel->influences();
    const QString exported = QString::fromStdString(outputPath("sleeve-influences.rschunks"));
    ASSERT_TRUE(e.window.exportSkinChunks(exported));
    const QString renamed = QString::fromStdString(outputPath("sleeve-renamed.rschunks"));
    const std::string elbow = writeRenamedElbow(exported, renamed, s);
    ASSERT_TRUE(s.applyWeightOperation(session::Session::WeightOperation::Limit, 1).ok());
    const std::size_t steps = s.history().size();
    panel->setImportFiles({renamed});

    // Stop (the default): nothing changes, the dock lists the influence and the mesh weighting it.
    EXPECT_EQ(box->missing(), skin::MissingInfluences::Stop);
    e.window.importSkinChunks(panel->importFiles(), false);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !e.window.isImportingChunks(); }, 20000));
    EXPECT_EQ(s.history().size(), steps);
    EXPECT_FALSE(box->resultList()->isHidden());
    EXPECT_TRUE(box->resultHeading()->text().contains("The import stopped: 1 influence")) << box->resultHeading()->text().toStdString();
    EXPECT_EQ(listed(box->resultList()), QStringList{"elbow_old  (weights 'sleeve')"});
    EXPECT_TRUE(logSays(e.window, "Nothing imported: 1 influences are no skin joint of the rig"));

    // Map, chosen in the dock, with a name map file: the bound weights exactly, one undo step.
    const std::string map = outputPath("elbow.map");
    std::ofstream(map) << "# old = new\nelbow_old = " << elbow << "\n";
    box->findChild<QComboBox*>("missingInfluences")->setCurrentIndex(1);
    box->findChild<QLineEdit*>("nameMapFile")->setText(QString::fromStdString(map));
    EXPECT_EQ(box->missing(), skin::MissingInfluences::Map);
    e.window.importSkinChunks(panel->importFiles(), false);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !e.window.isImportingChunks(); }, 20000));
    EXPECT_EQ(s.history().size(), steps + 1);
    EXPECT_TRUE(s.document().bindings[0].weights == bound);
    EXPECT_EQ(box->resultHeading()->text().toStdString(), "1 influences mapped by name, 0 created as joints");
    EXPECT_EQ(listed(box->resultList()), QStringList{QString::fromStdString("elbow_old -> " + elbow + "  (mapped; weights 'sleeve')")});

    // Create without the map: a joint of the guide under the elbow's parent (in the left arm's copy), said in the dock.
    box->setNameMapFile({});
    box->findChild<QComboBox*>("missingInfluences")->setCurrentIndex(2);
    const std::size_t instances = s.document().instances().size();
    e.window.importSkinChunks(panel->importFiles(), true);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !e.window.isImportingChunks(); }, 20000));
    EXPECT_EQ(box->resultHeading()->text().toStdString(), "0 influences mapped by name, 1 created as joints");
    ASSERT_EQ(box->resultList()->count(), 1);
    EXPECT_EQ(box->resultList()->item(0)->text().toStdString(), "elbow_old -> elbow_old_L  (created; weights 'sleeve')");
    EXPECT_EQ(s.history().size(), steps + 1) << "a preview applies nothing";
    EXPECT_EQ(s.document().instances().size(), instances) << "a preview adds no joint";
    e.window.importSkinChunks(panel->importFiles(), false);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !e.window.isImportingChunks(); }, 20000));
    EXPECT_EQ(s.history().size(), steps + 2) << "the joint and the weights: one undo step";
    ASSERT_EQ(s.document().instances().size(), instances + 1);
    EXPECT_EQ(s.document().instances().back().templateId, "core.joints");
    ASSERT_NE(s.rig(), nullptr);
    EXPECT_TRUE(std::any_of(s.rig()->nodes.begin(), s.rig()->nodes.end(), [](const model::RigNode& n) { return n.name == "elbow_old_L"; }));
    e.window.action("undo")->trigger();
    EXPECT_EQ(s.document().instances().size(), instances) << "undo removes the joint with the weights";
}
